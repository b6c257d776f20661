// Reading and writing FEM runs and campaigns (see fem_run.hpp; names in fem_run_format.hpp).

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/same_value.hpp"

#include "run/hdf5_file.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

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

namespace {

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

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

std::vector<double> required_series(const hdf5::File& file, const fs::path& path,
                                    const char* name, std::size_t size) {
  if (!file.has_dataset(name))
    fail(path, std::string("the file has no dataset '") + name + "'");
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
      fail(file_path, "the dataset 'time' is not strictly increasing (step " + std::to_string(i) +
                          ")");
  run.contact_force = required_series(file, file_path, format::contact_force_dataset, run.time.size());
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
                        "', and the attribute '" + format::impact_velocity.path +
                        "' is missing");
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
    fail(file_path, "no contact: 'contact_force' is never positive (the sphere did not reach "
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
                    "simulated time (" + std::to_string(run.time.back() * 1e6) +
                    " us; summary.json and the file have no '" +
                    std::string(format::restitution_key) +
                    "'): no restitution to calibrate or judge; lengthen the run to see one");
  if (!(std::isfinite(*restitution) && *restitution > 0))
    fail(file_path, "the restitution must be positive (got " + std::to_string(*restitution) + ")");
  run.restitution = *restitution;

  run.first_contact_time =
      results.number(format::first_contact_time_key)
          .value_or(first > 0 ? std::max(run.time[first - 1], force_zero_time(run, first, first + 1))
                              : run.time[0]);
  const double separation =
      last + 1 < n ? std::min(run.time[last + 1], force_zero_time(run, last, last - 1))
                   : run.time[last];
  run.contact_time = results.number(format::contact_time_key)
                         .value_or(separation - run.first_contact_time);
  run.force_max = results.number(format::force_max_key).value_or(run.contact_force[peak]);
  run.time_force_max = results.number(format::time_force_max_key).value_or(run.time[peak]);
  run.approach_max = results.number(format::approach_max_key)
                         .value_or(*std::max_element(run.approach.begin(), run.approach.end()));
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
  return run;
}

