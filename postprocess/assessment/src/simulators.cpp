// The section "In your simulator": what Simbody, MuJoCo and LAMMPS themselves measure with the
// files of impact-export (the result files of tests/consumers/run_in_simulators.sh, format
// "impact-simulator-run", postprocess/README.md), against the FEM of this report and against
// the reduced model each file was exported from. Read here, checked against the report's
// runs (a file made from another campaign would compare the tool with another FEM), judged by
// the verdict's rule and written as one table per file.

#include "steps.hpp"
#include "impact_postprocess/same_value.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace impact::postprocess::detail {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

const std::string result_format = "impact-simulator-run";
constexpr int result_format_version = 1;

// ---- Reading ------------------------------------------------------------------------------

// A result file that cannot be used; the message names the key.
class BadResult : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

const json& member(const json& object, const std::string& key, const std::string& path) {
  if (!object.is_object()) throw BadResult(path + " is not an object");
  const auto found = object.find(key);
  if (found == object.end())
    throw BadResult((path.empty() ? "" : path + ".") + key + " is missing");
  return *found;
}

std::string text(const json& object, const std::string& key, const std::string& path) {
  const json& value = member(object, key, path);
  if (!value.is_string())
    throw BadResult((path.empty() ? "" : path + ".") + key + " is not a string");
  return value.get<std::string>();
}

// A finite number > 0, or >= 0 where zero is a possible value.
double number(const json& object, const std::string& key, const std::string& path,
              bool zero_allowed = false) {
  const json& value = member(object, key, path);
  const std::string name = (path.empty() ? "" : path + ".") + key;
  if (!value.is_number()) throw BadResult(name + " is not a number (got " + value.dump() + ")");
  const double x = value.get<double>();
  if (!std::isfinite(x) || x < 0 || (x == 0 && !zero_allowed))
    throw BadResult(name + " must be a finite number " + (zero_allowed ? ">= 0" : "> 0") +
                    " (got " + value.dump() + ")");
  return x;
}

// e, t_c, F_max of one impact (the energy loss and the errors of the file are derived from
// them and recomputed here, by the report's one relative error).
ImpactFigures impact_of(const json& object, const std::string& key, const std::string& path) {
  const std::string at = path + "." + key;
  const json& figures = member(object, key, path);
  return {number(figures, "restitution", at, true), number(figures, "contact_time", at),
          number(figures, "force_max", at), nan, nan};
}

SimulatorResult read_result(const fs::path& file) {
  json document;
  {
    std::ifstream in(file);
    if (!in) throw BadResult("cannot be opened");
    try {
      document = json::parse(in);
    } catch (const json::parse_error& error) {
      throw BadResult(std::string("is not JSON (") + error.what() + ")");
    }
  }
  if (!document.is_object() || !document.contains("format") || document["format"] != result_format)
    throw BadResult("is not a result file of format '" + result_format + "' (the key 'format' is " +
                    (document.is_object() && document.contains("format") ? document["format"].dump()
                                                                         : std::string("missing")) +
                    ")");
  const json& version = member(document, "format_version", "");
  if (version != result_format_version)
    throw BadResult("has format_version " + version.dump() + "; impact-report reads version " +
                    std::to_string(result_format_version));
  SimulatorResult result;
  result.source = file.string();
  result.tool = text(document, "tool", "");
  result.tool_version = text(document, "tool_version", "");
  result.model = text(document, "model", "");
  result.export_manifest = text(document, "export", "");
  result.file = text(document, "file", "");
  const json& reference = member(document, "reference_velocity", "");
  if (!reference.is_null()) result.reference_velocity = number(document, "reference_velocity", "");
  const json& runs = member(document, "runs", "");
  if (!runs.is_array() || runs.empty()) throw BadResult("runs is not a non-empty list");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string path = "runs[" + std::to_string(i) + "]";
    result.runs.push_back(
        {number(runs[i], "impact_velocity", path), impact_of(runs[i], "tool", path),
         impact_of(runs[i], "reduced_model", path), impact_of(runs[i], "fem", path)});
  }
  std::sort(result.runs.begin(), result.runs.end(),
            [](const SimulatorRunAt& a, const SimulatorRunAt& b) {
              return a.velocity < b.velocity;
            });
  return result;
}

