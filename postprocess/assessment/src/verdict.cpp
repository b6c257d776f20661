// The verdict (verdict.hpp): per model, run and tolerance a decision that takes the FEM's
// numerical uncertainty into account; the cause of the calibrated model's failure; the
// velocity trends of the energy loss and of the per-run b; the plasticity check. Numbers and
// decisions: the report words them (report/src/verdict_words.cpp).

#include "steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

} // namespace

// Within when |error| + U <= tolerance for every quantity judged, outside when
// |error| - U > tolerance for one, not decided in between (U: the FEM's uncertainty of the
// quantity, 0 where it is not known), unknown without a prediction.
Decision decide(const std::optional<ImpactFigures>& judged, const ReportRun& run, double tolerance,
                const std::vector<Quantity>& quantities) {
  if (!judged) return Decision::unknown;
  bool undecided = false;
  for (Quantity quantity : quantities) {
    const double error = std::abs(relative_error(*judged, run.fem, quantity));
    if (!std::isfinite(error)) return Decision::unknown;
    const double uncertainty = run.uncertainty[std::size_t(quantity)].relative;
    const double u = std::isfinite(uncertainty) ? uncertainty : 0.0;
    if (error - u > tolerance) return Decision::outside;
    if (error + u > tolerance) undecided = true;
  }
  return undecided ? Decision::undecided : Decision::within;
}

ToleranceVerdict tolerance_verdict(const Assessment& report,
                                   const std::vector<std::optional<ImpactFigures>>& judged,
                                   double tolerance, const std::vector<Quantity>& quantities) {
  ToleranceVerdict verdict{tolerance, {}, std::nullopt, 0};
  const std::size_t count = report.runs.size();
  for (std::size_t i = 0; i < count; ++i)
    verdict.decisions.push_back(decide(judged[i], report.runs[i], tolerance, quantities));
  std::size_t best_begin = 0, best_length = 0;
  for (std::size_t i = 0; i < count;) {
    if (verdict.decisions[i] != Decision::within) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < count && verdict.decisions[j] == Decision::within) ++j;
    if (j - i > best_length) {
      best_begin = i;
      best_length = j - i;
    }
    i = j;
  }
  if (best_length > 0) {
    verdict.range = std::array<double, 2>{report.runs[best_begin].velocity,
                                          report.runs[best_begin + best_length - 1].velocity};
    verdict.range_runs = best_length;
  }
  return verdict;
}

namespace {

ToleranceVerdict model_verdict(const Assessment& report, const ReportModel& model,
                               double tolerance) {
  std::vector<std::optional<ImpactFigures>> judged;
  for (const auto& at : model.runs) judged.push_back(at.judged());
  return tolerance_verdict(report, judged, tolerance,
                           {verdict_quantities.begin(), verdict_quantities.end()});
}

// The smallest and largest signed error of the model's energy loss over the runs.
std::array<double, 2> energy_loss_errors(const Assessment& report, const ReportModel& model) {
  double low = INFINITY, high = -INFINITY;
  for (std::size_t i = 0; i < report.runs.size(); ++i)
    if (const auto& judged = model.runs[i].judged()) {
      const double error = relative_error(*judged, report.runs[i].fem, Quantity::energy_loss);
      low = std::min(low, error);
      high = std::max(high, error);
    }
  return {low, high};
}

// The quantity with the fewest velocities inside the tightest band breaks first.
FailureCause cause_of(const Assessment& report, const ReportModel& model) {
  const std::size_t count = report.runs.size();
  FailureCause cause;
  cause.tolerance = report.tolerances.front();
  cause.worst_quantity = cause.first_breaking = verdict_quantities[0];
  const auto error = [&](std::size_t i, Quantity quantity) {
    const auto& judged = model.runs[i].judged();
    return judged ? relative_error(*judged, report.runs[i].fem, quantity) : nan;
  };
  double worst = 0;
  for (std::size_t i = 0; i < count; ++i)
    for (Quantity quantity : verdict_quantities)
      if (std::isfinite(error(i, quantity)) && std::abs(error(i, quantity)) > worst) {
        worst = std::abs(error(i, quantity));
        cause.worst_run = i;
        cause.worst_quantity = quantity;
      }
  cause.worst_error = error(cause.worst_run, cause.worst_quantity);
  cause.holds = worst <= cause.tolerance;
  if (cause.holds) return cause;
  int fewest = int(count) + 1;
  double first_worst = 0;
  for (Quantity quantity : verdict_quantities) {
    int inside = 0;
    double largest = 0;
    for (std::size_t i = 0; i < count; ++i)
      if (std::isfinite(error(i, quantity))) {
        if (std::abs(error(i, quantity)) <= cause.tolerance) ++inside;
        largest = std::max(largest, std::abs(error(i, quantity)));
      }
    if (inside < fewest || (inside == fewest && largest > first_worst)) {
      cause.first_breaking = quantity;
      fewest = inside;
      first_worst = largest;
    }
  }
  cause.first_breaking_within = std::size_t(fewest);
  for (std::size_t i = 0; i < count; ++i)
    cause.first_breaking_errors.push_back(error(i, cause.first_breaking));
  return cause;
}

// How the per-run b (from the restitution) varies with V: least-squares line.
std::optional<DampingTrend> damping_trend(const std::vector<ReportRun>& runs) {
  std::vector<double> v, b;
  for (const auto& run : runs)
    if (std::isfinite(run.damping_from_restitution)) {
      v.push_back(run.velocity);
      b.push_back(run.damping_from_restitution);
    }
  if (v.size() < 2) return std::nullopt;
  const double n = double(v.size());
  double mv = 0, mb = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    mv += v[i] / n;
    mb += b[i] / n;
  }
  double svv = 0, svb = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    svv += (v[i] - mv) * (v[i] - mv);
    svb += (v[i] - mv) * (b[i] - mb);
  }
  if (!(svv > 0) || !(mb > 0)) return std::nullopt;
  const double slope = svb / svv;
  const auto [low, high] = std::minmax_element(b.begin(), b.end());
  DampingTrend trend{
      v.front(), v.back(), b.front(), b.back(), *low, *high, slope * (v.back() - v.front()) / mb};
  trend.constant = std::abs(trend.change) <= 0.02 && (*high - *low) <= 0.04 * mb;
  return trend;
}

