// The first screen of the page (sections.hpp): the verdict in three lines, the figure of
// every model's errors against V, and the recommended model with its parameters in a form to
// copy. Everything it states is computed elsewhere (the verdict, the ranking, the trend, the
// yield check); this file only chooses what a reader needs first and says it briefly.

#include "law_block.hpp"
#include "map_words.hpp"
#include "sections.hpp"
#include "impact_postprocess/report/verdict_words.hpp"
#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impact::postprocess::detail {

namespace {

// "within 2 %: 0.5 to 3 m/s; within 5 %: 0.5 to 5 m/s" of one model's verdict.
std::string ranges(const Report& report, const ModelVerdict& verdict) {
  std::string text;
  for (std::size_t k = 0; k < verdict.tolerances.size(); ++k)
    text += (k ? "; within " : "within ") + band_name(verdict.tolerances[k].tolerance) + ": " +
            range_text(verdict.tolerances[k], report);
  return text;
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

} // namespace

// "its largest error is -12.3 % (peak approach x_max at V = 5 m/s)".
std::string largest_error(const Report& report, const JudgedLaw& law) {
  return "its largest error is " + percent_cell(law.worst_error) + " (" +
         quantity_words(law.worst_quantity) + " " + quantity_symbol(law.worst_quantity) +
         " at V = " + short_number(report.runs[law.worst_run].velocity) + " m/s)";
}

std::string law_name(const JudgedLaw& law) {
  // A fit's label that is its key and the data it was fitted to names it by the key alone.
  return law.label.rfind(law.key, 0) == 0 ? law.key : law.label + " (" + law.key + ")";
}

std::string hardening_left_out_by(const Report& report, const JudgedLaw& law) {
  if (!report.plastic_laws) return "";
  for (const auto& curve : report.plastic_laws->laws)
    if (curve.key == law.key) return report.plastic_laws->hardening_left_out;
  return "";
}

namespace {

// Why a law is not within the band at the runs of one group (one quantity, one cause).
std::string cause_words(const Report& report, const JudgedLaw& law,
                        const std::vector<const BreakingRun*>& runs) {
  const BreakingRun& first = *runs.front();
  const std::string band = band_name(report.recommendation->tolerance);
  switch (first.cause) {
    case BreakCause::fem_uncertainty:
      return runs.size() == 1
                 ? "not decided: " + percent_cell(first.error) + " against the FEM's uncertainty " +
                       unsigned_percent(first.uncertainty)
                 : "not decided for the FEM's uncertainty";
    case BreakCause::law_shape: {
      const std::string hardening = hardening_left_out_by(report, law);
      const std::string spring = hardening.empty() ? ""
                                                   : "; the runs' material hardens (" + hardening +
                                                         "), the law's spring does not";
      if (!first.fitted) return "nothing fitted: the law's shape or its constants" + spring;
      return (runs.size() == 1
                  ? "the law's shape: " + percent_cell(first.in_sample_error) +
                        " even in the fit to every velocity"
                  : "the law's shape: beyond " + band + " even in the fit to every velocity") +
             spring;
    }
    case BreakCause::held_out:
      if (runs.size() > 1)
        return "held out: within " + band +
               " in the fit to every velocity, not in the fits without each";
      return "held out: " + percent_cell(first.in_sample_error) +
             " in the fit to every velocity; the fit without " +
             short_number(report.runs[first.run].velocity) + " m/s moves " + first.parameter +
             " from " + significant(first.fitted_value, 4) + " to " +
             significant(first.held_out_value, 4) + (first.unit == "1" ? "" : " " + first.unit);
  }
  return "";
}

} // namespace

std::string breaking_text(const Report& report, const JudgedLaw& law) {
  // Grouped by quantity, in the order of the verdict's quantities, then by cause.
  std::string text;
  for (Quantity quantity : verdict_quantities)
    for (BreakCause cause :
         {BreakCause::law_shape, BreakCause::held_out, BreakCause::fem_uncertainty}) {
      std::vector<const BreakingRun*> runs;
      std::vector<double> at;
      for (const auto& breaking : law.breaks)
        if (breaking.quantity == quantity && breaking.cause == cause) {
          runs.push_back(&breaking);
          at.push_back(report.runs[breaking.run].velocity);
        }
      if (runs.empty()) continue;
      text += std::string(text.empty() ? "" : ", ") + quantity_symbol(quantity) +
              " at V = " + velocity_list(at) + " (" + cause_words(report, law, runs) + ")";
    }
  return text;
}

// The velocities of report runs.
std::vector<double> velocities_of(const Report& report, const std::vector<std::size_t>& runs) {
  std::vector<double> velocities;
  for (std::size_t i : runs) velocities.push_back(report.runs[i].velocity);
  return velocities;
}

std::string where_within(const Report& report, const JudgedLaw& law) {
  if (law.within == report.runs.size() && !report.runs.empty())
    return "over the whole tested range, V = " + short_number(report.runs.front().velocity) +
           " to " + short_number(report.runs.back().velocity) + " m/s";
  // Runs of consecutive velocities within: "0.5 to 1", "3".
  std::vector<std::string> groups;
  for (std::size_t i = 0; i < law.decisions.size();) {
    if (law.decisions[i] != Decision::within) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < law.decisions.size() && law.decisions[j + 1] == Decision::within) ++j;
    groups.push_back(short_number(report.runs[i].velocity) +
                     (j > i ? " to " + short_number(report.runs[j].velocity) : ""));
    i = j + 1;
  }
  std::string text = "at V = ";
  for (std::size_t k = 0; k < groups.size(); ++k)
    text += (k == 0 ? "" : k + 1 == groups.size() ? " and " : ", ") + groups[k];
  return text + " m/s";
}

