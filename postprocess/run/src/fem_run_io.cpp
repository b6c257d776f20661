// Reading one FEM run, and a list of runs (see fem_run.hpp; names in fem_run_format.hpp);
// a campaign and its index: campaign_index.cpp; the writer: fem_run_writer.cpp.

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/same_value.hpp"

#include "hdf5_file.hpp"
#include "run_files.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <impact_fem/as_written.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

namespace impact::postprocess {

namespace fs = std::filesystem;
namespace format = fem_format;

namespace detail {

std::string quoted(const fs::path& path) {
  return "'" + path.string() + "'";
}

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
  throw RunInputError("run " + quoted(file) + ": " + problem);
}

// summary.json belongs to history.h5 in the same directory; another file NAME.h5 may have
// NAME.summary.json beside it.
fs::path summary_path_of(const fs::path& file) {
  if (file.filename() == format::history_file) return file.parent_path() / format::summary_file;
  return file.parent_path() / (file.stem().string() + ".summary.json");
}

fs::path incomplete_sibling(const fs::path& file) {
  return file.parent_path() / format::incomplete_history_file;
}

std::optional<FemRun> read_or_record(const fs::path& path, std::vector<InputProblem>& problems,
                                     std::map<std::string, SweepValue> point) {
  try {
    return read_fem_run(path);
  } catch (const RunInputError& error) {
    const bool no_rebound = dynamic_cast<const NoRebound*>(&error) != nullptr;
    problems.push_back(
        {{path.string(), no_rebound ? ProblemKind::no_rebound : ProblemKind::input, error.what()},
         std::move(point)});
    return std::nullopt;
  }
}

void sort_by_velocity(std::vector<FemRun>& runs) {
  std::stable_sort(runs.begin(), runs.end(), [](const FemRun& a, const FemRun& b) {
    return a.impact_velocity < b.impact_velocity;
  });
}

} // namespace detail

using detail::fail;
using detail::incomplete_sibling;
using detail::quoted;
using detail::read_or_record;
using detail::sort_by_velocity;
using detail::summary_path_of;

namespace {

// The run's HDF5 file for a path that names the file or the run directory.
fs::path history_file_of(const fs::path& path) {
  if (fs::is_directory(path)) {
    const fs::path complete = path / format::history_file;
    if (fs::exists(complete)) return complete;
    if (fs::exists(path / format::incomplete_history_file))
      fail(path, std::string("the FEM run did not finish: the directory holds only ") +
                     format::incomplete_history_file + " (status '" + format::status_incomplete +
                     "'); run it again to completion");
    fail(path, std::string("the directory holds no ") + format::history_file);
  }
  if (!fs::exists(path)) {
    if (path.filename() == format::history_file && fs::exists(incomplete_sibling(path)))
      fail(path, std::string("the file does not exist, only ") + format::incomplete_history_file +
                     ": the FEM run did not finish; run it again to completion");
    fail(path, "the file does not exist");
  }
  return path;
}

// The derived results, from summary.json first, else from the "result: ..." attributes.
class Results {
public:
  Results(const fs::path& file, const std::map<std::string, double>& attributes)
      : attributes_(attributes) {
    const fs::path summary_file = summary_path_of(file);
    if (!fs::exists(summary_file)) return;
    std::ifstream in(summary_file);
    try {
      summary_ = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& error) {
      fail(summary_file, std::string("it is not valid JSON (") + error.what() + ")");
    }
    if (!summary_.is_object()) fail(summary_file, "it is not a JSON object");
  }

  bool summary_says_incomplete() const {
    return summary_.contains(format::complete_key) && summary_[format::complete_key].is_boolean() &&
           !summary_[format::complete_key].get<bool>();
  }

