#ifndef IMPACT_FEM_CAMPAIGN_SHARD_H
#define IMPACT_FEM_CAMPAIGN_SHARD_H

#include <string>

namespace impact_fem
{
  /**
   * One job's share of a campaign that runs as N independent jobs (batch
   * jobs, job-array tasks, machines) into one campaign directory on a shared
   * file system: "--shard K/N" takes the points i = 0, 1, ... (the
   * campaign's order, velocity fastest) with i mod N = K - 1.
   *
   * The share is a function of K, N and the campaign alone, so the jobs need
   * no coordinator and never run the same point; it is balanced (the shares
   * differ by at most one point) and, since neighbouring points cost about
   * the same, so is the work. K counts from 1, as the task ids of a Slurm
   * array --array=1-N do. A shard beyond the number of points is empty.
   * The default, 1/1, is the whole campaign.
   */
  class CampaignShard
  {
  public:
    /// The whole campaign: 1/1.
    CampaignShard() = default;

    /// Parses "K/N" (whole numbers, 1 <= K <= N). Throws, naming @p option,
    /// the value received and the allowed range, otherwise.
    static CampaignShard
    parse(const std::string &text, const std::string &option);

    /// Is point @p point_index (0-based, in the campaign's order) ours?
    bool
    contains(const unsigned int point_index) const;

    /// The number of points of a campaign of @p n_points that are ours.
    unsigned int
    n_points(const unsigned int n_points_of_campaign) const;

    bool
    whole() const;

    /// "K/N".
    std::string
    name() const;

  private:
    unsigned int index = 1; ///< K, from 1
    unsigned int count = 1; ///< N
  };
} // namespace impact_fem

#endif
