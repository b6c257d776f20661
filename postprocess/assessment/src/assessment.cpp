// assess (assessment.hpp): the runs with what they record, the calibration's problems, the
// FEM's quality warnings, then the steps (steps.hpp): the models, the elastic-plastic laws,
// the verdict, the validity map, the simulators' own runs of the exports, the recommendation.

#include "impact_postprocess/assessment/assessment.hpp"

#include "steps.hpp"

#include "impact_postprocess/calibration/calibrate_run_set.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t fem_history_samples = 1500;

ImpactHistory fem_window(const FemRun& run) {
  ImpactHistory window;
  const double t0 = run.first_contact_time, tc = run.contact_time;
  std::vector<std::size_t> inside;
  for (std::size_t i = 0; i < run.time.size(); ++i) {
    const double t = run.time[i] - t0;
    if (t >= -0.05 * tc && t <= 1.25 * tc) inside.push_back(i);
  }
  const std::size_t stride =
      std::max<std::size_t>(1, (inside.size() + fem_history_samples - 1) / fem_history_samples);
  for (std::size_t k = 0; k < inside.size(); k += stride) {
    const std::size_t i = inside[k];
    window.time.push_back(run.time[i] - t0);
    window.approach.push_back(run.approach[i]);
    window.force.push_back(run.contact_force[i]);
  }
  return window;
}

ReportEstimate estimate_of(const Estimate& estimate) {
  return {estimate.value, estimate.lower, estimate.upper};
}

const RunCalibration* calibrated_run(const Calibration& calibration, const FemRun& fem) {
  for (const auto& run : calibration.runs)
    if (detail::same_source(run.source, fem.source)) return &run;
  const RunCalibration* found = nullptr;
  for (const auto& run : calibration.runs)
    if (detail::same_velocity(run.velocity, fem.impact_velocity)) {
      if (found) return nullptr;
      found = &run;
    }
  return found;
}

// What the FEM history itself shows beyond its warning thresholds (ProblemKind::quality once
// worded: the report stays complete), and the run's verification problem.
void add_quality_warnings(ReportRun& run, std::vector<Problem>& problems) {
  const ForceSmoothness& smoothness = run.record.smoothness;
  if (std::isfinite(smoothness.oscillation) && smoothness.oscillation > force_oscillation_warning)
    run.quality.oscillation = smoothness.oscillation;
  if (std::isfinite(smoothness.after_release) && smoothness.after_release > release_chatter_warning)
    run.quality.after_release = smoothness.after_release;
  if (const auto& balance = run.record.energy_error_final;
      balance && std::abs(*balance) > energy_balance_target)
    run.quality.energy_balance = *balance;
  run.quality.problem_position = problems.size();
  if (!run.record.verification_problem.empty())
    problems.push_back({run.source, ProblemKind::input, run.record.verification_problem});
}

} // namespace

const ReportModel* Assessment::model(std::string_view key) const {
  for (const auto& entry : models)
    if (entry.key == key) return &entry;
  return nullptr;
}

const ModelVerdict* Assessment::verdict(std::string_view key) const {
  for (const auto& entry : verdicts)
    if (entry.model_key == key) return &entry;
  return nullptr;
}

Assessment assess(const Campaign& campaign, const std::optional<Calibration>& calibration,
                  std::vector<Problem> problems, const std::string& campaign_source,
                  const std::string& calibration_source, const AssessmentOptions& options) {
  Assessment report;
  report.campaign_source = campaign_source;
  report.calibration_source = calibration_source;
  report.calibration = calibration;
  report.tolerances = options.tolerances;
  std::sort(report.tolerances.begin(), report.tolerances.end());
  // A run without rebound is a finding (ProblemKind::no_rebound), listed, not an input error.
  for (const auto& problem : campaign.problems) problems.push_back(problem);
  if (campaign.runs.empty())
    problems.push_back(
        {campaign_source, ProblemKind::input, "no usable run: the report has no FEM data"});

  // Runs, with the calibration's measured numbers where it holds the run.
  for (const FemRun& fem : campaign.runs) {
    ReportRun run;
    run.source = fem.source;
    run.velocity = fem.impact_velocity;
    run.mass = fem.mass;
    run.fem = measured_quantities(fem);
    run.fem_history = fem_window(fem);
    run.damping_from_restitution = nan;
    run.history_damping = run.history_stiffness = run.history_exponent = {nan, nan, nan};
    run.record = read_fem_run_record(fem);
    if (const RunCalibration* entry = calibration ? calibrated_run(*calibration, fem) : nullptr) {
      run.calibrated = true;
      run.fem = entry->measured;
      run.damping_from_restitution = entry->damping_from_restitution;
      if (entry->history) {
        run.history_damping = estimate_of(entry->history->parameter);
        run.history_stiffness = estimate_of(entry->history->stiffness);
        run.history_exponent = estimate_of(entry->history->exponent);
      }
    } else if (calibration) {
      problems.push_back({fem.source, ProblemKind::input,
                          "the run is not in the calibration " + calibration_source +
                              ": only its FEM data are shown"});
    }
    run.uncertainty = fem_uncertainty(run.record, run.fem);
    // An elastic-plastic FEM yields and stays valid: only a body without plasticity is flagged.
    run.yields = !run.record.plastic_material && run.record.yields.value_or(false);
    add_quality_warnings(run, problems);
    report.runs.push_back(std::move(run));
  }

  // The calibration's own problems (input and convergence), kept as they are; those of a run
  // that this campaign could not read either are the reader's, listed above.
  if (calibration)
    for (const auto& problem : calibration->problems) {
      const bool unread = std::any_of(campaign.problems.begin(), campaign.problems.end(),
                                      [&](const Problem& p) { return p.source == problem.source; });
      if (!unread) problems.push_back(problem);
    }

  const CampaignCalibration* fitted = calibration ? &calibration->campaign : nullptr;
  report.campaign_fitted = fitted && fitted->fitted && fitted->hunt_crossley;
  report.hertz_stiffness = fitted ? fitted->hertz_stiffness : nan;
  if (report.runs.empty()) {
    report.problems = std::move(problems);
    return report;
  }
  report.models = detail::report_models(report.runs, campaign.runs, calibration, problems);
  report.plastic_laws = detail::plastic_laws(campaign.runs, report.runs, calibration);

  // Without a campaign fit there is no verdict: that is missing input (e.g. a single run or
  // velocity given explicitly, which impact-calibrate itself accepts as a per-run job). Said
  // once: not again when the calibration's problems already say that its campaign was not
  // fitted (impact-calibrate's JSON of a campaign, impact-report's own calibration).
  if (!report.campaign_fitted && calibration) {
    const std::string reason = calibration->campaign.reason.empty()
                                   ? std::string("the calibration has no campaign fit")
                                   : calibration->campaign.reason;
    const bool said = std::any_of(calibration->problems.begin(), calibration->problems.end(),
                                  [&](const Problem& p) {
                                    return is_campaign_not_fitted(p, calibration->campaign);
                                  });
    if (!said)
      problems.push_back(
          {calibration_source, ProblemKind::input, "no validity verdict: " + reason});
  }
  report.problems = std::move(problems);
  detail::add_verdict(report);
  detail::add_validity_map(report, options.map_campaign ? *options.map_campaign : campaign,
                           options);
  report.detail_row = options.detail_row;
  if (options.simulators) detail::add_simulators(report, *options.simulators);
  detail::add_recommendation(report);
  return report;
}

} // namespace impact::postprocess
