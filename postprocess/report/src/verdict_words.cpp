// The verdict in words (verdict_words.hpp): every sentence here is made from the
// assessment's numbers and decisions; nothing is decided here.

#include "impact_postprocess/report/verdict_words.hpp"

#include "impact_postprocess/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The decided velocities of one verdict.
std::vector<double> velocities_where(const Report& report, const ToleranceVerdict& verdict,
                                     Decision decision, bool yielding_only = false) {
  std::vector<double> velocities;
  for (std::size_t i = 0; i < verdict.decisions.size(); ++i)
    if (verdict.decisions[i] == decision && (!yielding_only || report.runs[i].yields))
      velocities.push_back(report.runs[i].velocity);
  return velocities;
}

// "within 5 % at V = ..." of one model, for the summary.
std::string range_words(const Report& report, const ModelVerdict& verdict) {
  const ToleranceVerdict& loose = verdict.tolerances.back();
  const std::vector<double> within = velocities_where(report, loose, Decision::within);
  const std::vector<double> undecided = velocities_where(report, loose, Decision::undecided);
  std::string text =
      "within " + band_name(loose.tolerance) + " " +
      (within.empty() ? std::string("at no tested velocity") : "at V = " + velocity_list(within));
  if (!undecided.empty()) text += ", not decided at V = " + velocity_list(undecided);
  return text;
}

// "...; the FEM's 1 - e grows as V^p [..]: the nearest reference family is ..." of the
// summary (a viscoelastic FEM).
std::string summary_trend(const PowerLawTrend& trend) {
  const ReferenceSlope& nearest = nearest_reference(trend);
  return " The FEM's 1 - e grows as V^" + short_number(trend.exponent, 3) + " [" +
         short_number(trend.lower, 3) + ", " + short_number(trend.upper, 3) +
         "]: the nearest reference family is " + nearest.family + " (V^" +
         short_number(nearest.slope, 3) + ")" +
         (nearest.slope == 1.0 ? "." : ", not Hunt–Crossley with a constant b (V^1).");
}

// The summary's sentence on the model ranked first.
std::string summary_ranking(const Report& report) {
  const auto& ranking = report.calibration->campaign.ranking;
  if (ranking.empty()) return "";
  const RankedModel& best = ranking.front();
  const ReportModel* shown = nullptr;
  for (const auto& model : report.models)
    if (model.calibration_key == best.key) shown = &model;
  std::string text =
      " Ranked first by " + std::string(best.out_of_sample ? "out-of-sample" : "in-sample") +
      " error: " + (shown ? shown->label : best.key) + " (" + std::to_string(best.free_parameters) +
      " free parameters, RMS error " + unsigned_percent(best.score) + ")";
  if (shown && report.verdict(shown->key))
    text += ", " + range_words(report, *report.verdict(shown->key));
  return text + ".";
}

// Which family the FEM follows on the trend: the nearest reference, and those the interval
// excludes or admits.
std::string trend_family(const PowerLawTrend& trend) {
  const ReferenceSlope* nearest = &nearest_reference(trend);
  const auto inside = [&](const ReferenceSlope& reference) {
    return reference.slope >= trend.lower && reference.slope <= trend.upper;
  };
  std::string text = "the FEM follows " + nearest->family + " (reference slope " +
                     significant(nearest->slope, 3) + ")";
  if (inside(*nearest))
    text += ", which lies inside the interval";
  else
    text += ": the nearest reference, " +
            significant(std::abs(nearest->slope - trend.exponent), 2) + " from p (" +
            significant(std::abs(nearest->slope - trend.exponent) / trend.standard_error, 2) +
            " standard errors; the reference slopes are the small-dissipation limits, and a "
            "loss with two mechanisms, e.g. viscosity and wave radiation, lies between theirs)";
  std::string excluded, consistent;
  for (const auto& reference : reference_slopes()) {
    if (&reference == nearest) continue;
    std::string& list = inside(reference) ? consistent : excluded;
    list += (list.empty() ? "" : " and ") + reference.family + " (" +
            significant(reference.slope, 3) + ")";
  }
  if (!consistent.empty()) text += "; also inside the interval: " + consistent;
  if (!excluded.empty()) text += "; excluded: " + excluded;
  return text;
}

