// The section "In your simulator": what Simbody, MuJoCo and LAMMPS themselves measure with the
// files of impact-export (the result files of tests/consumers/run_in_simulators.sh, format
// "impact-simulator-run", postprocess/README.md), against the FEM of this report and against
// the reduced model each file was exported from. Read here, checked against the report's
// runs (a file made from another campaign would compare the tool with another FEM), judged by
// the verdict's rule and written as one table per file.

#include "report_parts.hpp"

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
// The FEM numbers of a result file are the calibration's, passed through JSON files without
// loss; anything beyond rounding means another campaign or calibration.
constexpr double same_fem = 1e-9;
// What the tools measure: x_max and t(F_max) are not among them.
const std::vector<Quantity> judged_quantities = {Quantity::energy_loss, Quantity::contact_time,
                                                 Quantity::force_max};
const std::vector<Quantity> table_quantities = {Quantity::restitution, Quantity::energy_loss,
                                                Quantity::contact_time, Quantity::force_max};

// ---- Reading ------------------------------------------------------------------------------

// A result file that cannot be used; the message names the key.
class BadResult : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

const json& member(const json& object, const std::string& key, const std::string& path) {
  if (!object.is_object()) throw BadResult(path + " is not an object");
  const auto found = object.find(key);
  if (found == object.end()) throw BadResult((path.empty() ? "" : path + ".") + key + " is missing");
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
ImpactQuantities impact_of(const json& object, const std::string& key, const std::string& path) {
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
  if (!document.is_object() || !document.contains("format") ||
      document["format"] != result_format)
    throw BadResult("is not a result file of format '" + result_format +
                    "' (the key 'format' is " +
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
    result.runs.push_back({number(runs[i], "impact_velocity", path), impact_of(runs[i], "tool", path),
                           impact_of(runs[i], "reduced_model", path), impact_of(runs[i], "fem", path)});
  }
  std::sort(result.runs.begin(), result.runs.end(),
            [](const SimulatorRunAt& a, const SimulatorRunAt& b) { return a.velocity < b.velocity; });
  return result;
}

// The run of the report at this velocity, or none.
std::optional<std::size_t> report_run(const Report& report, double velocity) {
  for (std::size_t i = 0; i < report.runs.size(); ++i)
    if (same_velocity(report.runs[i].velocity, velocity)) return i;
  return std::nullopt;
}

// Why the file does not belong to this report's campaign, or "".
std::string other_campaign(const Report& report, const SimulatorResult& result) {
  for (const auto& run : result.runs) {
    const auto index = report_run(report, run.velocity);
    if (!index)
      return "V = " + short_number(run.velocity) + " m/s is not a velocity of this report's "
             "campaign (" + report.campaign_source + ")";
    const ImpactQuantities& fem = report.runs[*index].fem;
    for (Quantity quantity : {Quantity::restitution, Quantity::contact_time, Quantity::force_max}) {
      const double difference = relative_error(value(run.fem, quantity), value(fem, quantity));
      if (!(std::abs(difference) <= same_fem))
        return "its FEM " + std::string(quantity_symbol(quantity)) + " at " +
               velocity_label(run.velocity) + " is " + cell(value(run.fem, quantity)) +
               ", this report's is " + cell(value(fem, quantity));
    }
  }
  return "";
}

// Simbody, MuJoCo, LAMMPS, then any other tool; by file within a tool.
int tool_rank(const std::string& tool) {
  const std::vector<std::string> order = {"simbody", "mujoco", "lammps"};
  const auto found = std::find(order.begin(), order.end(), tool);
  return int(found - order.begin());
}

// ---- Words --------------------------------------------------------------------------------

std::string tool_name(const std::string& tool) {
  if (tool == "simbody") return "Simbody";
  if (tool == "mujoco") return "MuJoCo";
  if (tool == "lammps") return "LAMMPS";
  return tool;
}

bool linear_spring_damper(const SimulatorResult& result) {
  return result.model == "linear-spring-damper";
}

// The table's display of each quantity: scale and unit.
double display_scale(Quantity quantity) {
  switch (quantity) {
  case Quantity::contact_time: return 1e6;
  case Quantity::force_max: return 1e-3;
  default: return 1;
  }
}

std::string display_unit(Quantity quantity) {
  switch (quantity) {
  case Quantity::contact_time: return " [µs]";
  case Quantity::force_max: return " [kN]";
  default: return "";
  }
}

// The largest |error| of `quantity` over the runs and where, against the FEM or the model.
struct Worst {
  double error = nan;
  double velocity = nan;
};

Worst worst_error(const SimulatorResult& result, Quantity quantity, bool against_fem) {
  Worst worst;
  for (const auto& run : result.runs) {
    const double error =
        relative_error(run.tool, against_fem ? run.fem : run.reduced_model, quantity);
    if (std::isfinite(error) && !(std::abs(error) <= std::abs(worst.error)))
      worst = {error, run.velocity};
  }
  return worst;
}

double rms_against_fem(const SimulatorResult& result) {
  double sum = 0;
  std::size_t count = 0;
  for (const auto& run : result.runs)
    for (Quantity quantity : judged_quantities) {
      const double error = relative_error(run.tool, run.fem, quantity);
      if (!std::isfinite(error)) continue; // 1 - e^2 = 0: no relative error
      sum += error * error;
      ++count;
    }
  return count ? std::sqrt(sum / double(count)) : nan;
}

double largest_against_model(const SimulatorResult& result) {
  double largest = 0;
  for (Quantity quantity : table_quantities) {
    const double error = std::abs(worst_error(result, quantity, false).error);
    if (std::isfinite(error)) largest = std::max(largest, error);
  }
  return largest;
}

fs::path export_directory(const SimulatorResult& result) {
  return fs::path(result.export_manifest).parent_path();
}

std::string commands(const Report& report) {
  // The report's own inputs where they are a campaign directory and a calibration file.
  std::error_code error;
  const std::string campaign = fs::is_directory(report.campaign_source, error)
                                   ? "--campaign " + report.campaign_source
                                   : std::string("RUN...");
  const std::string calibration = fs::is_regular_file(report.calibration_source, error)
                                      ? report.calibration_source
                                      : std::string("CALIBRATION.json");
  return "build/bin/impact-export " + campaign + " --calibration " + calibration +
         " --output EXPORT_DIR\n"
         "tests/consumers/run_in_simulators.sh EXPORT_DIR RESULTS_DIR\n"
         "build/bin/impact-report " + campaign + " --calibration " + calibration +
         " --output REPORT_DIR --simulators RESULTS_DIR";
}

void result_subsection(Document& doc, const Report& report, const SimulatorResult& result) {
  const std::string name = tool_name(result.tool);
  doc.heading(name + " " + result.tool_version + ": " + result.file, 3);
  doc.paragraph("Model " + result.model + ". The file to use: " +
                (export_directory(result) / result.file).string() + " (" + result.file +
                " of the export " + export_directory(result).string() + "). " +
                (result.reference_velocity
                     ? "Matched to the FEM at the reference velocity V = " +
                           short_number(*result.reference_velocity) + " m/s. "
                     : std::string()) +
                "Result file: " + result.source + ".");

  Table table{{"V [m/s]"}, {}};
  for (Quantity quantity : table_quantities) {
    const std::string symbol = quantity_symbol(quantity);
    table.header.push_back(symbol + " " + name + display_unit(quantity));
    table.header.push_back(symbol + " FEM" + display_unit(quantity));
    table.header.push_back("error " + symbol);
  }
  table.header.push_back("largest |error| vs exported model (e, 1 - e^2, t_c, F_max)");
  for (const auto& run : result.runs) {
    const auto index = report_run(report, run.velocity);
    const bool reference =
        result.reference_velocity && same_velocity(*result.reference_velocity, run.velocity);
    std::vector<std::string> row{(index ? velocity_cell(report.runs[*index]) : cell(run.velocity)) +
                                 (reference ? " (reference)" : "")};
    for (Quantity quantity : table_quantities) {
      row.push_back(cell(value(run.tool, quantity) * display_scale(quantity)));
      row.push_back(cell(value(run.fem, quantity) * display_scale(quantity)));
      row.push_back(percent_cell(relative_error(run.tool, run.fem, quantity)));
    }
    double deviation = 0;
    for (Quantity quantity : table_quantities)
      deviation = std::max(deviation, std::abs(relative_error(run.tool, run.reduced_model, quantity)));
    row.push_back(unsigned_percent(deviation));
    table.rows.push_back(row);
  }
  doc.table(table);

  doc.paragraph(name + " (" + result.file + ") against the FEM in the energy loss 1 - e^2, t_c "
                "and F_max, by the verdict's rule:");
  std::vector<std::string> items;
  for (const auto& verdict : result.against_fem) items.push_back(verdict.text);
  std::string worst = "Largest errors against the FEM:";
  for (Quantity quantity : judged_quantities) {
    const Worst w = worst_error(result, quantity, true);
    worst += std::string(quantity == judged_quantities.front() ? " " : ", ") +
             quantity_symbol(quantity) + " " + percent_cell(w.error) + " (" +
             velocity_label(w.velocity) + ")";
  }
  worst += "; against the model it was exported from, at most " +
           unsigned_percent(largest_against_model(result)) + " in e, 1 - e^2, t_c and F_max.";
  items.push_back(worst);
  doc.list(items);
  if (linear_spring_damper(result)) {
    std::string text =
        name + "'s contact is a linear spring–damper (the file's solref and solimp): its "
        "stiffness and damping are matched to the FEM's e and t_c at the reference velocity" +
        (result.reference_velocity ? " V = " + short_number(*result.reference_velocity) + " m/s"
                                   : std::string()) +
        ". Its e and t_c do not depend on V and its F_max grows in proportion to V, so away "
        "from the reference velocity it is off by what a linear law misses";
    for (const auto& run : result.runs)
      if (result.reference_velocity && same_velocity(*result.reference_velocity, run.velocity))
        text += "; even there its F_max is off by " +
                percent_cell(relative_error(run.tool, run.fem, Quantity::force_max)) +
                " (a linear law cannot match e, t_c and F_max at once)";
    doc.paragraph(text + ".");
  }
}

} // namespace

