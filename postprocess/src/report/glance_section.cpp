// The first screen of the page (report_parts.hpp): the verdict in three lines, the figure of
// every model's errors against V, and the recommended model with its parameters in a form to
// copy. Everything it states is computed elsewhere (the verdict, the ranking, the trend, the
// yield check); this file only chooses what a reader needs first and says it briefly.

#include "report/report_parts.hpp"
#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include <cmath>
#include <cstdio>

namespace impact::postprocess::detail {

namespace {

// Three significant digits, as the summary of the verdict gives the trend and the yield onset.
std::string three_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// "within 2 %: 0.5 to 3 m/s; within 5 %: 0.5 to 5 m/s" of one model's verdict.
std::string ranges(const Report& report, const ModelVerdict& verdict) {
  std::string text;
  for (std::size_t k = 0; k < verdict.tolerances.size(); ++k)
    text += (k ? "; within " : "within ") + band_name(verdict.tolerances[k].tolerance) + ": " +
            range_text(verdict.tolerances[k], report);
  return text;
}

// The report's model of a calibration key (the ranking's names), null if it shows none.
const ReportModel* shown_model(const Report& report, const std::string& calibration_key) {
  for (const auto& model : report.models)
    if (model.calibration_key == calibration_key) return &model;
  return nullptr;
}

// The largest and smallest judged error of `quantity` of a model over the runs.
std::pair<double, double> error_range(const Report& report, const ReportModel& model,
                                      Quantity quantity) {
  double low = INFINITY, high = -INFINITY;
  for (std::size_t i = 0; i < report.runs.size(); ++i)
    if (const auto& judged = model.runs[i].judged()) {
      const double error = relative_error(*judged, report.runs[i].fem, quantity);
      if (!std::isfinite(error)) continue;
      low = std::min(low, error);
      high = std::max(high, error);
    }
  return {low, high};
}

// Line 1: the model ranked first, where it holds.
std::string recommendation_line(const Report& report, const RankedModel& best) {
  const ReportModel* shown = shown_model(report, best.key);
  // The no-fit plastic laws are ranked but not among the judged models: their label is the
  // one of the section "Elastic-plastic laws".
  std::string label = shown ? shown->label : "";
  if (!shown && report.plastic_laws)
    for (const auto& law : report.plastic_laws->laws)
      if (law.key == best.key) label = law.label;
  std::string text = "Use " + (label.empty() ? best.key : label + " (" + best.key + ")") +
                     ": ranked first by " + (best.out_of_sample ? "out-of-sample" : "in-sample") +
                     " error (RMS " + unsigned_percent(best.score) +
                     " over 1 - e^2, t_c, F_max and x_max, " +
                     std::to_string(best.free_parameters) + " free parameters)";
  if (shown)
    if (const ModelVerdict* verdict = report.verdict(shown->key))
      text += "; " + ranges(report, *verdict);
  return text + ".";
}

// Line 2: the calibrated Hunt–Crossley law (constant b), or, when it is the one ranked
// first, the best comparison law.
std::string comparison_line(const Report& report, const RankedModel& best) {
  const ReportModel& calibrated = report.models.front();
  const ReportModel* other = &calibrated;
  if (best.key == calibrated.calibration_key) {
    other = report.model(model_keys::best_law);
    if (!other) return "";
  }
  const ModelVerdict* verdict = report.verdict(other->key);
  if (!verdict) return "";
  const auto [low, high] = error_range(report, *other, Quantity::energy_loss);
  std::string text = other->label + ": " + ranges(report, *verdict) +
                     "; its energy loss is off by " + percent_cell(low) + " to " +
                     percent_cell(high) + ".";
  if (other == &calibrated && report.plastic_laws && !report.family_ranges.empty()) {
    // An elastic-plastic FEM: the family of each velocity range, not one loss trend.
    text += " The FEM follows:";
    for (const auto& range : report.family_ranges)
      text += std::string(&range == &report.family_ranges.front() ? " " : "; ") +
              (range.family.empty() ? "no trend" : range.family) +
              " at V = " + short_number(range.low) +
              (range.high > range.low ? " to " + short_number(range.high) : "") + " m/s" +
              (std::isfinite(range.slope)
                   ? " (" + range.slope_of + " ∝ V^" + three_digits(range.slope) + ")"
                   : "");
    text += ".";
  } else if (other == &calibrated && report.trend) {
    const ReferenceSlope& nearest = nearest_reference(*report.trend);
    text += " The FEM's 1 - e grows as V^" + three_digits(report.trend->exponent) + ", nearest " +
            nearest.family + " (V^" + short_number(nearest.slope) + ")" +
            (nearest.slope == 1.0 ? "." : ", not V^1 as with a constant b.");
  }
  return text;
}

// Line 3: where no model may be trusted, and on what basis the errors were judged.
std::string limits_line(const Report& report) {
  const ReportModel& calibrated = report.models.front();
  std::string text;
  if (report.plasticity.first_yielding_velocity)
    text = "Above " +
           three_digits(report.plasticity.onset_estimate.value_or(
               *report.plasticity.first_yielding_velocity)) +
           " m/s the FEM exceeds the yield strength: no viscoelastic model, reduced or FEM, is "
           "valid there.";
  else if (report.plasticity.plastic_material)
    text = "The FEM's material is elastic-plastic: it stays valid above the yield velocity" +
           (report.plastic_laws
                ? " (V_y = " + three_digits(report.plastic_laws->yield_velocity) + " m/s)"
                : std::string()) +
           ", where the elastic-plastic laws are compared (section Elastic-plastic laws).";
  else if (report.plasticity.recorded)
    text = "The FEM stays below the yield strength at every tested velocity.";
  else
    text = "The runs record no yield strength: plasticity is not checked.";
  text += calibrated.out_of_sample
              ? " Errors out of sample (each velocity predicted by the fit without it), with the "
                "FEM's own uncertainty taken into account."
              : " Errors in sample (the fit to all runs): out-of-sample errors need three "
                "velocities or more.";
  return text;
}

// The symbol, value and unit of every parameter of the recommended model.
struct Parameter {
  std::string name;
  double value;
  std::string unit;
};

// "F = c x^n (1 + b x'), b constant" of "...; restitution k(b V) exact": the law without the
// notes after the first ";".
std::string force_law(const std::string& formula) {
  return formula.substr(0, formula.find(';'));
}

std::string stiffness_unit(double exponent, bool fixed) {
  return fixed ? "N/m^" + short_number(exponent) : "N/m^n";
}

std::string parameter_block(const std::string& heading, const std::string& law,
                            const std::vector<Parameter>& parameters) {
  std::size_t width = 0;
  for (const auto& parameter : parameters) width = std::max(width, parameter.name.size());
  std::string text = heading + "\n  " + law;
  for (const auto& parameter : parameters)
    text += "\n  " + parameter.name + std::string(width - parameter.name.size(), ' ') + " = " +
            cell(parameter.value) + (parameter.unit == "1" ? "" : " " + parameter.unit);
  return text;
}

// The recommended model in a form to copy; "" when the calibration does not hold it.
std::string recommended_block(const Report& report, const RankedModel& best) {
  const CampaignCalibration& campaign = report.calibration->campaign;
  const std::string heading = "Recommended: ";
  if (const CampaignModelFit* fit = campaign.find(best.key)) {
    const ModelFit& parameters = fit->fit;
    const std::vector<std::string> names = parameters.parameter_names();
    const std::vector<double> values = parameters.parameter_values();
    std::vector<std::string> units{stiffness_unit(parameters.exponent.value,
                                                  parameters.exponent_fixed),
                                   "1", parameters.parameter_unit};
    for (const auto& extra : parameters.extra) units.push_back(extra.unit);
    std::vector<Parameter> list;
    for (std::size_t i = 0; i < names.size() && i < values.size() && i < units.size(); ++i)
      list.push_back({names[i], values[i], units[i]});
    return parameter_block(heading + fit->label + " (calibration JSON: campaign, key " + fit->key +
                               (parameters.converged ? "" : "; NOT CONVERGED") + ")",
                           force_law(fit->formula), list);
  }
  for (const auto& reference : campaign.reference_models)
    if (reference.key == best.key) {
      std::vector<Parameter> list{{"c", reference.stiffness,
                                   stiffness_unit(reference.exponent, true)},
                                  {"n", reference.exponent, "1"}};
      if (!reference.dissipation.empty())
        list.push_back(
            {reference.parameter_name, reference.dissipation.front(), reference.parameter_unit});
      for (std::size_t i = 0;
           i < reference.extra_names.size() && i + 1 < reference.dissipation.size(); ++i)
        list.push_back({reference.extra_names[i], reference.dissipation[i + 1],
                        i < reference.extra_units.size() ? reference.extra_units[i] : ""});
      return parameter_block(heading + reference.label + " (nothing fitted: " + reference.basis +
                                 ")",
                             force_law(model_formula(reference.model)), list);
    }
  return "";
}

} // namespace

void glance_section(Document& doc, const Report& report, const FigurePlacer& figure) {
  const bool ranked = report.calibration && !report.calibration->campaign.ranking.empty();
  if (!report.verdict_available || !ranked) {
    doc.list({report.verdict_available ? report.summary : report.cause});
    figure(FigureId::errors, "");
    return;
  }
  const RankedModel& best = report.calibration->campaign.ranking.front();
  std::vector<std::string> lines{recommendation_line(report, best)};
  if (const std::string line = comparison_line(report, best); !line.empty()) lines.push_back(line);
  lines.push_back(limits_line(report));
  if (!report.detail_row.empty())
    lines.front() = report.detail_row + ": " + lines.front() +
                    " Every row of the campaign: the section Validity map.";
  doc.list(lines);
  figure(FigureId::errors, "");
  if (const std::string block = recommended_block(report, best); !block.empty()) doc.code(block);
}

} // namespace impact::postprocess::detail
