// The section "Elastic-plastic laws" and its three figures, declared here (sections.hpp):
// e against V/V_y in log-log with the laws and the FEM's uncertainty, the permanent approach
// against V, and the force-approach loops with the plastic unloading branch. Only for a
// campaign whose material is elastic-plastic (Report::plastic_laws).

#include "sections.hpp"
#include "impact_postprocess/report/verdict_words.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

namespace {

using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

json numbers(const std::vector<double>& values, double scale = 1) {
  json out = json::array();
  for (double v : values) out.push_back(std::isfinite(v) ? json(v * scale) : json(nullptr));
  return out;
}

json line(const std::string& label, json x, json y, const std::string& color,
          const std::string& style, const std::string& marker = "") {
  return {{"label", label}, {"x", std::move(x)},  {"y", std::move(y)},
          {"color", color}, {"linestyle", style}, {"marker", marker}};
}

// A law's values: "c = 1.234e+10 N/m^1.5, x_y = 1.2e-06 m (Y = 0.3 GPa)". The laws from the
// material give Y in GPa; Jackson–Green–Marghitu's restitution fit its V_c and eps_y, with
// the caveat on its constants.
std::string parameters_words(const PlasticLawCurve& law, const PlasticLaws& laws) {
  const auto gigapascal = [](double stress) { return short_number(stress / 1e9) + " GPa"; };
  if (law.key == model_keys::jackson_green_marghitu_material && law.parameters.size() == 2)
    return "V_c = " + short_number(law.parameters[0].value) +
           " m/s, eps_y = C(nu) Y / E* = " + short_number(law.parameters[1].value) +
           "; constants as read in one implementation, unconfirmed";
  std::string text = "c = " + cell(law.stiffness) + " N/m^1.5";
  if (law.key == model_keys::jackson_green_material)
    return text + ", Y = " + gigapascal(laws.yield_strength);
  for (const auto& parameter : law.parameters)
    text += ", " + parameter.name + " = " + cell(parameter.value) + " " + parameter.unit;
  if (law.key == model_keys::thornton_material)
    text += " (Y = " + gigapascal(laws.yield_strength) + ")";
  return text;
}

// The FEM's restitution against each law at each run, in a paragraph.
std::string comparison_words(const PlasticLaws& laws, const std::vector<ReportRun>& runs) {
  std::string text =
      "The FEM's restitution against the elastic-plastic laws (law / FEM - 1 in "
      "e, per run):";
  for (const auto& law : laws.laws) {
    text += " " + law.label + ":";
    for (std::size_t i = 0; i < runs.size(); ++i)
      text += std::string(i ? "," : "") + " " +
              percent_cell(law.run_restitution[i] / runs[i].fem.restitution - 1) + " at " +
              short_number(runs[i].velocity) + " m/s";
    text += ";";
  }
  text.back() = '.';
  text +=
      " Where the FEM records its permanent approach, the dent of each law is drawn beside it "
      "(figure below).";
  return text;
}

std::string color_of(const PlasticLawCurve& law) {
  if (law.key == model_keys::jackson_green_marghitu_material) return "tab:purple";
  // The damped laws: Hunt–Crossley on Thornton's spring (pink; b(V) from A fitted: dark
  // magenta), on Jackson–Green's (olive; b(V) from A fitted: teal), Kuwabara–Kono on them
  // (goldenrod, navy), as in the errors figure.
  if (law.damped) {
    const bool thornton = law.key.find("thornton") != std::string::npos;
    if (law.key.rfind("kuwabara-kono", 0) == 0) return thornton ? "goldenrod" : "navy";
    if (law.key == model_keys::hunt_crossley_thornton_from_a ||
        law.key == model_keys::hunt_crossley_jackson_green_from_a)
      return thornton ? "darkmagenta" : "teal";
    return thornton ? "tab:pink" : "tab:olive";
  }
  const bool thornton = law.key == model_keys::thornton || law.key == model_keys::thornton_material;
  return thornton ? "tab:blue" : "tab:green";
}

// Fitted dashed, from the material solid; a damped law fitted with a constant b dash-dotted.
std::string style_of(const PlasticLawCurve& law) {
  if (law.damped && law.fitted &&
      (law.key == model_keys::hunt_crossley_thornton ||
       law.key == model_keys::hunt_crossley_jackson_green))
    return "-.";
  return law.fitted ? "--" : "-";
}

json restitution_figure(const Report& report, const PlasticLaws& laws) {
  const double v_y = laws.yield_velocity;
  json panel = {{"title", "restitution against V/V_y (V_y = " + short_number(v_y) + " m/s)"},
                {"xlabel", "V / V_y [1] (V_y: Johnson's p_y = 1.6 Y)"},
                {"ylabel", "restitution e [1]"},
                {"xscale", "log"},
                {"yscale", "log"},
                {"series", json::array()}};
  double lowest = 1;
  for (const auto& law : laws.laws) {
    std::vector<double> ratio;
    for (double v : law.velocity) ratio.push_back(v / v_y);
    panel["series"].push_back(
        line(law.label, numbers(ratio), numbers(law.restitution), color_of(law), style_of(law)));
    for (double e : law.restitution)
      if (std::isfinite(e)) lowest = std::min(lowest, e);
  }
  // The calibrated Hunt–Crossley law (constant b), the viscoelastic law the study calibrates,
  // over the same range: how it bends against the plastic laws.
  if (const ReportModel* calibrated = report.model(model_keys::calibrated))
    if (calibrated->curve) {
      std::vector<double> ratio;
      for (double v : calibrated->curve->velocity) ratio.push_back(v / v_y);
      const auto& e = calibrated->curve->center[std::size_t(Quantity::restitution)];
      panel["series"].push_back(
          line(calibrated->label, numbers(ratio), numbers(e), "tab:red", "-"));
      for (double value : e)
        if (std::isfinite(value)) lowest = std::min(lowest, value);
    }
  // Thornton's far-field limit e -> 1.185 (V/V_y)^(-1/4) (reduced/thornton.hpp): the slope of
  // the plastic family.
  const double high = laws.laws.front().velocity.back() / v_y;
  panel["series"].push_back(
      line("plastic family: 1.185 (V/V_y)^(-1/4) (Thornton's limit)", numbers({2.0, high}),
           numbers({1.185 * std::pow(2.0, -0.25), 1.185 * std::pow(high, -0.25)}), "0.5", ":"));
  std::vector<double> ratio, e, error;
  for (const auto& run : report.runs) {
    ratio.push_back(run.velocity / v_y);
    e.push_back(run.fem.restitution);
    lowest = std::min(lowest, run.fem.restitution);
    const double u = run.uncertainty[std::size_t(Quantity::restitution)].relative;
    error.push_back(std::isfinite(u) ? u * run.fem.restitution : 0.0);
  }
  json fem = line("FEM (bars: the GCI of its verification)", numbers(ratio), numbers(e), "black",
                  "none", "o");
  fem["yerr"] = {numbers(error), numbers(error)};
  panel["series"].push_back(fem);
  panel["series"].push_back(
      line("V = V_y", numbers({1.0, 1.0}), numbers({0.9 * lowest, 1.05}), "0.3", "-."));
  // Plain tick labels: e in steps of 0.1, V/V_y at 1-2-5 steps.
  json yticks = json::array(), xticks = json::array();
  for (double tick = std::floor(lowest * 10) / 10; tick <= 1.0001; tick += 0.1)
    yticks.push_back(std::round(tick * 10) / 10);
  const double low = laws.laws.front().velocity.front() / v_y;
  for (double decade = 0.1; decade <= 1000; decade *= 10)
    for (double step : {1.0, 2.0, 5.0})
      if (step * decade >= low && step * decade <= high) xticks.push_back(step * decade);
  panel["yticks"] = yticks;
  panel["xticks"] = xticks;
  return {{"title", ""},
          {"columns", 1},
          {"width", 8.0},
          {"row_height", 4.6},
          {"shared_legend", true},
          {"legend_columns", 2},
          {"panels", json::array({panel})}};
}

json permanent_approach_figure(const Report& report, const PlasticLaws& laws) {
  json panel = {{"title", "permanent approach (dent and flattening) against V"},
                {"xlabel", "impact velocity V [m/s]"},
                {"ylabel", "permanent approach x_p [µm]"},
                {"series", json::array()}};
  for (const auto& law : laws.laws)
    if (!law.permanent_approach.empty()) // not the restitution fit
      panel["series"].push_back(line(law.label, numbers(law.velocity),
                                     numbers(law.permanent_approach, 1e6), color_of(law),
                                     style_of(law)));
  std::vector<double> v;
  for (const auto& run : report.runs) v.push_back(run.velocity);
  panel["series"].push_back(line("FEM (approach at separation)", numbers(v),
                                 numbers(laws.fem_permanent_approach, 1e6), "black", "none", "o"));
  panel["vbands"] = json::array({{{"x0", laws.laws.front().velocity.front()},
                                  {"x1", laws.yield_velocity},
                                  {"color", "0.85"},
                                  {"alpha", 0.35},
                                  {"label", "below V_y (Johnson): elastic, no dent"}}});
  return {{"title", ""},
          {"columns", 1},
          {"width", 8.0},
          {"row_height", 4.4},
          {"shared_legend", true},
          {"legend_columns", 2},
          {"panels", json::array({panel})}};
}

json loops_figure(const Report& report, const PlasticLaws& laws) {
  json panels = json::array();
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const ReportRun& run = report.runs[i];
    json panel = {{"title", velocity_label(run.velocity) + " (V/V_y = " +
                                short_number(run.velocity / laws.yield_velocity) + ")"},
                  {"xlabel", "approach x [µm]"},
                  {"ylabel", "contact force F [kN]"},
                  {"series", json::array()}};
    // The FEM from first contact to separation (the history's window extends beyond both).
    std::vector<double> approach, force;
    for (std::size_t k = 0; k < run.fem_history.time.size(); ++k)
      if (run.fem_history.time[k] >= 0 && run.fem_history.time[k] <= run.fem.contact_time) {
        approach.push_back(run.fem_history.approach[k]);
        force.push_back(run.fem_history.force[k]);
      }
    panel["series"].push_back(
        line("FEM", numbers(approach, 1e6), numbers(force, 1e-3), "black", "-"));
    for (const auto& law : laws.laws)
      if (i < law.loops.size() && !law.loops[i].approach.empty()) // none of the e fit
        panel["series"].push_back(line(law.label, numbers(law.loops[i].approach, 1e6),
                                       numbers(law.loops[i].force, 1e-3), color_of(law),
                                       style_of(law)));
    panels.push_back(panel);
  }
  return {{"title", ""},         {"columns", std::min<std::size_t>(3, panels.size())},
          {"row_height", 3.4},   {"shared_legend", true},
          {"legend_columns", 3}, {"panels", panels}};
}

} // namespace