std::string slope_words(const std::string& of, double slope,
                        const std::optional<PowerLawTrend>& trend) {
  std::string text = of + " ∝ V^" + significant(slope, 3);
  if (trend)
    text += " [" + significant(trend->lower, 3) + ", " + significant(trend->upper, 3) + "]";
  else
    text += " (two runs: no interval)";
  return text;
}

// One family range in a sentence.
std::string family_range_words(const FamilyRange& range, std::optional<double> yield_velocity) {
  std::string where = "V = " + significant(range.low, 3) +
                      (range.high > range.low ? " to " + significant(range.high, 3) : "") + " m/s";
  const std::string runs = std::to_string(range.runs) + (range.runs == 1 ? " run)" : " runs)");
  if (yield_velocity)
    where += " (" + std::string(range.above_yield ? "above" : "at or below") +
             " V_y, V/V_y = " + significant(range.low / *yield_velocity, 3) +
             (range.high > range.low ? " to " + significant(range.high / *yield_velocity, 3) : "") +
             ", " + runs;
  else
    where += " (" + runs;
  switch (range.basis) {
    case FamilyBasis::elastic:
      return where + ": elastic, 1 - e below " + significant(range.largest_loss * 100, 2) +
             " % at every run (the limit is " + significant(elastic_loss_limit * 100, 6) + " %).";
    case FamilyBasis::no_trend:
      return where + ": no trend (it needs two runs with 0 < e < 1 at two velocities).";
    case FamilyBasis::plastic: {
      std::string laws;
      for (const auto& law : range.law_slopes)
        laws += (laws.empty() ? "" : ", ") + law.law + " " + significant(law.slope, 3);
      const std::string reference =
          laws.empty() ? "the plastic family (reference slope -1/4 far above V_y, Thornton 1997)"
                       : "the plastic family (the plastic laws' own slopes over these "
                         "velocities: " +
                             laws + "; -1/4 far above V_y)";
      return where + ": " + slope_words("e", range.slope, range.trend) + ": " +
             (range.family == "plastic" ? reference + ", not a constant e (slope 0)"
                                        : "nearer a constant e (slope 0) than " + reference) +
             "; there " + slope_words("1 - e", range.loss_slope, range.loss_trend) + ".";
    }
    case FamilyBasis::nearest:
      break;
  }
  return where + ": " + slope_words("1 - e", range.loss_slope, range.loss_trend) + ", nearest " +
         range.family + " (slope " + significant(range.reference_slope, 3) + ")" +
         (range.plastic_possible ? ""
                                 : "; the plastic family does not apply (the FEM's "
                                   "material does not yield)") +
         ".";
}

std::string damping_trend_words(const DampingTrend& trend) {
  std::ostringstream text;
  text << "Per-run b from the restitution: " << short_number(trend.first) << " s/m at "
       << short_number(trend.first_velocity) << " m/s to " << short_number(trend.last) << " s/m at "
       << short_number(trend.last_velocity) << " m/s (range " << short_number(trend.low) << " to "
       << short_number(trend.high) << " s/m); the least-squares line changes by "
       << percent_cell(trend.change) << " of the mean over the tested range. ";
  if (trend.constant)
    text << "b is constant within 2 %: the dissipation has the velocity dependence of "
            "Hunt–Crossley (constant b).";
  else
    text << "b " << (trend.change > 0 ? "rises" : "falls")
         << " with V: one constant b cannot give the FEM restitution at every velocity, so the "
            "FEM dissipation is not of Hunt–Crossley's form over this range"
         << (trend.change > 0 ? ""
                              : " (a falling b means e decreases more slowly with V than "
                                "Hunt–Crossley predicts)")
         << ".";
  return text.str();
}