  std::optional<double> number(const std::string& key) const {
    if (summary_.contains(key) && summary_[key].is_number()) return summary_[key].get<double>();
    const auto attribute = attributes_.find(format::result_attribute_prefix + key);
    if (attribute != attributes_.end() && std::isfinite(attribute->second))
      return attribute->second;
    return std::nullopt;
  }

private:
  nlohmann::json summary_ = nlohmann::json::object();
  const std::map<std::string, double>& attributes_;
};

std::vector<double> required_series(const hdf5::File& file, const fs::path& path, const char* name,
                                    std::size_t size) {
  if (!file.has_dataset(name)) fail(path, std::string("the file has no dataset '") + name + "'");
  std::vector<double> values;
  try {
    values = file.read_dataset(name);
  } catch (const std::runtime_error& error) {
    fail(path, error.what());
  }
  if (size != 0 && values.size() != size)
    fail(path, "the dataset '" + std::string(name) + "' has " + std::to_string(values.size()) +
                   " values, but 'time' has " + std::to_string(size));
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      fail(path, "the dataset '" + std::string(name) + "' holds a non-finite value at step " +
                     std::to_string(i));
  return values;
}

// Where F^(2/3) (linear in time near the ends of a Hertz-like contact) extrapolates to zero
// between samples i (force > 0) and j.
double force_zero_time(const FemRun& run, std::size_t i, std::size_t j) {
  const double fi = std::cbrt(run.contact_force[i] * run.contact_force[i]);
  const double fj = std::cbrt(run.contact_force[j] * run.contact_force[j]);
  if (fj == fi) return run.time[i];
  return run.time[i] - fi * (run.time[j] - run.time[i]) / (fj - fi);
}

// The status attribute and the histories of a run file into `run`.
void read_histories(const hdf5::File& file, const fs::path& file_path, FemRun& run) {
  const auto status = run.text_attributes.find(format::status_attribute);
  if (status == run.text_attributes.end())
    fail(file_path, std::string("the file has no '") + format::status_attribute +
                        "' attribute, so it cannot be told whether the FEM run finished");
  if (status->second != format::status_complete)
    fail(file_path, std::string("the file is marked incomplete (") + format::status_attribute +
                        " = '" + status->second + "'): the FEM run did not finish");

  run.time = required_series(file, file_path, format::time_dataset, 0);
  if (run.time.size() < 3)
    fail(file_path, "the dataset 'time' has " + std::to_string(run.time.size()) +
                        " values; a run needs at least 3 time steps");
  for (std::size_t i = 1; i < run.time.size(); ++i)
    if (!(run.time[i] > run.time[i - 1]))
      fail(file_path,
           "the dataset 'time' is not strictly increasing (step " + std::to_string(i) + ")");
  run.contact_force =
      required_series(file, file_path, format::contact_force_dataset, run.time.size());
  run.approach = required_series(file, file_path, format::approach_dataset, run.time.size());
  if (file.has_dataset(format::sphere_velocity_dataset))
    run.sphere_velocity =
        required_series(file, file_path, format::sphere_velocity_dataset, run.time.size());
}

// The reduced model starts at first contact with the speed there: V of the run.
double impact_velocity_of(const FemRun& run, const Results& results, const fs::path& file_path) {
  auto velocity = results.number(format::contact_velocity_key);
  if (!velocity) velocity = results.number(format::impact_velocity_key);
  if (!velocity) {
    const auto parameter = run.text_attributes.find(format::impact_velocity.path);
    if (parameter != run.text_attributes.end()) {
      try {
        velocity = std::stod(parameter->second);
      } catch (const std::exception&) {
      }
    }
  }
  if (!velocity)
    fail(file_path, std::string("no impact velocity: neither summary.json nor the file has '") +
                        format::contact_velocity_key + "' or '" + format::impact_velocity_key +
                        "', and the attribute '" + format::impact_velocity.path + "' is missing");
  if (!(std::isfinite(*velocity) && *velocity > 0))
    fail(file_path, "the impact velocity must be positive (got " + std::to_string(*velocity) + ")");
  return *velocity;
}

double sphere_mass_of(const FemRun& run, const Results& results, const fs::path& file_path) {
  auto mass = results.number(format::sphere_mass_key);
  if (!mass) {
    const auto attribute = run.numeric_attributes.find(format::sphere_mass_attribute);
    if (attribute != run.numeric_attributes.end()) mass = attribute->second;
  }
  if (!mass)
    fail(file_path, std::string("no sphere mass: neither summary.json has '") +
                        format::sphere_mass_key + "' nor the file the attribute '" +
                        format::sphere_mass_attribute + "'");
  if (!(std::isfinite(*mass) && *mass > 0))
    fail(file_path, "the sphere mass must be positive (got " + std::to_string(*mass) + ")");
  return *mass;
}

// The contact of the run: the episode of positive force around the peak force (robust to
// noise before and after it), its restitution and figures (the summary's, else measured on
// the histories).
void read_contact(const Results& results, const fs::path& file_path, FemRun& run) {
  const std::size_t n = run.time.size();
  const auto peak =
      std::size_t(std::max_element(run.contact_force.begin(), run.contact_force.end()) -
                  run.contact_force.begin());
  if (!(run.contact_force[peak] > 0))
    fail(file_path,
         "no contact: 'contact_force' is never positive (the sphere did not reach "
         "the plate within the simulated time?)");
  std::size_t first = peak, last = peak;
  while (first > 0 && run.contact_force[first - 1] > 0) --first;
  while (last + 1 < n && run.contact_force[last + 1] > 0) ++last;
  if (last - first < 2)
    fail(file_path, "the contact lasts " + std::to_string(last - first + 1) +
                        " time step(s); at least 3 are needed to fit a force history");

  const auto restitution = results.number(format::restitution_key);
  if (!restitution)
    throw NoRebound("run " + quoted(file_path) +
                    ": no rebound: the sphere did not separate from the plate within the "
                    "simulated time (" +
                    std::to_string(run.time.back() * 1e6) +
                    " us; summary.json and the file have no '" +
                    std::string(format::restitution_key) +
                    "'): no restitution to calibrate or judge; lengthen the run to see one");
  if (!(std::isfinite(*restitution) && *restitution > 0))
    fail(file_path, "the restitution must be positive (got " + std::to_string(*restitution) + ")");
  // Below 1e-6 the sphere is all but held: no rebound to calibrate on, and the closed-form
  // inversion e -> b V (hunt_crossley.hpp, accurate from 1e-6) overflows soon after.
  if (*restitution < 1e-6)
    fail(file_path, "the restitution " + impact_fem::as_written(*restitution) +
                        " is below 1e-6: the sphere all but stuck, no rebound to calibrate on");
  run.restitution = *restitution;

  run.first_contact_time =
      results.number(format::first_contact_time_key)
          .value_or(first > 0
                        ? std::max(run.time[first - 1], force_zero_time(run, first, first + 1))
                        : run.time[0]);
  const double separation = last + 1 < n
                                ? std::min(run.time[last + 1], force_zero_time(run, last, last - 1))
                                : run.time[last];
  run.contact_time =
      results.number(format::contact_time_key).value_or(separation - run.first_contact_time);
  run.force_max = results.number(format::force_max_key).value_or(run.contact_force[peak]);
  run.time_force_max = results.number(format::time_force_max_key).value_or(run.time[peak]);
  run.approach_max = results.number(format::approach_max_key)
                         .value_or(*std::max_element(run.approach.begin(), run.approach.end()));
}

// The sphere's momentum balance over the run: the impulse of the contact force is
// m V (1 + e) (gravity's share over a contact is far below 1 %). A mass, impact velocity or
// restitution that misses it by more than a factor of two is not the run's: a damaged or
// foreign summary.json (an absurd value would also stall the fits).
void check_momentum_balance(const FemRun& run, const fs::path& file_path) {
  double impulse = 0;
  for (std::size_t i = 0; i + 1 < run.time.size(); ++i)
    impulse +=
        0.5 * (run.contact_force[i] + run.contact_force[i + 1]) * (run.time[i + 1] - run.time[i]);
  const double momentum = run.mass * run.impact_velocity * (1 + run.restitution);
  if (!(momentum > 0.5 * impulse && momentum < 2 * impulse))
    fail(file_path,
         "the sphere mass " + impact_fem::as_written(run.mass) + " kg, impact velocity " +
             impact_fem::as_written(run.impact_velocity) + " m/s and restitution " +
             impact_fem::as_written(run.restitution) + " (" + format::summary_file +
             ", else the file) give a momentum change "
             "m V (1 + e) = " +
             impact_fem::as_written(momentum) + " N s, but the contact force's impulse is " +
             impact_fem::as_written(impulse) + " N s: they are not this run's");
}

} // namespace