void add_simulators(Report& report, const fs::path& directory) {
  report.simulators_source = directory.string();
  const auto problem = [&](const std::string& source, const std::string& message) {
    report.problems.push_back({source, "input", message});
  };
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    problem(directory.string(), "the simulators directory (--simulators) does not exist: the "
                                "section 'In your simulator' has no results");
    return;
  }
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator(directory, error))
    if (item.is_regular_file() && item.path().extension() == ".json") files.push_back(item.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    problem(directory.string(), "the simulators directory (--simulators) holds no result file "
                                "(*.json of format '" + result_format +
                                "'; tests/consumers/run_in_simulators.sh writes them)");
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
      problem(file.string(), "the simulator result was made from another campaign or "
                             "calibration: " + why + "; left out of 'In your simulator'");
      continue;
    }
    std::vector<std::optional<ImpactQuantities>> judged(report.runs.size());
    for (const auto& run : result.runs) judged[*report_run(report, run.velocity)] = run.tool;
    for (double tolerance : report.tolerances)
      result.against_fem.push_back(tolerance_verdict(report, judged, tolerance, judged_quantities,
                                                     " in " + tool_name(result.tool)));
    report.simulators.push_back(std::move(result));
  }
  std::stable_sort(report.simulators.begin(), report.simulators.end(),
                   [](const SimulatorResult& a, const SimulatorResult& b) {
                     return tool_rank(a.tool) < tool_rank(b.tool);
                   });
}

