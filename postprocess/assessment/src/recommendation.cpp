// The law to recommend (recommendation.hpp, LawRecommendation): every ranked law judged at
// every run by the verdict's rule in the loosest band, the one that holds at the most velocities, the
// Hunt–Crossley form that does (for a multibody code), the velocities where none does, and
// the law and the export that come closest. Numbers only: the sections word them.

#include "steps.hpp"

#include "impact_postprocess/models/model_keys.hpp"

#include <cmath>

namespace impact::postprocess::detail {

namespace {

// The predictions of a calibration entry at each report run: out of sample where it has one
// (`judged`), and of the fit to every velocity (`in_sample`).
struct EntryPredictions {
  std::vector<std::optional<ImpactFigures>> judged, in_sample;
  bool out_of_sample = false;
};

EntryPredictions predictions_at_runs(const Assessment& report,
                                     const std::vector<RunResidual>& runs) {
  EntryPredictions predictions;
  predictions.judged.resize(report.runs.size());
  predictions.in_sample.resize(report.runs.size());
  predictions.out_of_sample = !runs.empty();
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const RunResidual* found = nullptr;
    for (const auto& run : runs)
      if (same_source(run.source, report.runs[i].source)) found = &run;
    if (!found)
      for (const auto& run : runs)
        if (same_velocity(run.velocity, report.runs[i].velocity)) found = &run;
    if (!found) continue;
    const ImpactFigures& figures = found->out_of_sample ? *found->out_of_sample : found->prediction;
    predictions.out_of_sample = predictions.out_of_sample && found->out_of_sample.has_value();
    if (std::isfinite(figures.restitution)) predictions.judged[i] = figures;
    if (std::isfinite(found->prediction.restitution)) predictions.in_sample[i] = found->prediction;
  }
  return predictions;
}

bool hunt_crossley_model(const std::string& model) {
  return model == model_keys::hunt_crossley || model == model_keys::hunt_crossley_velocity_damping;
}

// The entry of `key`: its label, whether it has the Hunt–Crossley form, its predictions and its
// fit (none for a law with nothing fitted); false when the calibration does not hold it.
bool judge_entry(const Assessment& report, const RankedModel& entry, JudgedLaw& law,
                 EntryPredictions& predictions, const CampaignModelFit*& fitted) {
  const CampaignCalibration& campaign = report.calibration->campaign;
  // The page's label, not the role "(best law)" the same law has in the verdict's tables.
  const ReportModel* shown = nullptr;
  for (const auto& model : report.models)
    if (model.calibration_key == entry.key && (!shown || shown->key == model_keys::best_law))
      shown = &model;
  std::string shown_label = shown ? shown->label : "";
  if (shown && shown->key == model_keys::best_law) {
    const std::string role = " (best law)";
    if (shown_label.size() > role.size() &&
        shown_label.compare(shown_label.size() - role.size(), role.size(), role) == 0)
      shown_label.erase(shown_label.size() - role.size());
  }
  if (const CampaignModelFit* fit = campaign.find(entry.key)) {
    law.label = shown ? shown_label : fit->label;
    law.hunt_crossley_form = hunt_crossley_model(fit->fit.model);
    predictions = predictions_at_runs(report, fit->runs);
    law.out_of_sample = predictions.out_of_sample && !fit->held_out.empty();
    fitted = fit;
    return true;
  }
  for (const auto& reference : campaign.reference_models)
    if (reference.key == entry.key) {
      law.label = shown ? shown_label : reference.label;
      if (!shown && report.plastic_laws)
        for (const auto& curve : report.plastic_laws->laws)
          if (curve.key == entry.key) law.label = curve.label;
      law.hunt_crossley_form = hunt_crossley_model(reference.model);
      predictions = predictions_at_runs(report, reference.runs);
      law.out_of_sample = true; // nothing fitted: every run is a prediction
      return true;
    }
  return false;
}

// The fitted parameter of `fit` that moves most, relative to its value in the fit to every
// velocity, in the fit without `velocity`; false without that held-out fit.
bool largest_shift(const CampaignModelFit& fit, double velocity, BreakingRun& breaking) {
  const std::vector<double> values = fit.fit.parameter_values();
  const std::vector<std::string> names = fit.fit.parameter_names();
  std::vector<std::string> units{"N/m^" + short_number(fit.fit.exponent.value), "1",
                                 fit.fit.parameter_unit};
  for (const auto& extra : fit.fit.extra) units.push_back(extra.unit);
  for (const auto& held : fit.held_out) {
    if (!same_velocity(held.velocity, velocity)) continue;
    double largest = -1;
    for (std::size_t k = 0; k < values.size() && k < held.parameters.size(); ++k) {
      const double shift = std::abs(held.parameters[k] - values[k]) / std::abs(values[k]);
      if (!std::isfinite(shift) || shift <= largest) continue;
      largest = shift;
      breaking.parameter = k < names.size() ? names[k] : "";
      breaking.unit = k < units.size() ? units[k] : "";
      breaking.fitted_value = values[k];
      breaking.held_out_value = held.parameters[k];
    }
    return largest >= 0;
  }
  return false;
}

// Why the law is not within the band at run i, by the quantity that keeps it out.
BreakingRun break_at(const Assessment& report, std::size_t i, Quantity quantity, Decision decision,
                     const EntryPredictions& predictions, const CampaignModelFit* fit,
                     double tolerance) {
  BreakingRun breaking{i, quantity, BreakCause::law_shape, 0, 0, 0, fit != nullptr, "", "", 0, 0};
  breaking.error = relative_error(*predictions.judged[i], report.runs[i].fem, quantity);
  breaking.uncertainty = report.runs[i].uncertainty[std::size_t(quantity)].relative;
  breaking.in_sample_error = predictions.in_sample[i] ? relative_error(*predictions.in_sample[i],
                                                                       report.runs[i].fem, quantity)
                                                      : NAN;
  if (decision == Decision::undecided)
    breaking.cause = BreakCause::fem_uncertainty;
  else if (fit && std::abs(breaking.in_sample_error) <= tolerance &&
           largest_shift(*fit, report.runs[i].velocity, breaking))
    breaking.cause = BreakCause::held_out;
  return breaking;
}

// The index of the best law among `laws` that `take` accepts: within at the most runs, the
// better ranked among equals (laws are in rank order); none when none is within anywhere. A
// fit scored in sample is never taken.
std::optional<std::size_t> best_within(const std::vector<JudgedLaw>& laws,
                                       const std::function<bool(const JudgedLaw&)>& take) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < laws.size(); ++k) {
    const JudgedLaw& law = laws[k];
    if (!law.out_of_sample || law.within == 0 || !take(law)) continue;
    if (!best || law.within > laws[*best].within) best = k;
  }
  return best;
}