// Offsets from Hertz of the calibrated elastic part: n from the free fit, c from the fit with
// n held at 3/2 (the free fit's c is in N/m^n, not comparable with c_Hertz).
std::string hertz_offsets(const Report& report) {
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

std::string failure_words(const Report& report, const FailureCause& cause) {
  const std::size_t count = report.runs.size();
  const std::string basis = report.models.front().out_of_sample ? "out of sample" : "in sample";
  const std::string largest =
      percent_cell(cause.worst_error) + " (" + quantity_words(cause.worst_quantity) +
      " at V = " + short_number(report.runs[cause.worst_run].velocity) + " m/s).";
  std::ostringstream text;
  if (cause.holds) {
    text << "The calibrated Hunt–Crossley model holds within " << band_name(cause.tolerance)
         << " at every tested velocity (" << basis << "); the largest error is " << largest;
    return text.str();
  }
  text << "The " << quantity_words(cause.first_breaking) << " ("
       << quantity_symbol(cause.first_breaking) << ") breaks first: " << basis << " it is within "
       << band_name(cause.tolerance) << " at " << cause.first_breaking_within << " of " << count
       << " velocities, with errors";
  for (std::size_t i = 0; i < count; ++i)
    text << (i ? "," : "") << " " << percent_cell(cause.first_breaking_errors[i]) << " at "
         << short_number(report.runs[i].velocity) << " m/s";
  text << ". The largest error of all is " << largest;
  const bool low_end = cause.worst_run == 0, high_end = cause.worst_run + 1 == count;
  if (low_end || high_end)
    text << " The errors grow towards the " << (low_end ? "lowest" : "highest")
         << " tested velocity.";
  return text.str();
}

// The model ranked first, when it is not the calibrated Hunt–Crossley, after the cause.
std::string ranked_first_words(const Report& report) {
  const ReportModel& calibrated = report.models.front();
  const auto& ranking = report.calibration->campaign.ranking;
  if (ranking.empty() || ranking.front().key == calibrated.calibration_key) return "";
  const RankedModel* own = nullptr;
  for (const auto& entry : ranking)
    if (entry.key == calibrated.calibration_key) own = &entry;
  return " The model ranked first by " +
         std::string(ranking.front().out_of_sample ? "out-of-sample" : "in-sample") + " error is " +
         ranking.front().key + " (RMS error " + unsigned_percent(ranking.front().score) +
         " in 1 - e^2, t_c, F_max and x_max" +
         (own ? " against " + unsigned_percent(own->score) +
                    " for the calibrated "
                    "Hunt–Crossley"
              : std::string()) +
         ").";
}

std::string plastic_material_words(const Report& report) {
  const PlasticityCheck& check = report.plasticity;
  std::string text =
      "The FEM's material is elastic-plastic (a body with 'Material model = "
      "elastic-plastic', J2 plasticity): the FEM itself yields";
  if (check.first_yielding_run)
    text += " (from V = " + short_number(report.runs[*check.first_yielding_run].velocity) +
            " m/s on, by its own record)";
  if (const auto& laws = report.plastic_laws)
    text += "; the material's yield velocity is V_y = " + short_number(laws->yield_velocity, 4) +
            " m/s (Johnson's p_y = 1.6 Y; " + short_number(laws->jackson_green_yield_velocity, 4) +
            " m/s with Jackson–Green's p_y = C(nu) Y)";
  return text +
         ". It stays valid above yield, so no velocity is flagged: there the viscoelastic "
         "laws are compared with a plastic FEM, and the elastic-plastic laws (Thornton, "
         "Jackson–Green; section Elastic-plastic laws) are the ones built for it.";
}

} // namespace

std::string sample_basis(bool out_of_sample) {
  return out_of_sample ? " (out of sample)" : " (in sample)";
}

std::string tolerance_sentence(const Report& report, const ToleranceVerdict& verdict,
                               const std::string& basis) {
  const std::size_t count = verdict.decisions.size();
  const std::string band = band_name(verdict.tolerance);
  std::string text;
  if (!verdict.range) {
    text = "Within " + band + ": at no tested velocity" + basis + ".";
  } else {
    const auto [low, high] = *verdict.range;
    text = "Within " + band + ": " +
           (verdict.range_runs == count ? "over the whole tested range, " : "") + "V = " +
           (low == high ? short_number(low) : short_number(low) + " to " + short_number(high)) +
           " m/s" + basis + " (" + std::to_string(verdict.range_runs) + " of " +
           std::to_string(count) + " tested velocities).";
  }
  if (const auto outside = velocities_where(report, verdict, Decision::outside); !outside.empty())
    text += " Outside " + band + " at V = " + velocity_list(outside) +
            (verdict.range ? "; the limits lie between the last tested velocity inside and the "
                             "first outside."
                           : ".");
  if (const auto undecided = velocities_where(report, verdict, Decision::undecided);
      !undecided.empty())
    text += " Not decided at V = " + velocity_list(undecided) +
            ": the FEM's numerical uncertainty is as large as the margin to the band.";
  if (const auto unknown = velocities_where(report, verdict, Decision::unknown); !unknown.empty())
    text += " Not decided at V = " + velocity_list(unknown) + " (prediction missing).";
  if (const auto yielding = velocities_where(report, verdict, Decision::within, true);
      !yielding.empty())
    text += " At V = " + velocity_list(yielding) +
            " the FEM exceeds the yield strength: the agreement is with a viscoelastic model "
            "that is itself not valid there.";
  return text;
}

