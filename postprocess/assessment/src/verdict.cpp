// The verdict of the report (verdict.hpp): per model, run and tolerance a decision that takes
// the FEM's numerical uncertainty into account; the ranges in words; the cause of the
// calibrated model's failure; the velocity trend of the energy loss; the plasticity check;
// and the notes on the calibrated parameters (offsets from Hertz, trend of the per-run b).

#include "steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impact::postprocess::detail {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

} // namespace

std::string band_name(double tolerance) {
  return short_number(tolerance * 100) + " %";
}

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
                                   double tolerance, const std::vector<Quantity>& quantities,
                                   const std::string& basis) {
  ToleranceVerdict verdict{tolerance, {}, std::nullopt, {}};
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
  std::vector<double> outside, undecided, unknown;
  for (std::size_t i = 0; i < count; ++i) {
    if (verdict.decisions[i] == Decision::outside) outside.push_back(report.runs[i].velocity);
    if (verdict.decisions[i] == Decision::undecided) undecided.push_back(report.runs[i].velocity);
    if (verdict.decisions[i] == Decision::unknown) unknown.push_back(report.runs[i].velocity);
  }
  const std::string band = band_name(tolerance);
  std::string text;
  if (best_length == 0) {
    text = "Within " + band + ": at no tested velocity" + basis + ".";
  } else {
    const double low = report.runs[best_begin].velocity;
    const double high = report.runs[best_begin + best_length - 1].velocity;
    verdict.range = std::array<double, 2>{low, high};
    text = "Within " + band + ": " + (best_length == count ? "over the whole tested range, " : "") +
           "V = " +
           (low == high ? short_number(low) : short_number(low) + " to " + short_number(high)) +
           " m/s" + basis + " (" + std::to_string(best_length) + " of " + std::to_string(count) +
           " tested velocities).";
  }
  if (!outside.empty())
    text += " Outside " + band + " at V = " + velocity_list(outside) +
            (best_length > 0 ? "; the limits lie between the last tested velocity inside and the "
                               "first outside."
                             : ".");
  if (!undecided.empty())
    text += " Not decided at V = " + velocity_list(undecided) +
            ": the FEM's numerical uncertainty is as large as the margin to the band.";
  if (!unknown.empty())
    text += " Not decided at V = " + velocity_list(unknown) + " (prediction missing).";
  std::vector<double> yielding;
  for (std::size_t i = 0; i < count; ++i)
    if (verdict.decisions[i] == Decision::within && report.runs[i].yields)
      yielding.push_back(report.runs[i].velocity);
  if (!yielding.empty())
    text += " At V = " + velocity_list(yielding) +
            " the FEM exceeds the yield strength: the agreement is with a viscoelastic model "
            "that is itself not valid there.";
  verdict.text = text;
  return verdict;
}