// The export whose tool, run in its simulator, comes closest to the FEM: the smallest
// largest |error| over the quantities the tools measure.
std::optional<ExportError> closest_export(const Assessment& report) {
  std::optional<ExportError> closest;
  for (std::size_t k = 0; k < report.simulators.size(); ++k) {
    const SimulatorResult& result = report.simulators[k];
    std::optional<ExportError> worst;
    for (const auto& run : result.runs)
      for (Quantity quantity : simulator_judged_quantities) {
        const double error = relative_error(run.tool, run.fem, quantity);
        if (!std::isfinite(error)) continue;
        if (!worst || std::abs(error) > std::abs(worst->worst_error))
          worst = ExportError{k, error, quantity, run.velocity};
      }
    if (worst && (!closest || std::abs(worst->worst_error) < std::abs(closest->worst_error)))
      closest = worst;
  }
  return closest;
}

} // namespace

void add_recommendation(Assessment& report) {
  if (!report.verdict_available || !report.calibration || report.tolerances.empty()) return;
  LawRecommendation recommendation;
  recommendation.tolerance = report.tolerances.back();
  const std::vector<Quantity> quantities(verdict_quantities.begin(), verdict_quantities.end());
  const auto& ranking = report.calibration->campaign.ranking;
  for (std::size_t rank = 0; rank < ranking.size(); ++rank) {
    JudgedLaw law;
    law.key = ranking[rank].key;
    law.rank = rank;
    law.score = ranking[rank].score;
    EntryPredictions predictions;
    const CampaignModelFit* fit = nullptr;
    if (!judge_entry(report, ranking[rank], law, predictions, fit)) continue;
    const auto& judged = predictions.judged;
    const ToleranceVerdict verdict =
        tolerance_verdict(report, judged, recommendation.tolerance, quantities);
    law.decisions = verdict.decisions;
    law.worst_error = 0;
    law.worst_quantity = quantities.front();
    for (std::size_t i = 0; i < report.runs.size(); ++i) {
      if (law.decisions[i] == Decision::within) ++law.within;
      if (!judged[i]) continue;
      double excess = -INFINITY;
      std::optional<Quantity> breaking;
      for (Quantity quantity : quantities) {
        if (law.decisions[i] == Decision::within) break;
        const double error = std::abs(relative_error(*judged[i], report.runs[i].fem, quantity));
        const double u = report.runs[i].uncertainty[std::size_t(quantity)].relative;
        const double margin = std::isfinite(u) ? u : 0.0;
        if (std::isfinite(error) && error + margin > recommendation.tolerance &&
            error - margin > excess) {
          excess = error - margin;
          breaking = quantity;
        }
      }
      if (breaking)
        law.breaks.push_back(break_at(report, i, *breaking, law.decisions[i], predictions, fit,
                                      recommendation.tolerance));
      for (Quantity quantity : quantities) {
        const double error = relative_error(*judged[i], report.runs[i].fem, quantity);
        if (std::isfinite(error) && std::abs(error) > std::abs(law.worst_error)) {
          law.worst_error = error;
          law.worst_quantity = quantity;
          law.worst_run = i;
        }
      }
    }
    recommendation.laws.push_back(std::move(law));
  }
  const auto& laws = recommendation.laws;
  recommendation.recommended = best_within(laws, [](const JudgedLaw&) { return true; });
  recommendation.multibody =
      best_within(laws, [](const JudgedLaw& law) { return law.hunt_crossley_form; });
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    bool covered = false;
    for (const auto& law : laws)
      covered = covered || (law.out_of_sample && law.decisions[i] == Decision::within);
    if (!covered) recommendation.uncovered.push_back(i);
  }
  for (std::size_t k = 0; k < laws.size() && !recommendation.closest; ++k)
    if (laws[k].out_of_sample) recommendation.closest = k;
  if (!recommendation.closest && !laws.empty()) recommendation.closest = 0;
  recommendation.closest_export = closest_export(report);
  report.recommendation = std::move(recommendation);
}

} // namespace impact::postprocess::detail