std::string campaign_reason(const Report& report) {
  return report.calibration ? report.calibration->campaign.reason : "there is no calibration";
}

std::string summary_sentence(const Report& report) {
  if (!report.verdict_available || !report.energy_loss_errors) return "";
  const ReportModel& calibrated = report.models.front();
  const ModelVerdict* verdict = report.verdict(calibrated.key);
  if (!verdict) return "";
  const auto [low, high] = *report.energy_loss_errors;
  std::string text = "Summary: the calibrated Hunt–Crossley model (constant b) is " +
                     range_words(report, *verdict) + " (" +
                     (calibrated.out_of_sample ? "out of sample" : "in sample") +
                     "); its energy loss is off by " + percent_cell(low) + " to " +
                     percent_cell(high) + ".";
  text += summary_ranking(report);
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
  if (report.trend && !report.plastic_laws) text += summary_trend(*report.trend);
  if (report.plastic_laws) text += " " + family_sentence(report);
  if (report.plasticity.first_yielding_velocity)
    text += " Above " +
            short_number(report.plasticity.onset_estimate.value_or(
                             *report.plasticity.first_yielding_velocity),
                         3) +
            " m/s the FEM exceeds the yield strength: there no viscoelastic model, reduced or "
            "FEM, is valid.";
  return text;
}

std::string no_verdict_sentence(const NoVerdict& why) {
  if (why.kind == NoVerdict::Kind::not_converged)
    return "No verdict: the campaign fit of Hunt–Crossley did not converge, so its "
           "predictions (shown, marked 'not converged') cannot decide where the model "
           "holds. Rerun the calibration with more iterations or check the runs.";
  const std::string reason =
      why.kind == NoVerdict::Kind::no_calibration ? "there is no calibration" : why.reason;
  return "No verdict: " + (reason.empty() ? std::string("the campaign was not fitted") : reason) +
         ". A validity range needs the campaign fit over at least two velocities.";
}

std::string cause_sentence(const Report& report) {
  if (report.no_verdict) return no_verdict_sentence(*report.no_verdict);
  if (!report.cause) return "";
  std::string text = failure_words(report, *report.cause);
  if (report.damping_trend) text += " " + damping_trend_words(*report.damping_trend);
  return text + ranked_first_words(report);
}

std::string trend_sentence(const Report& report) {
  if (report.runs.empty()) return "";
  if (!report.trend)
    return "Velocity trend of the FEM's energy loss: not fitted (it needs three "
           "runs with 0 < e < 1 at two or more velocities).";
  const PowerLawTrend& trend = *report.trend;
  return "Velocity trend of the FEM's energy loss: 1 - e ∝ V^p with p = " +
         short_number(trend.exponent, 3) + " [" + short_number(trend.lower, 3) + ", " +
         short_number(trend.upper, 3) + "] (" + short_number(trend.level * 100, 3) +
         " % interval, " + std::to_string(trend.points) + " runs): " + trend_family(trend) + "." +
         (report.plastic_laws ? " For an elastic-plastic FEM this one slope over every run mixes "
                                "the elastic and the plastic range; the family ranges (\"Which "
                                "family the FEM follows\") say which family holds where."
                              : "");
}

std::string family_sentence(const Report& report) {
  if (report.family_ranges.empty()) return "";
  const std::optional<double> yield_velocity =
      report.plastic_laws ? std::optional<double>(report.plastic_laws->yield_velocity)
                          : std::nullopt;
  std::string text = "Which family the FEM follows";
  text += yield_velocity
              ? " (split at the yield velocity V_y = " + significant(*yield_velocity, 4) +
                    " m/s of the material, Johnson's p_y = 1.6 Y):"
              : ":";
  for (const auto& range : report.family_ranges)
    text += " " + family_range_words(range, yield_velocity);
  return text;
}