// An elastic-plastic FEM: where it yields, by its own record (it stays valid there).
PlasticityCheck plastic_material_check(const std::vector<ReportRun>& runs) {
  PlasticityCheck check;
  check.plastic_material = true;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ReportRun& run = runs[i];
    check.recorded = check.recorded || (run.record.yield_strength && run.record.max_von_mises);
    if (!check.first_yielding_run && run.record.yields.value_or(false))
      check.first_yielding_run = i;
  }
  return check;
}

PlasticityCheck plasticity_check(const std::vector<ReportRun>& runs) {
  PlasticityCheck check;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ReportRun& run = runs[i];
    if (!run.record.yield_strength || !run.record.max_von_mises) continue;
    check.recorded = true;
    if (run.yields) {
      if (!check.first_yielding_run) check.first_yielding_run = i;
    } else if (!check.first_yielding_run) {
      check.last_elastic_run = i;
    }
  }
  if (!check.first_yielding_run) return check;
  const ReportRun& first_yielding = runs[*check.first_yielding_run];
  check.first_yielding_velocity = first_yielding.velocity;
  const double yield = *first_yielding.record.yield_strength;
  const double stress = *first_yielding.record.max_von_mises;
  if (check.last_elastic_run) {
    // log-log interpolation of the peak stress between the two runs.
    const ReportRun& last_elastic = runs[*check.last_elastic_run];
    const double s1 = std::log(*last_elastic.record.max_von_mises), s2 = std::log(stress);
    const double v1 = std::log(last_elastic.velocity), v2 = std::log(first_yielding.velocity);
    check.onset_estimate = std::exp(v1 + (std::log(yield) - s1) * (v2 - v1) / (s2 - s1));
  } else {
    // Hertz: the peak pressure, and with it the von Mises stress, grows as V^(2/5).
    check.onset_estimate = first_yielding.velocity * std::pow(yield / stress, 2.5);
  }
  return check;
}

} // namespace

void add_verdict(Assessment& report) {
  const std::size_t count = report.runs.size();
  if (count == 0) return;
  std::vector<double> velocities, restitutions;
  for (const auto& run : report.runs) {
    velocities.push_back(run.velocity);
    restitutions.push_back(run.fem.restitution);
  }
  const double level = report.calibration ? report.calibration->confidence_level : 0.95;
  report.trend = fit_restitution_trend(velocities, restitutions, level);
  const bool plastic_material =
      std::any_of(report.runs.begin(), report.runs.end(),
                  [](const ReportRun& run) { return run.record.plastic_material; });
  report.plasticity =
      plastic_material ? plastic_material_check(report.runs) : plasticity_check(report.runs);
  const std::optional<double> yield_velocity =
      report.plastic_laws ? std::optional<double>(report.plastic_laws->yield_velocity)
                          : std::nullopt;
  // The plastic family's reference over the tested range: the laws from the material (the
  // fitted ones are fits to this FEM).
  std::vector<PlasticReference> plastic_references;
  if (report.plastic_laws)
    for (const auto& law : report.plastic_laws->laws)
      if (!law.fitted && !law.damped)
        plastic_references.push_back({law.label, law.run_restitution});
  report.family_ranges =
      family_ranges(velocities, restitutions, yield_velocity, level, plastic_references);
  report.effective_alpha = effective_alpha(report.runs);

  for (const auto& model : report.models) {
    ModelVerdict verdict{model.key, model.out_of_sample, {}};
    for (double tolerance : report.tolerances)
      verdict.tolerances.push_back(model_verdict(report, model, tolerance));
    report.verdicts.push_back(std::move(verdict));
  }
  report.damping_trend = damping_trend(report.runs);

  const ReportModel& calibrated = report.models.front();
  if (!report.campaign_fitted) {
    report.no_verdict = report.calibration ? NoVerdict{NoVerdict::Kind::not_fitted,
                                                       report.calibration->campaign.reason}
                                           : NoVerdict{NoVerdict::Kind::no_calibration, ""};
    return;
  }
  if (!calibrated.converged) {
    report.no_verdict = NoVerdict{NoVerdict::Kind::not_converged, ""};
    return;
  }
  report.verdict_available = true;
  report.cause = cause_of(report, calibrated);
  report.energy_loss_errors = energy_loss_errors(report, calibrated);
}

} // namespace impact::postprocess::detail