namespace {

ToleranceVerdict model_verdict(const Assessment& report, const ReportModel& model,
                               double tolerance) {
  std::vector<std::optional<ImpactFigures>> judged;
  for (const auto& at : model.runs) judged.push_back(at.judged());
  return tolerance_verdict(report, judged, tolerance,
                           {verdict_quantities.begin(), verdict_quantities.end()},
                           model.out_of_sample ? " (out of sample)" : " (in sample)");
}

// "within 5 % at V = ..." of one model, for the summary.
std::string range_words(const Assessment& report, const ModelVerdict& verdict) {
  const ToleranceVerdict& loose = verdict.tolerances.back();
  std::vector<double> within, undecided;
  for (std::size_t i = 0; i < loose.decisions.size(); ++i) {
    if (loose.decisions[i] == Decision::within) within.push_back(report.runs[i].velocity);
    if (loose.decisions[i] == Decision::undecided) undecided.push_back(report.runs[i].velocity);
  }
  std::string text =
      "within " + band_name(loose.tolerance) + " " +
      (within.empty() ? std::string("at no tested velocity") : "at V = " + velocity_list(within));
  if (!undecided.empty()) text += ", not decided at V = " + velocity_list(undecided);
  return text;
}

std::string summary_of(const Assessment& report) {
  const ReportModel& calibrated = report.models.front();
  const ModelVerdict* verdict = report.verdict(calibrated.key);
  if (!verdict) return "";
  double low = INFINITY, high = -INFINITY;
  for (std::size_t i = 0; i < report.runs.size(); ++i)
    if (const auto& judged = calibrated.runs[i].judged()) {
      const double error = relative_error(*judged, report.runs[i].fem, Quantity::energy_loss);
      low = std::min(low, error);
      high = std::max(high, error);
    }
  std::string text = "Summary: the calibrated Hunt–Crossley model (constant b) is " +
                     range_words(report, *verdict) + " (" +
                     (calibrated.out_of_sample ? "out of sample" : "in sample") +
                     "); its energy loss is off by " + percent_cell(low) + " to " +
                     percent_cell(high) + ".";
  const auto& ranking = report.calibration->campaign.ranking;
  if (!ranking.empty()) {
    const RankedModel& best = ranking.front();
    const ReportModel* shown = nullptr;
    for (const auto& model : report.models)
      if (model.calibration_key == best.key) shown = &model;
    text += " Ranked first by " + std::string(best.out_of_sample ? "out-of-sample" : "in-sample") +
            " error: " + (shown ? shown->label : best.key) + " (" +
            std::to_string(best.free_parameters) + " free parameters, RMS error " +
            unsigned_percent(best.score) + ")";
    if (shown && report.verdict(shown->key))
      text += ", " + range_words(report, *report.verdict(shown->key));
    text += ".";
  }
  bool undecided = false;
  for (const auto& entry : report.verdicts)
    for (const auto& band : entry.tolerances)
      for (Decision decision : band.decisions)
        undecided = undecided || decision == Decision::undecided;
  bool all_verified = !report.runs.empty();
  for (const auto& run : report.runs) all_verified = all_verified && run.record.verification;
  if (undecided)
    text += all_verified
                ? " Where a velocity is not decided, the FEM's numerical uncertainty (the grid "
                  "convergence index of its verification) is as large as the margin: a finer "
                  "FEM is needed to decide."
                : " Where a velocity is not decided, the FEM's own numerical uncertainty (its "
                  "force oscillation, its time step) is as large as the margin: a cleaner or "
                  "verified FEM is needed to decide.";
  if (report.trend && !report.plastic_laws) {
    const ReferenceSlope& nearest = nearest_reference(*report.trend);
    text += " The FEM's 1 - e grows as V^" + short_number(report.trend->exponent, 3) + " [" +
            short_number(report.trend->lower, 3) + ", " + short_number(report.trend->upper, 3) +
            "]: the nearest reference family is " + nearest.family + " (V^" +
            short_number(nearest.slope, 3) + ")" +
            (nearest.slope == 1.0 ? "." : ", not Hunt–Crossley with a constant b (V^1).");
  }
  if (report.plastic_laws) text += " " + report.family_text;
  if (report.plasticity.first_yielding_velocity)
    text += " Above " +
            short_number(report.plasticity.onset_estimate.value_or(
                             *report.plasticity.first_yielding_velocity),
                         3) +
            " m/s the FEM exceeds the yield strength: there no viscoelastic model, reduced or "
            "FEM, is valid.";
  return text;
}

// The quantity with the fewest velocities inside the tightest band breaks first.
std::string cause_of(const Assessment& report, const ReportModel& model) {
  const std::size_t count = report.runs.size();
  const double tight = report.tolerances.front();
  const std::string basis = model.out_of_sample ? "out of sample" : "in sample";
  std::ostringstream cause;
  double worst = 0;
  std::size_t worst_run = 0;
  Quantity worst_quantity = verdict_quantities[0];
  const auto error = [&](std::size_t i, Quantity quantity) {
    const auto& judged = model.runs[i].judged();
    return judged ? relative_error(*judged, report.runs[i].fem, quantity) : nan;
  };
  for (std::size_t i = 0; i < count; ++i)
    for (Quantity quantity : verdict_quantities)
      if (std::isfinite(error(i, quantity)) && std::abs(error(i, quantity)) > worst) {
        worst = std::abs(error(i, quantity));
        worst_run = i;
        worst_quantity = quantity;
      }
  if (worst <= tight) {
    cause << "The calibrated Hunt–Crossley model holds within " << band_name(tight)
          << " at every tested velocity (" << basis << "); the largest error is "
          << percent_cell(error(worst_run, worst_quantity)) << " ("
          << quantity_words(worst_quantity)
          << " at V = " << short_number(report.runs[worst_run].velocity) << " m/s).";
    return cause.str();
  }
  Quantity first = verdict_quantities[0];
  int fewest = int(count) + 1;
  double first_worst = 0;
  for (Quantity quantity : verdict_quantities) {
    int inside = 0;
    double largest = 0;
    for (std::size_t i = 0; i < count; ++i)
      if (std::isfinite(error(i, quantity))) {
        if (std::abs(error(i, quantity)) <= tight) ++inside;
        largest = std::max(largest, std::abs(error(i, quantity)));
      }
    if (inside < fewest || (inside == fewest && largest > first_worst)) {
      first = quantity;
      fewest = inside;
      first_worst = largest;
    }
  }
  cause << "The " << quantity_words(first) << " (" << quantity_symbol(first)
        << ") breaks first: " << basis << " it is within " << band_name(tight) << " at " << fewest
        << " of " << count << " velocities, with errors";
  for (std::size_t i = 0; i < count; ++i)
    cause << (i ? "," : "") << " " << percent_cell(error(i, first)) << " at "
          << short_number(report.runs[i].velocity) << " m/s";
  cause << ". The largest error of all is " << percent_cell(error(worst_run, worst_quantity))
        << " (" << quantity_words(worst_quantity)
        << " at V = " << short_number(report.runs[worst_run].velocity) << " m/s).";
  const bool low_end = worst_run == 0, high_end = worst_run + 1 == count;
  if (low_end || high_end)
    cause << " The errors grow towards the " << (low_end ? "lowest" : "highest")
          << " tested velocity.";
  return cause.str();
}

// How the per-run b (from the restitution) varies with V: least-squares line.
std::string damping_trend(const std::vector<ReportRun>& runs) {
  std::vector<double> v, b;
  for (const auto& run : runs)
    if (std::isfinite(run.damping_from_restitution)) {
      v.push_back(run.velocity);
      b.push_back(run.damping_from_restitution);
    }
  if (v.size() < 2) return "";
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
  if (!(svv > 0) || !(mb > 0)) return "";
  const double slope = svb / svv;
  const double change = slope * (v.back() - v.front()) / mb;
  const auto [low, high] = std::minmax_element(b.begin(), b.end());
  std::ostringstream text;
  text << "Per-run b from the restitution: " << short_number(b.front()) << " s/m at "
       << short_number(v.front()) << " m/s to " << short_number(b.back()) << " s/m at "
       << short_number(v.back()) << " m/s (range " << short_number(*low) << " to "
       << short_number(*high) << " s/m); the least-squares line changes by " << percent_cell(change)
       << " of the mean over the tested range. ";
  if (std::abs(change) <= 0.02 && (*high - *low) <= 0.04 * mb)
    text << "b is constant within 2 %: the dissipation has the velocity dependence of "
            "Hunt–Crossley (constant b).";
  else
    text << "b " << (change > 0 ? "rises" : "falls")
         << " with V: one constant b cannot give the FEM restitution at every velocity, so the "
            "FEM dissipation is not of Hunt–Crossley's form over this range"
         << (change > 0 ? ""
                        : " (a falling b means e decreases more slowly with V than "
                          "Hunt–Crossley predicts)")
         << ".";
  return text.str();
}

// Offsets from Hertz of the calibrated elastic part: n from the free fit, c from the fit with
// n held at 3/2 (the free fit's c is in N/m^n, not comparable with c_Hertz).
std::string hertz_offsets(const Assessment& report) {
  const CampaignCalibration& campaign = report.calibration->campaign;
  const ModelFit& hc = campaign.hunt_crossley->fit;
  const auto not_converged = [](const ModelFit& fit) {
    return fit.converged ? std::string() : std::string(" (not converged)");
  };
  const double c = hc.stiffness.value, n = hc.exponent.value, hertz = report.hertz_stiffness;
  std::string note =
      "Offsets of the calibrated elastic part from Hertz (c_Hertz = " + short_number(hertz, 5) +
      " N/m^1.5): n - 3/2 = " + (n >= 1.5 ? "+" : "") + short_number(n - 1.5, 3) +
      " (free fit of c, n, b: n = " + short_number(n, 6) + not_converged(hc) + ")";
  if (campaign.hunt_crossley_hertz_exponent) {
    const ModelFit& fixed = campaign.hunt_crossley_hertz_exponent->fit;
    const double c_fixed = fixed.stiffness.value;
    note += "; c / c_Hertz - 1 = " + percent_cell(c_fixed / hertz - 1) +
            " (fit with n fixed at 3/2, c and b free: c = " + short_number(c_fixed, 6) +
            " N/m^1.5" + not_converged(fixed) +
            "); for information, the free fit's c / c_Hertz - 1 = " + percent_cell(c / hertz - 1) +
            " (c = " + short_number(c, 6) +
            " N/m^n at the fitted n: its unit depends on n, so it is not comparable with "
            "c_Hertz).";
  } else {
    note += "; the free fit's c / c_Hertz - 1 = " + percent_cell(c / hertz - 1) +
            " (c = " + short_number(c, 6) +
            " N/m^n: its unit depends on n, so this offset means most when n is close to 3/2; "
            "the calibration has no fit with n fixed at 3/2).";
  }
  return note;
}

// An elastic-plastic FEM: where it yields, and that it stays valid there.
PlasticityCheck plastic_material_check(const std::vector<ReportRun>& runs,
                                       const std::optional<PlasticLaws>& laws) {
  PlasticityCheck check;
  check.plastic_material = true;
  const ReportRun* first_yielding = nullptr;
  for (const auto& run : runs) {
    check.recorded = check.recorded || (run.record.yield_strength && run.record.max_von_mises);
    if (!first_yielding && run.record.yields.value_or(false)) first_yielding = &run;
  }
  std::string text =
      "The FEM's material is elastic-plastic (a body with 'Material model = "
      "elastic-plastic', J2 plasticity): the FEM itself yields";
  if (first_yielding)
    text += " (from V = " + short_number(first_yielding->velocity) + " m/s on, by its own record)";
  if (laws)
    text += "; the material's yield velocity is V_y = " + short_number(laws->yield_velocity, 4) +
            " m/s (Johnson's p_y = 1.6 Y; " + short_number(laws->jackson_green_yield_velocity, 4) +
            " m/s with Jackson–Green's p_y = C(nu) Y)";
  text +=
      ". It stays valid above yield, so no velocity is flagged: there the viscoelastic "
      "laws are compared with a plastic FEM, and the elastic-plastic laws (Thornton, "
      "Jackson–Green; section Elastic-plastic laws) are the ones built for it.";
  check.text = text;
  return check;
}

PlasticityCheck plasticity_check(const std::vector<ReportRun>& runs) {
  PlasticityCheck check;
  const ReportRun* last_elastic = nullptr;
  const ReportRun* first_yielding = nullptr;
  for (const auto& run : runs) {
    if (!run.record.yield_strength || !run.record.max_von_mises) continue;
    check.recorded = true;
    if (run.yields) {
      if (!first_yielding) first_yielding = &run;
    } else if (!first_yielding) {
      last_elastic = &run;
    }
  }
  if (!check.recorded) {
    check.text =
        "No yield strength is recorded with the stresses (Sphere/Yield strength, "
        "Plate/Yield strength of impact-fem): whether the viscoelastic model itself "
        "holds (no plasticity) is not checked.";
    return check;
  }
  if (!first_yielding) {
    check.text =
        "The FEM stays below the yield strength at every tested velocity (largest von "
        "Mises stress " +
        short_number(runs.back().record.max_von_mises.value_or(nan) / 1e9, 3) + " GPa against " +
        short_number(runs.back().record.yield_strength.value_or(nan) / 1e9, 3) +
        " GPa): the viscoelastic model holds over the whole range.";
    return check;
  }
  check.first_yielding_velocity = first_yielding->velocity;
  const double yield = *first_yielding->record.yield_strength;
  const double stress = *first_yielding->record.max_von_mises;
  std::string onset;
  if (last_elastic) {
    // log-log interpolation of the peak stress between the two runs.
    const double s1 = std::log(*last_elastic->record.max_von_mises), s2 = std::log(stress);
    const double v1 = std::log(last_elastic->velocity), v2 = std::log(first_yielding->velocity);
    check.onset_estimate = std::exp(v1 + (std::log(yield) - s1) * (v2 - v1) / (s2 - s1));
    onset = "; the onset lies near " + short_number(*check.onset_estimate, 3) +
            " m/s (log-log interpolation of the peak stress between " +
            short_number(last_elastic->velocity) + " and " +
            short_number(first_yielding->velocity) + " m/s)";
  } else {
    // Hertz: the peak pressure, and with it the von Mises stress, grows as V^(2/5).
    check.onset_estimate = first_yielding->velocity * std::pow(yield / stress, 2.5);
    onset =
        "; every tested velocity yields, and by the Hertz scaling of the stress "
        "(sigma ~ V^(2/5)) the onset lies near " +
        short_number(*check.onset_estimate, 3) + " m/s";
  }
  check.text =
      "The FEM exceeds the yield strength (" + short_number(yield / 1e9, 3) + " GPa, " +
      first_yielding->record.yield_source + ") from V = " + short_number(first_yielding->velocity) +
      " m/s on (peak von Mises stress " + short_number(stress / 1e9, 3) + " GPa there" + onset +
      "): from there on the bodies would yield and the viscoelastic model itself is "
      "not valid, so no reduced model may be trusted there whatever its agreement with "
      "this FEM. Those velocities are marked (yields) in every table.";
  return check;
}

std::string uncertainty_summary(const std::vector<ReportRun>& runs) {
  bool verified = false, unverified = false;
  double oscillation_low = INFINITY, oscillation_high = 0;
  for (const auto& run : runs) {
    (run.record.verification ? verified : unverified) = true;
    const double oscillation = run.record.smoothness.oscillation;
    if (std::isfinite(oscillation)) {
      oscillation_low = std::min(oscillation_low, oscillation);
      oscillation_high = std::max(oscillation_high, oscillation);
    }
  }
  std::string text =
      "The FEM's numerical uncertainty enters every decision: a velocity is "
      "within a band only if each error plus the FEM's uncertainty of that "
      "quantity is, outside only if an error minus it is beyond the band, and "
      "not decided otherwise. ";
  if (verified)
    text += "Verified runs (verification.json) use the grid convergence index of each quantity. ";
  if (unverified) {
    text += std::string(verified ? "The other runs have" : "The runs have") +
            " no verification, so the uncertainty is what the history shows: the peak force "
            "that of the step-to-step oscillation of the force (" +
            (std::isfinite(oscillation_low)
                 ? unsigned_percent(oscillation_low) + " to " + unsigned_percent(oscillation_high)
                 : std::string("n/a")) +
            " of the peak), the contact time one time step or the release chatter; the energy "
            "loss and the peak approach have no estimate and count as exact, which the verdict "
            "cannot check.";
  }
  return text;
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
  report.trend =
      fit_restitution_trend(velocities, restitutions,
                            report.calibration ? report.calibration->confidence_level : 0.95);
  if (report.trend)
    report.trend_text =
        "Velocity trend of the FEM's energy loss: 1 - e ∝ V^p with p = " +
        short_number(report.trend->exponent, 3) + " [" + short_number(report.trend->lower, 3) +
        ", " + short_number(report.trend->upper, 3) + "] (" +
        short_number(report.trend->level * 100, 3) + " % interval, " +
        std::to_string(report.trend->points) + " runs): " + trend_family(*report.trend) + "." +
        (report.plastic_laws ? " For an elastic-plastic FEM this one slope over every run mixes "
                               "the elastic and the plastic range; the family ranges (\"Which "
                               "family the FEM follows\") say which family holds where."
                             : "");
  else
    report.trend_text =
        "Velocity trend of the FEM's energy loss: not fitted (it needs three "
        "runs with 0 < e < 1 at two or more velocities).";
  const bool plastic_material =
      std::any_of(report.runs.begin(), report.runs.end(),
                  [](const ReportRun& run) { return run.record.plastic_material; });
  report.plasticity = plastic_material ? plastic_material_check(report.runs, report.plastic_laws)
                                       : plasticity_check(report.runs);
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
      family_ranges(velocities, restitutions, yield_velocity,
                    report.calibration ? report.calibration->confidence_level : 0.95,
                    plastic_references);
  report.family_text = family_ranges_text(report.family_ranges, yield_velocity);
  report.alpha_text = effective_alpha_text(report.runs);
  report.uncertainty_text = uncertainty_summary(report.runs);

  for (const auto& model : report.models) {
    ModelVerdict verdict{model.key, model.out_of_sample, {}};
    for (double tolerance : report.tolerances)
      verdict.tolerances.push_back(model_verdict(report, model, tolerance));
    report.verdicts.push_back(std::move(verdict));
  }

  if (report.calibration && report.campaign_fitted && report.calibration->campaign.hunt_crossley)
    report.parameter_notes.push_back(hertz_offsets(report));
  const std::string trend = damping_trend(report.runs);
  if (!trend.empty()) report.parameter_notes.push_back(trend);

  const ReportModel& calibrated = report.models.front();
  if (!report.campaign_fitted) {
    report.cause = "No verdict: " +
                   (report.campaign_reason.empty() ? std::string("the campaign was not fitted")
                                                   : report.campaign_reason) +
                   ". A validity range needs the campaign fit over at least two velocities.";
    return;
  }
  if (!calibrated.converged) {
    report.cause =
        "No verdict: the campaign fit of Hunt–Crossley did not converge, so its "
        "predictions (shown, marked 'not converged') cannot decide where the model "
        "holds. Rerun the calibration with more iterations or check the runs.";
    return;
  }
  report.verdict_available = true;
  report.cause = cause_of(report, calibrated);
  report.summary = summary_of(report);
  if (!trend.empty()) report.cause += " " + trend;
  const auto& ranking = report.calibration->campaign.ranking;
  if (!ranking.empty() && ranking.front().key != calibrated.calibration_key) {
    const RankedModel* own = nullptr;
    for (const auto& entry : ranking)
      if (entry.key == calibrated.calibration_key) own = &entry;
    report.cause += " The model ranked first by " +
                    std::string(ranking.front().out_of_sample ? "out-of-sample" : "in-sample") +
                    " error is " + ranking.front().key + " (RMS error " +
                    unsigned_percent(ranking.front().score) + " in 1 - e^2, t_c, F_max and x_max" +
                    (own ? " against " + unsigned_percent(own->score) +
                               " for the calibrated "
                               "Hunt–Crossley"
                         : std::string()) +
                    ").";
  }
}

} // namespace impact::postprocess::detail