std::vector<ReportFigure> plastic_figures(const Report& report) {
  if (!report.plastic_laws || report.runs.empty() || report.plastic_laws->laws.empty()) return {};
  const PlasticLaws& laws = *report.plastic_laws;
  return {
      {FigureId::plastic_restitution, "", "plastic_restitution.png",
       "Restitution against V/V_y in log-log: the FEM (error bars: the grid convergence index of "
       "its verification, where the run was verified), Thornton (1997) and Jackson–Green (2005) "
       "from the material (solid) and fitted (dashed), Jackson–Green–Marghitu's (2010) "
       "restitution fit from the material (constants unconfirmed), Hunt–Crossley damping on the "
       "elastic-plastic springs where the calibration holds it (Thornton's spring: pink, dark "
       "magenta with b(V) from A fitted; Jackson–Green's: olive, teal with b(V) from A fitted; "
       "a constant b fitted dash-dotted), the calibrated Hunt–Crossley law (red) and the plastic "
       "family's slope "
       "-1/4.",
       restitution_figure(report, laws)},
      {FigureId::permanent_approach, "", "permanent_approach.png",
       "Permanent approach against V: the FEM's approach at separation (dent plus the sphere's "
       "flattening) and the laws' residual approach.",
       permanent_approach_figure(report, laws)},
      {FigureId::plastic_loops, "", "plastic_loops.png",
       "Force against approach per velocity: the FEM and the elastic-plastic laws, each with its "
       "unloading branch ending at its permanent approach.",
       loops_figure(report, laws)}};
}

