// The writer of FEM runs (fem_run.hpp, write_fem_run): impact-fem's format, for the tests and
// the tools that make runs the readers cannot tell from impact-fem's.

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include "hdf5_file.hpp"
#include "run_files.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace impact::postprocess {

namespace fs = std::filesystem;
namespace format = fem_format;

fs::path write_fem_run(const FemRun& run, const fs::path& directory, bool complete) {
  fs::create_directories(directory);
  const fs::path file_path =
      directory / (complete ? format::history_file : format::incomplete_history_file);
  auto file = hdf5::File::create(file_path.string());
  file.write_attribute(format::status_attribute,
                       std::string(complete ? format::status_complete : format::status_incomplete));
  {
    std::ostringstream velocity;
    velocity.precision(17);
    velocity << run.impact_velocity;
    file.write_attribute(format::impact_velocity.path, velocity.str());
  }
  file.write_attribute(format::sphere_mass_attribute, run.mass);

  const std::vector<std::pair<const char*, double>> results = {
      {format::impact_velocity_key, run.impact_velocity},
      {format::contact_velocity_key, run.impact_velocity},
      {format::restitution_key, run.restitution},
      {format::rebound_velocity_key, run.restitution * run.impact_velocity},
      {format::first_contact_time_key, run.first_contact_time},
      {format::contact_time_key, run.contact_time},
      {format::force_max_key, run.force_max},
      {format::time_force_max_key, run.time_force_max},
      {format::approach_max_key, run.approach_max}};
  for (const auto& [key, value] : results)
    if (std::isfinite(value))
      file.write_attribute(format::result_attribute_prefix + std::string(key), value);
  for (const auto& [key, value] : run.text_attributes)
    if (key != format::status_attribute && key != format::impact_velocity.path)
      file.write_attribute(key, value);
  for (const auto& [key, value] : run.numeric_attributes)
    if (key != format::sphere_mass_attribute &&
        key.rfind(format::result_attribute_prefix, 0) == std::string::npos)
      file.write_attribute(key, value);

  const struct {
    const char* name;
    const std::vector<double>& values;
    const char* unit;
    const char* description;
  } series[] = {{format::time_dataset, run.time, format::time_unit, "simulated time"},
                {format::contact_force_dataset, run.contact_force, format::contact_force_unit,
                 "total normal contact force"},
                {format::approach_dataset, run.approach, format::approach_unit,
                 "approach (indentation) of sphere and plate"},
                {format::sphere_velocity_dataset, run.sphere_velocity, format::sphere_velocity_unit,
                 "centre-of-mass velocity of the sphere, downward positive"}};
  for (const auto& s : series)
    if (!s.values.empty()) file.write_dataset(s.name, s.values, s.unit, s.description);

  const fs::path summary_file = detail::summary_path_of(file_path);
  if (complete) {
    nlohmann::json summary;
    summary[format::complete_key] = true;
    for (const auto& [key, value] : results)
      summary[key] = std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
    summary[format::sphere_mass_key] = run.mass;
    std::ofstream out(summary_file);
    out << summary.dump(2) << '\n';
  } else {
    fs::remove(summary_file);
  }
  return file_path;
}

} // namespace impact::postprocess
