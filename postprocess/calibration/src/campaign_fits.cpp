// The campaign fits: one model fitted to every run at once, and again without each velocity
// (the held-out fits of the out-of-sample errors and the jackknife intervals).

#include "fit_model.hpp"
#include "ranking.hpp"

#include "impact_postprocess/number_format.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>

namespace impact::postprocess::detail {

namespace {

// The residual blocks of `runs` for parameters mapped by `setup`.
std::vector<ResidualBlock> residual_blocks(const std::vector<HistoryEvaluator>& evaluators,
                                           double energy_weight) {
  std::vector<ResidualBlock> blocks;
  for (const auto& evaluator : evaluators) {
    blocks.push_back({evaluator.run->times.size(), [evaluator](const double* theta, double* r) {
                        return evaluator.residuals(theta, r);
                      }});
    if (energy_weight > 0 && evaluator.run->energy_loss > 0)
      blocks.push_back({1, [evaluator, energy_weight](const double* theta, double* r) {
                          return evaluator.energy_residual(theta, energy_weight, r);
                        }});
  }
  return blocks;
}

// Jackknife over the held-out fits: standard error sqrt((g-1)/g sum (theta_i - mean)^2).
std::vector<Estimate> jackknife(const std::vector<HeldOutFit>& held_out,
                                const std::vector<double>& full, const std::vector<bool>& fixed,
                                double confidence_level) {
  const std::size_t g = held_out.size();
  const double quantile = student_quantile(confidence_level, g - 1);
  std::vector<Estimate> estimates;
  for (std::size_t j = 0; j < full.size(); ++j) {
    if (fixed[j]) {
      estimates.push_back({full[j], nan, nan, nan});
      continue;
    }
    double mean = 0;
    for (const auto& fit : held_out) mean += fit.parameters[j] / double(g);
    double sum = 0;
    for (const auto& fit : held_out) sum += (fit.parameters[j] - mean) * (fit.parameters[j] - mean);
    if (sum == 0) { // held-out fits equal to the last bit (exact model, noise-free data)
      estimates.push_back({full[j], 0.0, full[j], full[j]});
      continue;
    }
    estimates.push_back(estimate(full[j], double(g - 1) / double(g) * sum, quantile));
  }
  return estimates;
}

// The parameters of a campaign fit of `model` and their start (n held when the model or the
// request fixes it, the dissipation from the campaign's median restitution).
FitSetup campaign_fit_setup(const ContactModel& model, const CampaignFitRequest& request,
                            const CampaignStart& start) {
  const std::optional<double> exponent =
      model.required_exponent ? model.required_exponent : request.exponent;
  const bool fixed_exponent = exponent.has_value();
  const double n0 = fixed_exponent ? *exponent : start.exponent;
  const double c0 = std::exp(start.log_reference_force - n0 * std::log(start.reference_approach));
  const reduced::ContactSetup reference_setup{start.mass, c0, n0};
  double scale = 1, p0 = start.restitution;
  if (model.parameter == DissipationParameter::damping) {
    scale = model.damping_for_restitution(std::min(start.restitution, 0.95), start.velocity,
                                          reference_setup);
    p0 = std::isfinite(request.initial_damping)
             ? request.initial_damping
             : (start.restitution < 1
                    ? model.damping_for_restitution(start.restitution, start.velocity,
                                                    reference_setup)
                    : 0.0);
  }
  FitSetup setup{&model, {start.reference_approach, {scale}}, {}};
  setup.parameters = {{start.log_reference_force},
                      exponent_parameter(n0, fixed_exponent),
                      {p0 / scale}};
  if (request.stiffness) {
    setup.parameters[0].initial = setup.parametrisation.log_reference_force(*request.stiffness, n0);
    setup.parameters[0].fixed = true;
  }
  if (model.parameter == DissipationParameter::damping) {
    setup.parameters[2].lower = 0;
  } else {
    setup.parameters[2].initial = std::clamp(p0, 1e-3, 1.0);
    setup.parameters[2].lower = 1e-3;
    setup.parameters[2].upper = 1;
  }
  for (std::size_t i = 0; i < model.extra_parameters.size(); ++i) {
    const auto& spec = model.extra_parameters[i];
    setup.parametrisation.scales.push_back(spec.scale);
    FitParameter parameter{
        (i < request.initial_extra.size() ? request.initial_extra[i] : spec.initial) / spec.scale};
    parameter.lower = spec.lower / spec.scale;
    parameter.upper = spec.upper / spec.scale;
    setup.parameters.push_back(parameter);
  }
  return setup;
}

// The force-history evaluators of the runs that `take` accepts.
std::vector<HistoryEvaluator> evaluators_of(const ContactModel& model, const FitSetup& setup,
                                            const std::vector<PreparedRun>& runs,
                                            const CalibrationOptions& options,
                                            const std::function<bool(const PreparedRun&)>& take) {
  std::vector<HistoryEvaluator> evaluators;
  for (const auto& run : runs)
    if (take(run))
      evaluators.push_back({&model, &run, setup.parametrisation, options.ode_tolerance});
  return evaluators;
}

// Leave one velocity out: the prediction at each velocity by the fit to the others (started
// from the full fit `theta`), and the jackknife of the parameters over those fits. The
// held-out fits are independent of one another: they run on `options.threads` threads, each
// fit on one (Ceres' own threads, over a handful of residual blocks of unequal cost, kept one
// core busy: impact-calibrate's second thread did 3 % of the work, perf, 2026-12-05). The
// results are gathered in the order of the velocities, so that the output does not depend on
// which thread finished first.
void add_held_out_fits(CampaignModelFit& campaign_fit, const ContactModel& model,
                       const CampaignFitRequest& request, const FitSetup& setup,
                       const std::vector<double>& theta, const std::vector<PreparedRun>& runs,
                       const std::vector<double>& velocities, const CalibrationOptions& options,
                       std::vector<Problem>& problems) {
  const std::string what = "the campaign fit of " + request.label + " (" + request.key + ")";
  std::vector<FitParameter> restart = setup.parameters;
  for (std::size_t j = 0; j < restart.size(); ++j) restart[j].initial = theta[j];
  struct HeldOut {
    LeastSquaresResult solution;
    ModelFit fit;
    std::exception_ptr error;
  };
  std::vector<HeldOut> held(velocities.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&]() {
    for (std::size_t k = next++; k < velocities.size(); k = next++) try {
        const double left_out = velocities[k];
        const auto others =
            evaluators_of(model, setup, runs, options, [left_out](const PreparedRun& run) {
              return !same_velocity(run.run->impact_velocity, left_out);
            });
        held[k].solution =
            solve_least_squares(restart, residual_blocks(others, request.energy_weight),
                                {options.max_iterations, 1});
        held[k].fit = to_model_fit(setup, held[k].solution, options.confidence_level);
      } catch (...) {
        held[k].error = std::current_exception();
      }
  };
  std::vector<std::thread> workers;
  const std::size_t threads =
      std::min<std::size_t>(std::size_t(std::max(options.threads, 1)), velocities.size());
  for (std::size_t i = 1; i < threads; ++i) workers.emplace_back(work);
  work();
  for (auto& worker : workers) worker.join();
  for (std::size_t k = 0; k < velocities.size(); ++k) {
    if (held[k].error) std::rethrow_exception(held[k].error);
    const double left_out = velocities[k];
    const ModelFit& held_fit = held[k].fit;
    campaign_fit.held_out.push_back(
        {left_out, held_fit.parameter_values(), held[k].solution.converged});
    if (!held[k].solution.converged)
      problems.push_back({request.key, ProblemKind::convergence,
                          what + " without V = " + significant(left_out, 6) +
                              " m/s did not converge: " + held[k].solution.message});
    for (std::size_t i = 0; i < runs.size(); ++i)
      if (same_velocity(runs[i].run->impact_velocity, left_out))
        campaign_fit.runs[i].out_of_sample =
            predict_impact(model, runs[i].run->mass, runs[i].run->impact_velocity,
                           held_fit.stiffness.value, held_fit.exponent.value,
                           held_fit.dissipation(), options.ode_tolerance);
  }
  std::vector<bool> fixed;
  for (const auto& parameter : setup.parameters) fixed.push_back(parameter.fixed);
  campaign_fit.jackknife = jackknife(campaign_fit.held_out, campaign_fit.fit.parameter_values(),
                                     fixed, options.confidence_level);
}

// One campaign fit of `model` to all runs, then, with at least three velocities, one fit
// per velocity with that velocity's runs left out (started from the full fit).
} // namespace

CampaignModelFit fit_campaign_model(const ContactModel& model, const CampaignFitRequest& request,
                                    const std::vector<PreparedRun>& runs,
                                    const std::vector<double>& velocities,
                                    const CampaignStart& start, const CalibrationOptions& options,
                                    std::vector<Problem>& problems) {
  const FitSetup setup = campaign_fit_setup(model, request, start);
  const std::vector<HistoryEvaluator> evaluators =
      evaluators_of(model, setup, runs, options, [](const PreparedRun&) { return true; });
  const auto result =
      solve_least_squares(setup.parameters, residual_blocks(evaluators, request.energy_weight),
                          {options.max_iterations, options.threads});
  CampaignModelFit campaign_fit;
  campaign_fit.key = request.key;
  campaign_fit.label = request.label;
  campaign_fit.fit = to_model_fit(setup, result, options.confidence_level);
  campaign_fit.formula = model.formula;
  campaign_fit.reference = model.reference;
  campaign_fit.damping_name = model.damping_name;
  campaign_fit.damping_unit = model.damping_unit;
  campaign_fit.energy_weight = request.energy_weight;
  std::vector<FitQuality> parts;
  const ModelFit& fit = campaign_fit.fit;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const FemRun& fem = *runs[i].run;
    RunResidual residual{fem.source, fem.impact_velocity,
                         evaluators[i].quality(result.theta.data()),
                         predict_impact(model, fem.mass, fem.impact_velocity, fit.stiffness.value,
                                        fit.exponent.value, fit.dissipation(),
                                        options.ode_tolerance),
                         std::nullopt};
    parts.push_back(residual.quality);
    campaign_fit.runs.push_back(residual);
  }
  campaign_fit.fit.quality = combine(parts);
  const std::string what = "the campaign fit of " + request.label + " (" + request.key + ")";
  if (!fit.converged)
    problems.push_back(
        {request.key, ProblemKind::convergence, what + " did not converge: " + fit.solver_message});

  if (velocities.size() >= 3)
    add_held_out_fits(campaign_fit, model, request, setup, result.theta, runs, velocities, options,
                      problems);
  return campaign_fit;
}

// A model evaluated with given parameters at every run: no fit.
} // namespace impact::postprocess::detail
