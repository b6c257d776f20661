#include <impact_fem/campaign/shard.h>

#include <deal.II/base/exceptions.h>

#include <limits>

namespace impact_fem
{
  namespace
  {
    // A whole number written with digits only ("+1", "1.0", " 1" are not);
    // false also when it does not fit an unsigned int.
    bool
    parse_whole_number(const std::string &text, unsigned int &value)
    {
      if (text.empty() || text.size() > 9 ||
          text.find_first_not_of("0123456789") != std::string::npos)
        return false;
      const unsigned long number = std::stoul(text);
      if (number > std::numeric_limits<unsigned int>::max())
        return false;
      value = number;
      return true;
    }
  } // namespace


  CampaignShard
  CampaignShard::parse(const std::string &text, const std::string &option)
  {
    CampaignShard     shard;
    const std::size_t slash = text.find('/');
    const bool        numbers =
      slash != std::string::npos &&
      parse_whole_number(text.substr(0, slash), shard.index) &&
      parse_whole_number(text.substr(slash + 1), shard.count);
    using dealii::ExcMessage;
    AssertThrow(numbers && shard.count >= 1 && shard.index >= 1 &&
                  shard.index <= shard.count,
                ExcMessage(option + " <" + text +
                           ">: expected K/N, whole numbers with N >= 1 and "
                           "1 <= K <= N: this job runs share K of a campaign "
                           "split into N jobs (e.g. " +
                           option + " 1/4 ... " + option + " 4/4)."));
    return shard;
  }


  bool
  CampaignShard::contains(const unsigned int point_index) const
  {
    return point_index % count == index - 1;
  }


  unsigned int
  CampaignShard::n_points(const unsigned int n_points_of_campaign) const
  {
    return n_points_of_campaign / count +
           (index - 1 < n_points_of_campaign % count ? 1 : 0);
  }


  bool
  CampaignShard::whole() const
  {
    return count == 1;
  }


  std::string
  CampaignShard::name() const
  {
    return std::to_string(index) + "/" + std::to_string(count);
  }
} // namespace impact_fem
