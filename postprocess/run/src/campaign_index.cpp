// Reading a campaign (fem_run.hpp, read_campaign): its index.json (runs, sweep axes, points,
// format in postprocess/README.md), else the run directories and files it holds.

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/same_value.hpp"

#include "run_files.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace impact::postprocess {

namespace fs = std::filesystem;
namespace format = fem_format;
using detail::fail;
using detail::incomplete_sibling;
using detail::quoted;
using detail::read_or_record;
using detail::sort_by_velocity;

namespace {

struct IndexEntry {
  fs::path path;
  std::optional<double> velocity;
  std::optional<std::map<std::string, SweepValue>> point; ///< the index's "point"
};

[[noreturn]] void index_error(const fs::path& index_file, const std::string& problem) {
  throw RunInputError("campaign index " + quoted(index_file) + ": " + problem);
}

std::string value_text(const SweepValue& value) {
  return "'" + value.text + "'";
}

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
      index_error(index_file,
                  "the axis '" + entry.parameter + "' has no \"values\" (a non-empty list)");
    for (const auto& value : axis["values"]) {
      SweepValue parsed =
          sweep_value(value, index_file, "a value of the axis '" + entry.parameter + "'");
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
void check_point(const std::map<std::string, SweepValue>& point, const std::vector<SweepAxis>& axes,
                 const std::string& file_words, const std::string& whose) {
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
std::map<std::string, SweepValue> point_of(
    const FemRun& run, const std::optional<std::map<std::string, SweepValue>>& listed,
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
        fail(run.source,
             "the campaign index gives no \"point\" for this run and the run has no "
             "parameter '" +
                 axis.parameter +
                 "' (text attribute), so its place in "
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
  if (number && other.number) return same_value(*number, *other.number);
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
                                       ", no subdirectory with " + format::history_file + ")"));

  std::vector<fs::path> paths;
  std::vector<const IndexEntry*> listed;
  Campaign missing;
  for (auto& entry : entries) {
    if (entry.path.is_relative()) entry.path = directory / entry.path;
    if (!fs::exists(entry.path) && !(entry.path.filename() == format::history_file &&
                                     fs::exists(incomplete_sibling(entry.path)))) {
      missing.problems.push_back({{entry.path.string(), ProblemKind::input,
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

} // namespace impact::postprocess
