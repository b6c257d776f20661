// The per-run fits: the loading branch with b from the restitution, and the whole force
// history (c, n, b), each started from a straight line in log-log space.

#include "fit_model.hpp"

#include "impact_postprocess/models/simulated_force.hpp"
#include "impact_postprocess/number_format.hpp"

#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/invalid_input.hpp>

#include <algorithm>
#include <cmath>

namespace impact::postprocess::detail {

namespace {

// Starting values: straight line through (ln x, ln F) over the upper part of the loading
// branch (F > 5 % of the peak), where the force is well resolved.
std::pair<double, double> log_space_start(const PreparedRun& run) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < run.loading_force.size(); ++i) {
    if (run.loading_force[i] < 0.05 * run.force_scale) continue;
    const double lx = std::log(run.loading_approach[i]);
    const double ly = std::log(run.loading_force[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
    ++count;
  }
  const double denominator = double(count) * sxx - sx * sx;
  if (count < 2 || !(std::abs(denominator) > 0)) return {nan, 1.5};
  const double exponent = (double(count) * sxy - sx * sy) / denominator;
  const double log_stiffness = (sy - exponent * sx) / double(count);
  return {std::exp(log_stiffness), exponent};
}

// The loading branch: F = c x^n (1 + b v(x)), b fixed (from the restitution).
std::optional<ModelFit> fit_loading(const PreparedRun& run, double damping,
                                    const CalibrationOptions& options,
                                    std::vector<Problem>& problems) {
  const FemRun& fem = *run.run;
  if (run.loading_force.size() < 3) {
    problems.push_back({fem.source, ProblemKind::input,
                        "the loading branch has " + std::to_string(run.loading_force.size()) +
                            " samples with positive force and approach; at least 3 are needed "
                            "for the loading fit"});
    return std::nullopt;
  }
  const auto [c0, n0] = log_space_start(run);
  static const ContactModel model = hunt_crossley_model();
  FitSetup setup{&model, {fem.approach_max, {damping > 0 ? damping : 1.0}}, {}};
  setup.parameters = {{setup.parametrisation.log_reference_force(
                          std::isfinite(c0) ? c0 : fem.force_max / std::pow(fem.approach_max, n0),
                          n0)},
                      exponent_parameter(n0, false),
                      {damping > 0 ? 1.0 : 0.0}};
  setup.parameters[0].step = 1e-6;
  setup.parameters[2].fixed = true;

  const auto force = [&run, &fem, map = setup.parametrisation](const double* theta,
                                                               double* out) -> bool {
    const double c = map.stiffness(theta);
    const double n = map.exponent(theta);
    const double b = map.dissipation(theta)[0];
    if (!(std::isfinite(c) && c > 0 && n > 0)) return false;
    try {
      const reduced::HuntCrossleyImpact impact(fem.mass, c, n, b, fem.impact_velocity);
      const double approach_max = impact.approach_max();
      for (std::size_t i = 0; i < run.loading_approach.size(); ++i) {
        const double x = std::min(run.loading_approach[i], approach_max);
        const double rate =
            b > 0 ? impact.approach_rate(x, reduced::ImpactPhase::compression) : 0.0;
        out[i] = c * std::pow(run.loading_approach[i], n) * (1 + b * rate);
      }
    } catch (const std::exception&) {
      return false;
    }
    return true;
  };
  ResidualBlock block{run.loading_force.size(),
                      [&run, force](const double* theta, double* residual) {
                        if (!force(theta, residual)) return false;
                        for (std::size_t i = 0; i < run.loading_force.size(); ++i)
                          residual[i] = (residual[i] - run.loading_force[i]) / run.force_scale;
                        return true;
                      }};
  const auto result = solve_least_squares(setup.parameters, {block}, {options.max_iterations, 1});
  ModelFit fit = to_model_fit(setup, result, options.confidence_level);
  std::vector<double> model_force(run.loading_force.size());
  fit.quality = force(result.theta.data(), model_force.data())
                    ? quality_of(model_force, run.loading_force, run.force_scale)
                    : FitQuality{nan, nan, model_force.size()};
  if (!fit.converged)
    problems.push_back({fem.source, ProblemKind::convergence,
                        "the loading-branch fit did not converge: " + fit.solver_message});
  return fit;
}

std::optional<ModelFit> fit_history(const PreparedRun& run, double c0, double n0, double b0,
                                    const CalibrationOptions& options,
                                    std::vector<Problem>& problems) {
  const FemRun& fem = *run.run;
  static const ContactModel model = hunt_crossley_model();
  const double scale =
      model.damping_for_restitution(std::min(fem.restitution, 0.95), fem.impact_velocity, {});
  FitSetup setup{&model, {fem.approach_max, {scale}}, {}};
  setup.parameters = {{setup.parametrisation.log_reference_force(c0, n0)},
                      exponent_parameter(n0, false),
                      {b0 / scale}};
  setup.parameters[2].lower = 0;
  const HistoryEvaluator evaluator{&model, &run, setup.parametrisation, options.ode_tolerance};
  ResidualBlock block{run.times.size(), [evaluator](const double* theta, double* r) {
                        return evaluator.residuals(theta, r);
                      }};
  const auto result = solve_least_squares(setup.parameters, {block}, {options.max_iterations, 1});
  ModelFit fit = to_model_fit(setup, result, options.confidence_level);
  fit.quality = evaluator.quality(result.theta.data());
  if (!fit.converged)
    problems.push_back({fem.source, ProblemKind::convergence,
                        "the force-history fit did not converge: " + fit.solver_message});
  return fit;
}

} // namespace

RunCalibration calibrate_run(const PreparedRun& run, const CalibrationOptions& options,
                             std::vector<Problem>& problems) {
  const FemRun& fem = *run.run;
  RunCalibration result;
  result.source = fem.source;
  result.velocity = fem.impact_velocity;
  result.mass = fem.mass;
  result.measured = measured_quantities(fem);
  result.damping_from_restitution =
      fem.restitution < 1 ? reduced::damping_from_restitution(fem.restitution, fem.impact_velocity)
                          : 0.0;
  result.impact_parameter = result.damping_from_restitution * fem.impact_velocity;
  if (fem.restitution > 1)
    problems.push_back({fem.source, ProblemKind::input,
                        "the restitution " + significant(fem.restitution, 6) +
                            " exceeds 1 (energy gained?); b from the restitution is set to 0"});

  result.loading = fit_loading(run, result.damping_from_restitution, options, problems);
  double c0 = result.loading ? result.loading->stiffness.value : nan;
  double n0 = result.loading ? result.loading->exponent.value : 1.5;
  if (!(std::isfinite(c0) && c0 > 0)) {
    n0 = 1.5;
    c0 = fem.force_max / std::pow(fem.approach_max, n0);
  }
  result.history = fit_history(run, c0, n0, result.damping_from_restitution, options, problems);
  if (result.history)
    result.history_prediction =
        predict_impact(hunt_crossley_model(), fem.mass, fem.impact_velocity,
                       result.history->stiffness.value, result.history->exponent.value,
                       result.history->dissipation(), options.ode_tolerance);
  return result;
}

} // namespace impact::postprocess::detail