std::string plasticity_sentence(const Report& report) {
  if (report.runs.empty()) return "";
  const PlasticityCheck& check = report.plasticity;
  if (check.plastic_material) return plastic_material_words(report);
  if (!check.recorded)
    return "No yield strength is recorded with the stresses (Sphere/Yield strength, "
           "Plate/Yield strength of impact-fem): whether the viscoelastic model itself "
           "holds (no plasticity) is not checked.";
  const auto& runs = report.runs;
  if (!check.first_yielding_run)
    return "The FEM stays below the yield strength at every tested velocity (largest von "
           "Mises stress " +
           short_number(runs.back().record.max_von_mises.value_or(nan) / 1e9, 3) + " GPa against " +
           short_number(runs.back().record.yield_strength.value_or(nan) / 1e9, 3) +
           " GPa): the viscoelastic model holds over the whole range.";
  const ReportRun& first_yielding = runs[*check.first_yielding_run];
  const double yield = *first_yielding.record.yield_strength;
  const double stress = *first_yielding.record.max_von_mises;
  const std::string onset =
      check.last_elastic_run
          ? "; the onset lies near " + short_number(*check.onset_estimate, 3) +
                " m/s (log-log interpolation of the peak stress between " +
                short_number(runs[*check.last_elastic_run].velocity) + " and " +
                short_number(first_yielding.velocity) + " m/s)"
          : "; every tested velocity yields, and by the Hertz scaling of the stress "
            "(sigma ~ V^(2/5)) the onset lies near " +
                short_number(*check.onset_estimate, 3) + " m/s";
  return "The FEM exceeds the yield strength (" + short_number(yield / 1e9, 3) + " GPa, " +
         first_yielding.record.yield_source +
         ") from V = " + short_number(first_yielding.velocity) + " m/s on (peak von Mises stress " +
         short_number(stress / 1e9, 3) + " GPa there" + onset +
         "): from there on the bodies would yield and the viscoelastic model itself is "
         "not valid, so no reduced model may be trusted there whatever its agreement with "
         "this FEM. Those velocities are marked (yields) in every table.";
}

std::string uncertainty_sentence(const Report& report) {
  if (report.runs.empty()) return "";
  bool verified = false, unverified = false;
  double oscillation_low = INFINITY, oscillation_high = 0;
  for (const auto& run : report.runs) {
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
  if (unverified)
    text += std::string(verified ? "The other runs have" : "The runs have") +
            " no verification, so the uncertainty is what the history shows: the peak force "
            "that of the step-to-step oscillation of the force (" +
            (std::isfinite(oscillation_low)
                 ? unsigned_percent(oscillation_low) + " to " + unsigned_percent(oscillation_high)
                 : std::string("n/a")) +
            " of the peak), the contact time one time step or the release chatter; the energy "
            "loss and the peak approach have no estimate and count as exact, which the verdict "
            "cannot check.";
  return text;
}

std::string alpha_sentence(const Report& report) {
  if (!report.effective_alpha) return "";
  const EffectiveAlpha& alpha = *report.effective_alpha;
  std::string where;
  if (alpha.inside == alpha.count)
    where = "inside that range at every run";
  else if (alpha.below == alpha.count)
    where = "below that range at every run";
  else if (alpha.above == alpha.count)
    where = "above that range at every run";
  else
    where = std::to_string(alpha.below) + " run(s) below, " + std::to_string(alpha.inside) +
            " inside and " + std::to_string(alpha.above) + " above that range";
  return "Effective alpha (1 - e)/V of the FEM (the per-run table): " + short_number(alpha.low) +
         " to " + short_number(alpha.high) +
         " s/m. The seed paper compares this number with the 0.08–0.32 s/m measured for steel, "
         "glass and brass (Goldsmith's experiments); the FEM's values lie " +
         where +
         ". (1 - e)/V is constant only where 1 - e grows like V (Hunt–Crossley's small-damping "
         "limit 1 - e = (2/3) b V, so alpha = (2/3) b): where the FEM's 1 - e grows more slowly "
         "(velocity trend), "
         "its effective alpha falls with V and one measured alpha holds at one velocity only.";
}

std::vector<std::string> parameter_notes(const Report& report) {
  std::vector<std::string> notes;
  if (report.runs.empty()) return notes;
  if (report.calibration && report.campaign_fitted && report.calibration->campaign.hunt_crossley)
    notes.push_back(hertz_offsets(report));
  if (report.damping_trend) notes.push_back(damping_trend_words(*report.damping_trend));
  return notes;
}

} // namespace impact::postprocess