namespace {

// The run at `path`, or none: why it cannot be read is then a problem of the campaign (a run
// without rebound marked so), with the run's place in the sweep (`point`) when known.
std::optional<FemRun> read_or_record(const fs::path& path, std::vector<InputProblem>& problems,
                                     std::map<std::string, SweepValue> point = {}) {
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

} // namespace

ImpactFigures measured_quantities(const FemRun& run) {
  return {run.restitution, run.contact_time, run.force_max,
          run.time_force_max - run.first_contact_time, run.approach_max};
}

Campaign read_runs(const std::vector<fs::path>& paths) {
  Campaign campaign;
  for (const auto& path : paths)
    if (auto run = read_or_record(path, campaign.problems)) campaign.runs.push_back(std::move(*run));
  sort_by_velocity(campaign.runs);
  return campaign;
}

namespace {

struct IndexEntry {
  fs::path path;
  std::optional<double> velocity;
  std::optional<std::map<std::string, SweepValue>> point; ///< the index's "point"
};

[[noreturn]] void index_error(const fs::path& index_file, const std::string& problem) {
  throw RunInputError("campaign index " + quoted(index_file) + ": " + problem);
}

std::string value_text(const SweepValue& value) { return "'" + value.text + "'"; }

// A JSON number or string of the sweep (numbers with every digit as text).
SweepValue sweep_value(const nlohmann::json& value, const fs::path& index_file,
                       const std::string& where) {
  if (value.is_number()) {
    std::ostringstream text;
    text.precision(15);
    text << value.get<double>();
    return {text.str(), value.get<double>()};
  }
  if (value.is_string()) {
    SweepValue result{value.get<std::string>(), std::nullopt};
    try {
      std::size_t end = 0;
      const double number = std::stod(result.text, &end);
      if (end == result.text.size() && std::isfinite(number)) result.number = number;
    } catch (const std::exception&) {
    }
    return result;
  }
  index_error(index_file, where + " must be a number or a string (got " + value.dump() + ")");
}

std::vector<SweepAxis> read_axes(const nlohmann::json& index, const fs::path& index_file) {
  std::vector<SweepAxis> axes;
  if (!index.is_object() || !index.contains("axes")) return axes;
  const nlohmann::json& list = index["axes"];
  if (!list.is_array() || list.empty())
    index_error(index_file, "\"axes\" must be a non-empty list of {\"parameter\", \"values\"}");
  for (const auto& axis : list) {
    if (!axis.is_object() || !axis.contains("parameter") || !axis["parameter"].is_string() ||
        axis["parameter"].get<std::string>().empty())
      index_error(index_file, "the axis " + axis.dump() + " has no \"parameter\" (a string)");
    SweepAxis entry{axis["parameter"].get<std::string>(), {}};
    for (const auto& other : axes)
      if (other.parameter == entry.parameter)
        index_error(index_file, "the axis '" + entry.parameter + "' is listed twice");
    if (!axis.contains("values") || !axis["values"].is_array() || axis["values"].empty())
      index_error(index_file, "the axis '" + entry.parameter +
                                  "' has no \"values\" (a non-empty list)");
    for (const auto& value : axis["values"]) {
      SweepValue parsed = sweep_value(value, index_file, "a value of the axis '" + entry.parameter + "'");
      for (const auto& known : entry.values)
        if (known.matches(parsed))
          index_error(index_file, "the axis '" + entry.parameter + "' lists the value " +
                                      value_text(parsed) + " twice");
      entry.values.push_back(std::move(parsed));
    }
    axes.push_back(std::move(entry));
  }
  return axes;
}

// A point (of the index or of a run) checked against the axes: every axis, only axes, and
// values the axes list.
void check_point(const std::map<std::string, SweepValue>& point,
                 const std::vector<SweepAxis>& axes, const std::string& file_words,
                 const std::string& whose) {
  const auto reject = [&](const std::string& problem) {
    throw RunInputError(file_words + ": " + problem);
  };
  for (const auto& axis : axes) {
    const auto found = point.find(axis.parameter);
    if (found == point.end()) reject(whose + " has no value of the axis '" + axis.parameter + "'");
    if (std::none_of(axis.values.begin(), axis.values.end(),
                     [&](const SweepValue& value) { return value.matches(found->second); }))
      reject(whose + " has '" + axis.parameter + "' = " + value_text(found->second) +
             ", which is not one of the axis's values");
  }
  for (const auto& [parameter, value] : point)
    if (std::none_of(axes.begin(), axes.end(),
                     [&](const SweepAxis& axis) { return axis.parameter == parameter; }))
      reject(whose + " has a value of '" + parameter + "', which is not an axis");
}

std::string describe(const IndexEntry& entry) {
  std::ostringstream text;
  if (entry.velocity) text << " (velocity " << *entry.velocity << " m/s)";
  return text.str();
}

std::vector<IndexEntry> read_json_index(const fs::path& index_file, std::vector<SweepAxis>& axes) {
  nlohmann::json index;
  try {
    std::ifstream in(index_file);
    index = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw RunInputError("campaign index " + quoted(index_file) + " is not valid JSON (" +
                        error.what() + ")");
  }
  const nlohmann::json& runs = index.is_object() && index.contains("runs") ? index["runs"] : index;
  if (!runs.is_array())
    throw RunInputError("campaign index " + quoted(index_file) +
                        ": expected a list of runs, or an object with a list \"runs\"");
  axes = read_axes(index, index_file);
  std::vector<IndexEntry> entries;
  for (const auto& run : runs) {
    IndexEntry entry;
    if (run.is_string()) {
      entry.path = run.get<std::string>();
    } else if (run.is_object() && run.contains("path") && run["path"].is_string()) {
      entry.path = run["path"].get<std::string>();
      if (run.contains("velocity") && run["velocity"].is_number())
        entry.velocity = run["velocity"].get<double>();
      if (run.contains("point")) {
        const std::string whose = "the point of the run '" + entry.path.string() + "'";
        if (!run["point"].is_object()) index_error(index_file, whose + " is not an object");
        if (axes.empty())
          index_error(index_file, whose + " is given, but the index has no \"axes\"");
        std::map<std::string, SweepValue> point;
        for (const auto& [parameter, value] : run["point"].items())
          point[parameter] = sweep_value(value, index_file, whose + "'s '" + parameter + "'");
        check_point(point, axes, "campaign index " + quoted(index_file), whose);
        const auto at = point.find(velocity_axis);
        if (at != point.end() && entry.velocity && at->second.number &&
            !at->second.matches({"", *entry.velocity}))
          index_error(index_file, whose + " has the velocity " + at->second.text +
                                      " m/s, but the entry's \"velocity\" is " +
                                      run["velocity"].dump());
        entry.point = std::move(point);
      }
    } else {
      throw RunInputError("campaign index " + quoted(index_file) + ": the entry " + run.dump() +
                          " has no \"path\"");
    }
    entries.push_back(entry);
  }
  return entries;
}

// The run's point: the index's, checked against the run's own parameters (its text
// attributes), else the run's parameters for the index's axes.
std::map<std::string, SweepValue> point_of(const FemRun& run,
                                           const std::optional<std::map<std::string, SweepValue>>& listed,
                                           const std::vector<SweepAxis>& axes) {
  std::map<std::string, SweepValue> own;
  for (const auto& axis : axes) {
    const auto attribute = run.text_attributes.find(axis.parameter);
    if (attribute != run.text_attributes.end())
      own[axis.parameter] = sweep_value(nlohmann::json(attribute->second), run.source,
                                        "the parameter '" + axis.parameter + "'");
  }
  if (!listed) {
    for (const auto& axis : axes)
      if (!own.count(axis.parameter))
        fail(run.source, "the campaign index gives no \"point\" for this run and the run has no "
                         "parameter '" + axis.parameter + "' (text attribute), so its place in "
                         "the sweep is not known");
    check_point(own, axes, "run " + quoted(fs::path(run.source)), "the run's parameters");
    return own;
  }
  for (const auto& [parameter, value] : own)
    if (!listed->at(parameter).matches(value))
      fail(run.source, "its parameter '" + parameter + "' = '" + value.text +
                           "' differs from its point in the campaign index ('" +
                           listed->at(parameter).text + "')");
  return *listed;
}

} // namespace

bool SweepValue::matches(const SweepValue& other) const {
  if (number && other.number)
    return same_value(*number, *other.number);
  return !number && !other.number && text == other.text;
}

Campaign read_campaign(const fs::path& directory) {
  if (!fs::is_directory(directory))
    throw RunInputError("campaign directory " + quoted(directory) +
                        (fs::exists(directory) ? " is not a directory" : " does not exist"));
  std::vector<IndexEntry> entries;
  std::vector<SweepAxis> axes;
  bool indexed = false;
  if (fs::exists(directory / format::campaign_index_json)) {
    entries = read_json_index(directory / format::campaign_index_json, axes);
    indexed = true;
  } else {
    std::vector<fs::path> found;
    for (const auto& item : fs::directory_iterator(directory)) {
      const fs::path& path = item.path();
      if (item.is_directory() && (fs::exists(path / format::history_file) ||
                                  fs::exists(path / format::incomplete_history_file)))
        found.push_back(path);
      else if (item.is_regular_file() && path.extension() == ".h5")
        found.push_back(path);
    }
    std::sort(found.begin(), found.end());
    // Relative to the campaign directory, as the entries of an index are.
    for (const auto& path : found) entries.push_back({path.filename(), std::nullopt, std::nullopt});
  }
  if (entries.empty())
    throw RunInputError("campaign directory " + quoted(directory) + " holds no run" +
                        (indexed ? std::string(" (its index lists none)")
                                 : std::string(" (no ") + format::campaign_index_json +
                                       ", no subdirectory with " +
                                       format::history_file + ")"));

  std::vector<fs::path> paths;
  std::vector<const IndexEntry*> listed;
  Campaign missing;
  for (auto& entry : entries) {
    if (entry.path.is_relative()) entry.path = directory / entry.path;
    if (!fs::exists(entry.path) &&
        !(entry.path.filename() == format::history_file &&
          fs::exists(incomplete_sibling(entry.path)))) {
      missing.problems.push_back(
          {{entry.path.string(), ProblemKind::input,
            "run " + quoted(entry.path) + describe(entry) +
                " is listed in the campaign index but does not exist"}});
      continue;
    }
    paths.push_back(entry.path);
    listed.push_back(&entry);
  }
  Campaign campaign;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    auto run = read_or_record(paths[k], campaign.problems,
                              listed[k]->point.value_or(std::map<std::string, SweepValue>{}));
    if (!run) continue;
    if (!axes.empty()) run->sweep_point = point_of(*run, listed[k]->point, axes);
    campaign.runs.push_back(std::move(*run));
  }
  sort_by_velocity(campaign.runs);
  campaign.problems.insert(campaign.problems.begin(), missing.problems.begin(),
                           missing.problems.end());
  campaign.axes = std::move(axes);
  return campaign;
}

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
  } series[] = {
      {format::time_dataset, run.time, format::time_unit, "simulated time"},
      {format::contact_force_dataset, run.contact_force, format::contact_force_unit,
       "total normal contact force"},
      {format::approach_dataset, run.approach, format::approach_unit,
       "approach (indentation) of sphere and plate"},
      {format::sphere_velocity_dataset, run.sphere_velocity, format::sphere_velocity_unit,
       "centre-of-mass velocity of the sphere, downward positive"}};
  for (const auto& s : series)
    if (!s.values.empty()) file.write_dataset(s.name, s.values, s.unit, s.description);

  const fs::path summary_file = summary_path_of(file_path);
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