namespace {

// "ranked first", "ranked 2nd", ... of a 0-based rank.
std::string ordinal_rank(std::size_t rank) {
  const std::size_t n = rank + 1;
  if (n == 1) return "ranked first";
  const char* suffix = (n % 100 >= 11 && n % 100 <= 13) ? "th"
                       : n % 10 == 1                    ? "st"
                       : n % 10 == 2                    ? "nd"
                       : n % 10 == 3                    ? "rd"
                                                        : "th";
  return "ranked " + std::to_string(n) + suffix;
}

// Line 1: the law that holds where it holds (by the verdict's rule in the loosest band), the
// velocities where none does; or that none does anywhere, and the law that comes closest.
std::string recommendation_line(const Report& report) {
  const LawRecommendation& recommendation = *report.recommendation;
  const std::string band = band_name(recommendation.tolerance);
  const std::string basis =
      " (out of sample, with the FEM's uncertainty, in 1 - e^2, t_c, F_max and x_max)";
  if (!recommendation.recommended) {
    std::string text = "No law holds within " + band + " at any tested velocity" + basis + ".";
    if (recommendation.closest) {
      const JudgedLaw& closest = recommendation.laws[*recommendation.closest];
      text += " Closest: " + law_name(closest) + ", ranked first by " +
              (closest.out_of_sample ? "out-of-sample" : "in-sample") + " error (RMS " +
              unsigned_percent(closest.score) + "); " + largest_error(report, closest) +
              "; not within " + band + " by " + breaking_text(report, closest) + ".";
    }
    return text;
  }
  const JudgedLaw& law = recommendation.laws[*recommendation.recommended];
  std::string text = "Use " + law_name(law) + " " + where_within(report, law) + ": within " + band +
                     " there" + basis + "; " + ordinal_rank(law.rank) + " by RMS error (" +
                     unsigned_percent(law.score) + ").";
  // Elsewhere: what keeps it out, which other law holds there, and where none does.
  if (law.within < report.runs.size())
    text += " Not within " + band + " by " + breaking_text(report, law) + ".";
  std::vector<std::size_t> elsewhere;
  for (std::size_t i = 0; i < report.runs.size(); ++i)
    if (law.decisions[i] != Decision::within &&
        std::find(recommendation.uncovered.begin(), recommendation.uncovered.end(), i) ==
            recommendation.uncovered.end())
      elsewhere.push_back(i);
  std::string others;
  for (const auto& other : recommendation.laws) {
    if (elsewhere.empty()) break;
    if (!other.out_of_sample) continue;
    std::vector<std::size_t> at;
    for (std::size_t i : elsewhere)
      if (other.decisions[i] == Decision::within) at.push_back(i);
    if (at.empty()) continue;
    others += (others.empty() ? "" : "; ") + law_name(other) + " at " +
              velocity_list(velocities_of(report, at));
    elsewhere.erase(std::remove_if(elsewhere.begin(), elsewhere.end(),
                                   [&](std::size_t i) {
                                     return std::find(at.begin(), at.end(), i) != at.end();
                                   }),
                    elsewhere.end());
  }
  if (!others.empty()) text += " Within " + band + " there: " + others + ".";
  if (!recommendation.uncovered.empty())
    text += " No law holds within " + band +
            " at V = " + velocity_list(velocities_of(report, recommendation.uncovered)) + ".";
  return text;
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
                   ? " (" + range.slope_of + " ∝ V^" + significant(range.slope, 3) + ")"
                   : "");
    text += ".";
  } else if (other == &calibrated && report.trend) {
    const ReferenceSlope& nearest = nearest_reference(*report.trend);
    text += " The FEM's 1 - e grows as V^" + significant(report.trend->exponent, 3) + ", nearest " +
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
           significant(report.plasticity.onset_estimate.value_or(
                           *report.plasticity.first_yielding_velocity),
                       3) +
           " m/s the FEM exceeds the yield strength: no viscoelastic model, reduced or FEM, is "
           "valid there.";
  else if (report.plasticity.plastic_material)
    text = "The FEM's material is elastic-plastic: it stays valid above the yield velocity" +
           (report.plastic_laws
                ? " (V_y = " + significant(report.plastic_laws->yield_velocity, 3) + " m/s)"
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

// "F = c x^n (1 + b x'), b constant" of "...; restitution k(b V) exact": the law without the
// notes after the first ";".
std::string force_law(const std::string& formula) {
  return formula.substr(0, formula.find(';'));
}

std::string stiffness_unit(double exponent, bool fixed) {
  return fixed ? "N/m^" + short_number(exponent) : "N/m^n";
}

} // namespace

LawBlock law_block(const Report& report, const std::string& key) {
  const CampaignCalibration& campaign = report.calibration->campaign;
  LawBlock block;
  if (const CampaignModelFit* fit = campaign.find(key)) {
    const ModelFit& parameters = fit->fit;
    const std::vector<std::string> names = parameters.parameter_names();
    const std::vector<double> values = parameters.parameter_values();
    std::vector<std::string> units{stiffness_unit(parameters.exponent.value,
                                                  parameters.exponent_fixed),
                                   "1", parameters.parameter_unit};
    for (const auto& extra : parameters.extra) units.push_back(extra.unit);
    for (std::size_t i = 0; i < names.size() && i < values.size() && i < units.size(); ++i)
      block.parameters.push_back({names[i], values[i], units[i]});
    block.name = fit->label + " (calibration JSON: campaign, key " + fit->key +
                 (parameters.converged ? "" : "; NOT CONVERGED") + ")";
    block.law = force_law(fit->formula);
    block.found = true;
    return block;
  }
  for (const auto& reference : campaign.reference_models)
    if (reference.key == key) {
      block.parameters = {{"c", reference.stiffness, stiffness_unit(reference.exponent, true)},
                          {"n", reference.exponent, "1"}};
      if (!reference.dissipation.empty())
        block.parameters.push_back(
            {reference.parameter_name, reference.dissipation.front(), reference.parameter_unit});
      for (std::size_t i = 0;
           i < reference.extra_names.size() && i + 1 < reference.dissipation.size(); ++i)
        block.parameters.push_back(
            {reference.extra_names[i], reference.dissipation[i + 1],
             i < reference.extra_units.size() ? reference.extra_units[i] : ""});
      block.name = reference.label + " (nothing fitted: " + reference.basis + ")";
      block.law = force_law(model_formula(reference.model));
      block.found = true;
      return block;
    }
  return block;
}

std::string law_block_text(const std::string& heading, const LawBlock& block) {
  std::size_t width = 0;
  for (const auto& parameter : block.parameters) width = std::max(width, parameter.name.size());
  std::string text = heading + block.name + "\n  " + block.law;
  for (const auto& parameter : block.parameters)
    text += "\n  " + parameter.name + std::string(width - parameter.name.size(), ' ') + " = " +
            cell(parameter.value) + (parameter.unit == "1" ? "" : " " + parameter.unit);
  return text;
}

namespace {

// The recommended law in a form to copy, headed by where it holds; the closest when none
// holds, headed so; "" when the calibration does not hold it.
std::string recommended_block(const Report& report) {
  const LawRecommendation& recommendation = *report.recommendation;
  const auto chosen =
      recommendation.recommended ? recommendation.recommended : recommendation.closest;
  if (!chosen) return "";
  const JudgedLaw& law = recommendation.laws[*chosen];
  const LawBlock block = law_block(report, law.key);
  if (!block.found) return "";
  const std::string band = band_name(recommendation.tolerance);
  return law_block_text(recommendation.recommended
                            ? "Recommended, within " + band + " " + where_within(report, law) + ": "
                            : "Closest, within " + band + " at no tested velocity: ",
                        block);
}

// One line under the glance for every problem and warning of section Status: the kinds,
// and where the warnings on the FEM runs are, by velocity.
std::string status_line(const Report& report, bool& incomplete) {
  std::vector<std::string> problems;
  std::vector<double> oscillating, energy, other_warnings;
  std::size_t warnings = 0, without_rebound = 0, unplaced = 0;
  const auto add = [](std::vector<double>& list, double velocity) {
    if (std::find(list.begin(), list.end(), velocity) == list.end()) list.push_back(velocity);
  };
  for (const auto& problem : report.problems) {
    if (!is_warning(problem.kind)) {
      problems.push_back(std::string(kind_name(problem.kind)) +
                         (problem.source.empty() ? "" : " (" + problem.source + ")"));
      continue;
    }
    ++warnings;
    if (problem.kind == ProblemKind::quality) continue; // by the runs' findings, below
    const auto run = std::find_if(report.runs.begin(), report.runs.end(), [&](const ReportRun& r) {
      return same_source(r.source, problem.source);
    });
    if (run != report.runs.end())
      add(other_warnings, run->velocity);
    else if (problem.kind == ProblemKind::no_rebound)
      ++without_rebound; // a run the reader could not use: it has no velocity on this page
    else
      ++unplaced;
  }
  for (const auto& run : report.runs) {
    if (run.quality.oscillation || run.quality.after_release) add(oscillating, run.velocity);
    if (run.quality.energy_balance) add(energy, run.velocity);
  }
  incomplete = !problems.empty();
  if (problems.empty() && warnings == 0) return "";
  std::string text;
  if (incomplete) {
    text = "INCOMPLETE: " + std::to_string(problems.size()) + " problem(s): ";
    for (std::size_t i = 0; i < problems.size() && i < 3; ++i)
      text += (i ? "; " : "") + problems[i];
    if (problems.size() > 3) text += "; ...";
    text += ".";
  }
  if (warnings > 0) {
    std::vector<std::string> parts;
    const auto sorted = [](std::vector<double> list) {
      std::sort(list.begin(), list.end());
      return list;
    };
    if (!oscillating.empty())
      parts.push_back("the FEM's force oscillates (or chatters at release) at V = " +
                      velocity_list(sorted(oscillating)));
    if (!energy.empty())
      parts.push_back("its energy balance misses the " + unsigned_percent(energy_balance_target) +
                      " target at V = " + velocity_list(sorted(energy)));
    if (!other_warnings.empty())
      parts.push_back("other findings at V = " + velocity_list(sorted(other_warnings)));
    if (without_rebound > 0)
      parts.push_back("no rebound in " + std::to_string(without_rebound) +
                      " run(s), which the verdict cannot judge");
    if (unplaced > 0) parts.push_back(std::to_string(unplaced) + " other finding(s)");
    text += std::string(text.empty() ? "" : " ") + "Warnings: ";
    for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? "; " : "") + parts[i];
    text += ".";
  }
  return text + " Section Status lists them.";
}

} // namespace

void glance_section(Document& doc, const Report& report, const FigurePlacer& figure) {
  bool incomplete = false;
  const std::string status = status_line(report, incomplete);
  const auto place_status = [&] {
    if (status.empty()) return;
    if (incomplete)
      doc.warning(status);
    else
      doc.paragraph(status);
  };
  const bool ranked = report.calibration && !report.calibration->campaign.ranking.empty();
  if (!report.verdict_available || !ranked || !report.recommendation) {
    doc.list({report.verdict_available ? summary_sentence(report) : cause_sentence(report)});
    place_status();
    figure(FigureId::errors, "");
    return;
  }
  const RankedModel& best = report.calibration->campaign.ranking.front();
  std::vector<std::string> lines{recommendation_line(report)};
  if (const std::string line = comparison_line(report, best); !line.empty()) lines.push_back(line);
  lines.push_back(limits_line(report));
  if (report.detail_row)
    lines.front() = detail_row_name(*report.detail_row) + ": " + lines.front() +
                    " Every row of the campaign: the section Validity map.";
  doc.list(lines);
  place_status();
  figure(FigureId::errors, "");
  if (const std::string block = recommended_block(report); !block.empty()) doc.code(block);
}

} // namespace impact::postprocess::detail