// Why the file does not belong to this report's campaign, or "".
std::string other_campaign(const Assessment& report, const SimulatorResult& result) {
  for (const auto& run : result.runs) {
    const auto index = report_run(report, run.velocity);
    if (!index)
      return "V = " + short_number(run.velocity) +
             " m/s is not a velocity of this report's "
             "campaign (" +
             report.campaign_source + ")";
    const ImpactFigures& fem = report.runs[*index].fem;
    for (Quantity quantity : {Quantity::restitution, Quantity::contact_time, Quantity::force_max}) {
      // The FEM numbers of a result file are the calibration's, passed through JSON files
      // without loss; anything beyond rounding means another campaign or calibration.
      if (!same_value(value(run.fem, quantity), value(fem, quantity)))
        return "its FEM " + std::string(quantity_symbol(quantity)) + " at " +
               velocity_label(run.velocity) + " is " + cell(value(run.fem, quantity)) +
               ", this report's is " + cell(value(fem, quantity));
    }
  }
  return "";
}

// Simbody, MuJoCo, LAMMPS, LIGGGHTS, each tool's run of the restitution table's law through
// its extension point beside it, then any other tool; by file within a tool.
int tool_rank(const std::string& tool) {
  const std::vector<std::string> order = {"simbody", "simbody-custom",  "mujoco",
                                          "lammps",  "lammps-external", "liggghts"};
  const auto found = std::find(order.begin(), order.end(), tool);
  return int(found - order.begin());
}

} // namespace

std::optional<std::size_t> report_run(const Assessment& report, double velocity) {
  for (std::size_t i = 0; i < report.runs.size(); ++i)
    if (same_velocity(report.runs[i].velocity, velocity)) return i;
  return std::nullopt;
}

void add_simulators(Assessment& report, const fs::path& directory) {
  report.simulators_source = directory.string();
  const auto problem = [&](const std::string& source, const std::string& message) {
    report.problems.push_back({source, ProblemKind::input, message});
  };
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    problem(directory.string(),
            "the simulators directory (--simulators) does not exist: the "
            "section 'In your simulator' has no results");
    return;
  }
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator(directory, error))
    if (item.is_regular_file() && item.path().extension() == ".json") files.push_back(item.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    problem(directory.string(),
            "the simulators directory (--simulators) holds no result file "
            "(*.json of format '" +
                result_format + "'; tests/consumers/run_in_simulators.sh writes them)");
    return;
  }
  for (const auto& file : files) {
    SimulatorResult result;
    try {
      result = read_result(file);
    } catch (const BadResult& bad) {
      problem(file.string(), std::string("not a usable simulator result: ") + bad.what() +
                                 "; left out of 'In your simulator'");
      continue;
    }
    if (const std::string why = other_campaign(report, result); !why.empty()) {
      problem(file.string(),
              "the simulator result was made from another campaign or "
              "calibration: " +
                  why + "; left out of 'In your simulator'");
      continue;
    }
    std::vector<std::optional<ImpactFigures>> judged(report.runs.size());
    for (const auto& run : result.runs) judged[*report_run(report, run.velocity)] = run.tool;
    for (double tolerance : report.tolerances)
      result.against_fem.push_back(
          tolerance_verdict(report, judged, tolerance, simulator_judged_quantities));
    report.simulators.push_back(std::move(result));
  }
  std::stable_sort(report.simulators.begin(), report.simulators.end(),
                   [](const SimulatorResult& a, const SimulatorResult& b) {
                     return tool_rank(a.tool) < tool_rank(b.tool);
                   });
}

} // namespace impact::postprocess::detail