void simulators_section(Document& doc, const Report& report) {
  doc.heading("In your simulator");
  if (!report.simulators_source) {
    doc.paragraph("Not produced: this section shows what Simbody, MuJoCo and LAMMPS themselves "
                  "measure with the contact exported for them by impact-export, against the FEM "
                  "and against the exported model. To produce it (the tools are installed by "
                  "./setup.sh; run_in_simulators.sh drops the campaign's sphere in each tool at "
                  "each campaign velocity and writes one result file per exported file), run "
                  "from the source directory:");
    doc.code(commands(report));
    return;
  }
  doc.paragraph("What each tool measured itself, with the file exported for it by impact-export "
                "(the result files in " + *report.simulators_source +
                ", written by tests/consumers/run_in_simulators.sh): the campaign's sphere "
                "dropped on a fixed plane at each campaign velocity, no gravity, no friction; "
                "e, t_c and F_max from the tool's own state. Errors are (tool - reference) / "
                "|reference|, against the FEM (the calibration's numbers, as everywhere in this "
                "report) and against the reduced model the file was exported from (its "
                "prediction in export.json): the second says whether the tool runs the exported "
                "law, the first what a user of the file gets. The ranges within each band follow "
                "the verdict's rule, with the FEM's uncertainty, in 1 - e^2, t_c and F_max (the "
                "tools do not report x_max).");
  if (report.simulators.empty()) {
    doc.warning("No usable result file in " + *report.simulators_source + " (see Status).");
    return;
  }
  Table summary{{"tool", "version", "model", "file"}, {}};
  for (double tolerance : report.tolerances) summary.header.push_back("within " + band_name(tolerance));
  summary.header.push_back("RMS error vs FEM (1 - e^2, t_c, F_max)");
  summary.header.push_back("largest |error| vs exported model");
  for (const auto& result : report.simulators) {
    std::vector<std::string> row{tool_name(result.tool), result.tool_version, result.model,
                                 result.file};
    for (const auto& verdict : result.against_fem) row.push_back(range_text(verdict, report));
    row.push_back(unsigned_percent(rms_against_fem(result)));
    row.push_back(unsigned_percent(largest_against_model(result)));
    summary.rows.push_back(row);
  }
  doc.table(summary);
  for (const auto& result : report.simulators) result_subsection(doc, report, result);
}

} // namespace impact::postprocess::detail
