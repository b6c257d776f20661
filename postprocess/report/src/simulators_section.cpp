// The section "In your simulator" (sections.hpp): the simulators' results judged in
// assessment/simulators.cpp, in words and tables, or the commands that make them.

#include "sections.hpp"
#include "impact_postprocess/report/verdict_words.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace impact::postprocess::detail {

std::string simulator_tool_name(const std::string& tool) {
  if (tool == "simbody") return "Simbody";
  if (tool == "mujoco") return "MuJoCo";
  if (tool == "lammps") return "LAMMPS";
  if (tool == "liggghts") return "LIGGGHTS";
  if (tool == "simbody-custom") return "Simbody (Force::Custom)";
  if (tool == "lammps-external") return "LAMMPS (fix external)";
  return tool;
}

namespace {

namespace fs = std::filesystem;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

bool linear_spring_damper(const SimulatorResult& result) {
  return result.model == "linear-spring-damper";
}

// The restitution table's law, run through the tool's own extension point (no built-in
// contact of the tool carries it).
bool extension_point(const SimulatorResult& result) {
  return result.tool == "simbody-custom" || result.tool == "lammps-external";
}

// The table's display of each quantity: scale and unit.
double display_scale(Quantity quantity) {
  switch (quantity) {
    case Quantity::contact_time:
      return 1e6;
    case Quantity::force_max:
      return 1e-3;
    default:
      return 1;
  }
}

std::string display_unit(Quantity quantity) {
  switch (quantity) {
    case Quantity::contact_time:
      return " [µs]";
    case Quantity::force_max:
      return " [kN]";
    default:
      return "";
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
    for (Quantity quantity : simulator_judged_quantities) {
      const double error = relative_error(run.tool, run.fem, quantity);
      if (!std::isfinite(error)) continue; // 1 - e^2 = 0: no relative error
      sum += error * error;
      ++count;
    }
  return count ? std::sqrt(sum / double(count)) : nan;
}

double largest_against_model(const SimulatorResult& result) {
  double largest = 0;
  for (Quantity quantity : simulator_table_quantities) {
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
         "build/bin/impact-report " +
         campaign + " --calibration " + calibration +
         " --output REPORT_DIR --simulators RESULTS_DIR";
}

void result_subsection(Document& doc, const Report& report, const SimulatorResult& result) {
  const std::string name = simulator_tool_name(result.tool);
  doc.heading(name + " " + result.tool_version + ": " + result.file, 3);
  doc.paragraph("Model " + result.model +
                ". The file to use: " + (export_directory(result) / result.file).string() + " (" +
                result.file + " of the export " + export_directory(result).string() + "). " +
                (result.reference_velocity ? "Matched to the FEM at the reference velocity V = " +
                                                 short_number(*result.reference_velocity) + " m/s. "
                                           : std::string()) +
                "Result file: " + result.source + ".");

  Table table{{"V [m/s]"}, {}};
  for (Quantity quantity : simulator_table_quantities) {
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
    for (Quantity quantity : simulator_table_quantities) {
      row.push_back(cell(value(run.tool, quantity) * display_scale(quantity)));
      row.push_back(cell(value(run.fem, quantity) * display_scale(quantity)));
      row.push_back(percent_cell(relative_error(run.tool, run.fem, quantity)));
    }
    double deviation = 0;
    for (Quantity quantity : simulator_table_quantities)
      deviation =
          std::max(deviation, std::abs(relative_error(run.tool, run.reduced_model, quantity)));
    row.push_back(unsigned_percent(deviation));
    table.rows.push_back(row);
  }
  doc.table(table);

  doc.paragraph(name + " (" + result.file +
                ") against the FEM in the energy loss 1 - e^2, t_c "
                "and F_max, by the verdict's rule:");
  std::vector<std::string> items;
  for (const auto& verdict : result.against_fem)
    items.push_back(tolerance_sentence(report, verdict, " in " + simulator_tool_name(result.tool)));
  std::string worst = "Largest errors against the FEM:";
  for (Quantity quantity : simulator_judged_quantities) {
    const Worst w = worst_error(result, quantity, true);
    worst += std::string(quantity == simulator_judged_quantities.front() ? " " : ", ") +
             quantity_symbol(quantity) + " " + percent_cell(w.error) + " (" +
             velocity_label(w.velocity) + ")";
  }
  worst += "; against the model it was exported from, at most " +
           unsigned_percent(largest_against_model(result)) + " in e, 1 - e^2, t_c and F_max.";
  items.push_back(worst);
  doc.list(items);
  if (extension_point(result)) {
    const fs::path table = fs::path(result.file).replace_extension(".csv");
    doc.paragraph(
        "The damped elastic-plastic law " + result.model +
        (result.model.rfind("kuwabara-kono", 0) == 0
             ? " (F = F_s(x) + A k_t(x) x', k_t = dF_s/dx, F_s"
             : " (F = F_s(x) (1 + b x'), F_s") +
        " the spring's loading branch while the approach grows and "
        "its unloading branch from the largest approach x_max after) is no built-in contact "
        "of " +
        simulator_tool_name(result.tool.substr(0, result.tool.find('-'))) + ": it runs " +
        (result.tool == "simbody-custom"
             ? "as a SimTK::Force::Custom on the sphere, with x_max a continuous state of the "
               "force (z' = max(x', 0)) integrated under Simbody's error control"
             : "through fix external (pf/callback) of LAMMPS's library interface: at every step "
               "the callback reads the sphere's height and velocity and returns the wall's "
               "force, x_max kept between steps; fix nve/sphere integrates with the half-step "
               "velocity, an error of first order in the step") +
        ". Its parameters are those of the restitution table " +
        (export_directory(result) / table).string() +
        " (e(V), t_c(V), F_max(V) over the campaign's range for an impulse-based engine, "
        "with the FEM's uncertainty and the law's error per row); the spring is the reduced "
        "library's.");
  }
  if (linear_spring_damper(result)) {
    std::string text =
        name +
        "'s contact is a linear spring–damper (the file's solref and solimp): its "
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

void simulators_section(Document& doc, const Report& report) {
  doc.heading("In your simulator");
  if (!report.simulators_source) {
    doc.paragraph(
        "Not produced: this section shows what Simbody, MuJoCo, LAMMPS and LIGGGHTS "
        "themselves measure with the contact exported for them by impact-export (and, "
        "through Simbody's Force::Custom and LAMMPS's fix external, the damped "
        "elastic-plastic law of its restitution table), against the FEM "
        "and against the exported model. To produce it (the tools are installed by "
        "./setup.sh; run_in_simulators.sh drops the campaign's sphere in each tool at "
        "each campaign velocity and writes one result file per exported file), run "
        "from the source directory:");
    doc.code(commands(report));
    return;
  }
  doc.paragraph(
      "What each tool measured itself, with the file exported for it by impact-export "
      "(the result files in " +
      *report.simulators_source +
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
  for (double tolerance : report.tolerances)
    summary.header.push_back("within " + band_name(tolerance));
  summary.header.push_back("RMS error vs FEM (1 - e^2, t_c, F_max)");
  summary.header.push_back("largest |error| vs exported model");
  for (const auto& result : report.simulators) {
    std::vector<std::string> row{simulator_tool_name(result.tool), result.tool_version,
                                 result.model, result.file};
    for (const auto& verdict : result.against_fem) row.push_back(range_text(verdict, report));
    row.push_back(unsigned_percent(rms_against_fem(result)));
    row.push_back(unsigned_percent(largest_against_model(result)));
    summary.rows.push_back(row);
  }
  doc.table(summary);
  for (const auto& result : report.simulators) result_subsection(doc, report, result);
}

} // namespace impact::postprocess::detail