void plastic_section(Document& doc, const Report& report,
                     const std::function<void(FigureId)>& figure) {
  if (!report.plastic_laws) return;
  const PlasticLaws& laws = *report.plastic_laws;
  doc.heading("Elastic-plastic laws");
  doc.paragraph(
      "The FEM's material is elastic-plastic: the laws built for it are Thornton's "
      "(J. Appl. Mech. 64:383, 1997: Hertz to the limiting pressure p_y = 1.6 Y, then "
      "a linear branch, elastic unloading on an enlarged radius) and Jackson & Green's "
      "finite-element fit of the sphere on a flat (J. Tribol. 127:343, 2005, unloading "
      "on the radius of the maximum contact), both elastic–perfectly-plastic: no "
      "hardening enters them. The yield velocity of the material is V_y = " +
      short_number(laws.yield_velocity) + " m/s with Johnson's p_y = 1.6 Y and " +
      short_number(laws.jackson_green_yield_velocity) +
      " m/s with Jackson–Green's p_y = C(nu) Y (m = " + short_number(laws.mass) + " kg, " +
      laws.material_basis +
      "). Beside them, the restitution that Jackson, Green & Marghitu fitted to "
      "their finite-element impacts of an elastic–perfectly-plastic sphere on a rigid "
      "flat (Nonlinear Dyn. 60:217, 2010): e = 1 - 0.0361 eps_y^-0.114 ln(V/V_c) "
      "(V/V_c - 1)^(9.5 eps_y), V_c the critical velocity of p_y = C(nu) Y, "
      "eps_y = C(nu) Y / E*. The paper could not be read here; the formula was read "
      "in one public implementation, and its constants and the definition of eps_y "
      "could not be confirmed. It gives e only (no force, no dent).");
  std::vector<std::string> items;
  for (const auto& law : laws.laws)
    items.push_back(law.label + ": " + parameters_words(law, laws) +
                    (law.fitted ? " (campaign fit of the calibration, " +
                                      std::to_string(law.free_parameters) + " free parameters)"
                                : " (nothing fitted)"));
  doc.list(items);
  if (std::any_of(laws.laws.begin(), laws.laws.end(),
                  [](const PlasticLawCurve& law) { return law.damped; }))
    doc.paragraph(
        "Hunt–Crossley on an elastic-plastic spring, F = F_s(x) (1 + b x'), carries "
        "both losses: the viscous one through b (below the yield velocity the law is "
        "Hunt–Crossley's), the plastic one through the spring's unloading branch. From "
        "the material: the spring from E*, R and Y, and b(V) = (3/2) gamma_1 A "
        "(c/m)^(2/5) V^(-4/5) with A of the retardation times, the b whose small-loss "
        "restitution is Kuwabara–Kono's. Fitted: the yield parameter and b, with c at "
        "the Hertz value of the materials.");
  doc.paragraph(comparison_words(laws, report.runs));
  if (const std::string family = family_sentence(report); !family.empty()) doc.paragraph(family);
  Table table{{"V [m/s]", "V/V_y", "FEM e", "FEM x_p [µm]"}, {}};
  for (const auto& law : laws.laws) {
    table.header.push_back(law.label + " e");
    if (!law.run_permanent_approach.empty()) table.header.push_back(law.label + " x_p [µm]");
  }
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const ReportRun& run = report.runs[i];
    std::vector<std::string> row{velocity_cell(run),
                                 short_number(run.velocity / laws.yield_velocity),
                                 cell(run.fem.restitution),
                                 std::isfinite(laws.fem_permanent_approach[i])
                                     ? cell(laws.fem_permanent_approach[i] * 1e6)
                                     : "not recorded"};
    for (const auto& law : laws.laws) {
      row.push_back(cell(law.run_restitution[i]));
      if (!law.run_permanent_approach.empty())
        row.push_back(cell(law.run_permanent_approach[i] * 1e6));
    }
    table.rows.push_back(row);
  }
  doc.table(table);
  figure(FigureId::plastic_restitution);
  figure(FigureId::permanent_approach);
  figure(FigureId::plastic_loops);
}

} // namespace impact::postprocess::detail