FemRun read_fem_run(const fs::path& path) {
  const fs::path file_path = history_file_of(path);
  FemRun run;
  run.source = file_path.string();

  std::optional<hdf5::File> opened;
  try {
    opened.emplace(hdf5::File::open_read_only(file_path.string()));
  } catch (const std::runtime_error& error) {
    fail(file_path, std::string("cannot be read: ") + error.what());
  }
  const hdf5::File& file = *opened;
  file.read_root_attributes(run.text_attributes, run.numeric_attributes);
  read_histories(file, file_path, run);

  const Results results(file_path, run.numeric_attributes);
  if (results.summary_says_incomplete())
    fail(file_path, std::string(format::summary_file) + " says the run is not complete");
  run.impact_velocity = impact_velocity_of(run, results, file_path);
  run.mass = sphere_mass_of(run, results, file_path);
  read_contact(results, file_path, run);
  check_momentum_balance(run, file_path);
  return run;
}

ImpactFigures measured_quantities(const FemRun& run) {
  return {run.restitution, run.contact_time, run.force_max,
          run.time_force_max - run.first_contact_time, run.approach_max};
}

Campaign read_runs(const std::vector<fs::path>& paths) {
  Campaign campaign;
  for (const auto& path : paths)
    if (auto run = read_or_record(path, campaign.problems))
      campaign.runs.push_back(std::move(*run));
  sort_by_velocity(campaign.runs);
  return campaign;
}

} // namespace impact::postprocess
