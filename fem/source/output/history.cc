#include <impact_fem/output/history.h>
#include <impact_fem/result_files.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/hdf5.h>

#include <filesystem>

namespace impact_fem
{
  using namespace dealii;

  void
  History::declare(const std::string &name,
                   const std::string &unit,
                   const std::string &description)
  {
    index[name] = series.size();
    series.push_back({name, unit, description, {}});
  }


  void
  History::append(const std::string &name, const double value)
  {
    series.at(index.at(name)).values.push_back(value);
  }


  const std::vector<double> &
  History::operator[](const std::string &name) const
  {
    return series.at(index.at(name)).values;
  }


  void
  History::set_profile(const std::string         &name,
                       const std::string         &unit,
                       const std::string         &description,
                       const std::vector<double> &values)
  {
    for (auto &profile : profiles)
      if (profile.name == name)
        {
          profile.values = values;
          return;
        }
    profiles.push_back({name, unit, description, values});
  }


  const std::vector<double> &
  History::profile(const std::string &name) const
  {
    static const std::vector<double> none;
    for (const auto &profile : profiles)
      if (profile.name == name)
        return profile.values;
    return none;
  }


  std::size_t
  History::n_steps() const
  {
    if (series.empty())
      return 0;
    std::size_t n = series.front().values.size();
    for (const auto &s : series)
      n = std::min(n, s.values.size());
    return n;
  }


  void
  History::save(checkpoint::Writer &writer) const
  {
    std::vector<std::pair<std::string, std::vector<double>>> values;
    for (const auto &s : series)
      values.emplace_back(s.name, s.values);
    std::vector<std::vector<std::string>> profile_texts;
    std::vector<std::vector<double>>      profile_values;
    for (const auto &p : profiles)
      {
        profile_texts.push_back({p.name, p.unit, p.description});
        profile_values.push_back(p.values);
      }
    writer &values &profile_texts &profile_values;
  }


  void
  History::load(checkpoint::Reader &reader)
  {
    std::vector<std::pair<std::string, std::vector<double>>> values;
    std::vector<std::vector<std::string>>                    profile_texts;
    std::vector<std::vector<double>>                         profile_values;
    reader &values &profile_texts                           &profile_values;
    AssertThrow(values.size() == series.size() &&
                  profile_texts.size() == profile_values.size(),
                ExcMessage("The checkpoint's history has " +
                           std::to_string(values.size()) +
                           " quantities, the run declares " +
                           std::to_string(series.size()) + "."));
    for (std::size_t i = 0; i < values.size(); ++i)
      {
        AssertThrow(values[i].first == series[i].name,
                    ExcMessage("The checkpoint's history has " +
                               values[i].first + " where the run declares " +
                               series[i].name + "."));
        series[i].values = std::move(values[i].second);
      }
    profiles.clear();
    for (std::size_t i = 0; i < profile_texts.size(); ++i)
      {
        AssertThrow(profile_texts[i].size() == 3,
                    ExcMessage("The checkpoint's history is damaged."));
        profiles.push_back({profile_texts[i][0],
                            profile_texts[i][1],
                            profile_texts[i][2],
                            std::move(profile_values[i])});
      }
  }


  void
  History::write_hdf5(const std::string                        &filename,
                      const std::map<std::string, std::string> &text_attributes,
                      const std::map<std::string, double> &numeric_attributes,
                      const bool                           complete) const
  {
    const std::string final_name =
      complete ? filename :
                 filename.substr(0, filename.rfind(".h5")) + ".incomplete.h5";
    const std::string temporary_name = final_name + ".tmp";
    {
      HDF5::File file(temporary_name, HDF5::File::FileAccessMode::create);
      file.set_attribute(result_files::status_attribute,
                         std::string(complete ?
                                       result_files::status_complete :
                                       result_files::status_incomplete));
      for (const auto &[key, value] : text_attributes)
        file.set_attribute(key, value);
      for (const auto &[key, value] : numeric_attributes)
        file.set_attribute(key, value);

      // A quantity may be one value short when a step failed half-way.
      const std::size_t n = n_steps();
      for (const auto &s : series)
        {
          std::vector<double> values(s.values.begin(),
                                     s.values.begin() +
                                       std::min(n, s.values.size()));
          if (values.empty())
            continue;
          auto dataset =
            file.create_dataset<double>(s.name,
                                        std::vector<hsize_t>{values.size()});
          dataset.write(values);
          dataset.set_attribute(result_files::unit_attribute, s.unit);
          dataset.set_attribute(result_files::description_attribute,
                                s.description);
        }
      for (const auto &s : profiles)
        if (!s.values.empty())
          {
            auto dataset = file.create_dataset<double>(
              s.name, std::vector<hsize_t>{s.values.size()});
            dataset.write(s.values);
            dataset.set_attribute(result_files::unit_attribute, s.unit);
            dataset.set_attribute(result_files::description_attribute,
                                  s.description);
          }
    }
    std::filesystem::rename(temporary_name, final_name);
  }
} // namespace impact_fem
