// The fits of calibration.hpp. Every fit works on the internal parameters
//     theta = (ln F_ref, n, p / p_scale),   F_ref = c x_ref^n,
// with x_ref a typical approach of the data: ln c and n are almost perfectly correlated
// (ln F = ln c + n ln x with ln x ~ -10), ln F_ref and n are not, so the solver and the
// covariance work on a well-conditioned problem; the covariance is mapped back to (c, n, p)
// by the Jacobian of that change of variables.

#include "impact_postprocess/calibration.hpp"

#include "least_squares.hpp"
#include "simulated_force.hpp"

#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/invalid_input.hpp>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The samples of a run that the fits use.
struct PreparedRun {
  const FemRun* run;
  std::vector<double> times;   // s since first contact: from just before contact to 1.25 t_c
  std::vector<double> forces;  // N
  double force_scale;          // N, the run's peak force: residuals are relative to it
  std::vector<double> loading_approach; // m, first contact to peak approach
  std::vector<double> loading_force;    // N
  std::size_t points;          // samples of the simulated impact
};

PreparedRun prepare(const FemRun& run) {
  PreparedRun prepared{&run, {}, {}, run.force_max, {}, {}, 0};
  const double t0 = run.first_contact_time;
  const double tc = run.contact_time;
  std::size_t in_contact = 0;
  std::size_t peak_approach = run.time.size();
  for (std::size_t i = 0; i < run.time.size(); ++i) {
    const double t = run.time[i] - t0;
    if (t < -0.05 * tc || t > 1.25 * tc) continue;
    prepared.times.push_back(t);
    prepared.forces.push_back(run.contact_force[i]);
    if (t > 0 && t < tc) {
      ++in_contact;
      if (peak_approach == run.time.size() || run.approach[i] > run.approach[peak_approach])
        peak_approach = i;
    }
  }
  // Strictly before the sample of peak approach, which may lie just past x_max.
  for (std::size_t i = 0; i < run.time.size() && i < peak_approach; ++i)
    if (run.time[i] > t0 && run.contact_force[i] > 0 && run.approach[i] > 0) {
      prepared.loading_approach.push_back(run.approach[i]);
      prepared.loading_force.push_back(run.contact_force[i]);
    }
  prepared.points = std::clamp<std::size_t>(4 * in_contact, 400, 20000);
  return prepared;
}

// theta = (ln F_ref, n, p / p_scale).
struct Parametrisation {
  double reference_approach;
  double parameter_scale;

  double stiffness(const double* theta) const {
    return std::exp(theta[0] - theta[1] * std::log(reference_approach));
  }
  double exponent(const double* theta) const { return theta[1]; }
  double parameter(const double* theta) const { return theta[2] * parameter_scale; }
  double log_reference_force(double stiffness, double exponent) const {
    return std::log(stiffness) + exponent * std::log(reference_approach);
  }
};

double student_quantile(double level, std::size_t degrees_of_freedom) {
  if (degrees_of_freedom == 0) return nan;
  const boost::math::students_t distribution{static_cast<double>(degrees_of_freedom)};
  return boost::math::quantile(distribution, 0.5 + level / 2);
}

Estimate estimate(double value, double variance, double quantile) {
  if (!(variance > 0) || !std::isfinite(quantile)) return {value, nan, nan, nan};
  const double error = std::sqrt(variance);
  return {value, error, value - quantile * error, value + quantile * error};
}

struct FitSetup {
  const ContactModel* model;
  Parametrisation parametrisation;
  std::vector<detail::FitParameter> parameters;
};

// ModelFit from the solver's result; quality filled by the caller.
ModelFit to_model_fit(const FitSetup& setup, const detail::LeastSquaresResult& result,
                      double confidence_level) {
  const double* theta = result.theta.data();
  const Parametrisation& map = setup.parametrisation;
  ModelFit fit;
  fit.model = setup.model->name;
  fit.parameter_name = setup.model->parameter_name();
  fit.parameter_unit = setup.model->parameter_unit();
  fit.exponent_fixed = setup.parameters[1].fixed;
  fit.parameter_fixed = setup.parameters[2].fixed;
  fit.converged = result.converged;
  fit.solver_message = result.message;
  fit.iterations = result.iterations;
  fit.reference_approach = map.reference_approach;

  const double c = map.stiffness(theta);
  // d(c, n, p) / d theta.
  const double g[3][3] = {{c, -c * std::log(map.reference_approach), 0},
                          {0, 1, 0},
                          {0, 0, map.parameter_scale}};
  std::array<double, 9> covariance{};
  const bool have_covariance = result.covariance.size() == 9;
  if (have_covariance)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double sum = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) sum += g[i][k] * result.covariance[k * 3 + l] * g[j][l];
        covariance[i * 3 + j] = sum;
      }
  else
    covariance.fill(nan);
  fit.covariance = covariance;
  const std::size_t dof = result.residual_count > result.free_parameters
                              ? result.residual_count - result.free_parameters
                              : 0;
  const double quantile = student_quantile(confidence_level, dof);
  fit.stiffness = estimate(c, covariance[0], quantile);
  fit.exponent = estimate(map.exponent(theta), covariance[4], quantile);
  fit.parameter = estimate(map.parameter(theta), covariance[8], quantile);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double scale = std::sqrt(covariance[i * 3 + i] * covariance[j * 3 + j]);
      fit.correlation[i * 3 + j] = scale > 0 ? covariance[i * 3 + j] / scale : nan;
    }
  const double reference_force = std::exp(theta[0]);
  fit.force_at_reference =
      estimate(reference_force,
               have_covariance ? reference_force * reference_force * result.covariance[0] : nan,
               quantile);
  return fit;
}

FitQuality quality_of(const std::vector<double>& model, const std::vector<double>& measured,
                      double scale) {
  const std::size_t n = measured.size();
  const double mean = std::accumulate(measured.begin(), measured.end(), 0.0) / double(n);
  double residual = 0, total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    residual += (model[i] - measured[i]) * (model[i] - measured[i]);
    total += (measured[i] - mean) * (measured[i] - mean);
  }
  return {std::sqrt(residual / double(n)) / scale, total > 0 ? 1 - residual / total : nan, n};
}

FitQuality combine(const std::vector<FitQuality>& parts) {
  double squares = 0, weights = 0;
  std::size_t samples = 0;
  double r_squared = 0;
  for (const auto& part : parts) {
    squares += part.rms_residual * part.rms_residual * double(part.samples);
    samples += part.samples;
    r_squared += part.r_squared * double(part.samples);
    weights += double(part.samples);
  }
  return {std::sqrt(squares / double(samples)), r_squared / weights, samples};
}

// ---- Force histories of a model -------------------------------------------------------

struct HistoryEvaluator {
  const ContactModel* model;
  const PreparedRun* run;
  Parametrisation map;
  double tolerance;

  bool force(const double* theta, double* force) const {
    const double c = map.stiffness(theta);
    const double n = map.exponent(theta);
    const double p = map.parameter(theta);
    if (!(std::isfinite(c) && c > 0 && n > 0 && std::isfinite(p))) return false;
    const reduced::ContactSetup setup{run->run->mass, c, n};
    double damping;
    try {
      damping = model->damping(p, run->run->impact_velocity, setup);
    } catch (const std::exception&) {
      return false;
    }
    return detail::simulate_force(model->force_law(damping, setup), run->run->mass,
                                  run->run->impact_velocity, run->times, run->points, tolerance,
                                  force);
  }

  bool residuals(const double* theta, double* residual) const {
    if (!force(theta, residual)) return false;
    for (std::size_t i = 0; i < run->forces.size(); ++i)
      residual[i] = (residual[i] - run->forces[i]) / run->force_scale;
    return true;
  }

  FitQuality quality(const double* theta) const {
    std::vector<double> model_force(run->times.size());
    if (!force(theta, model_force.data())) return {nan, nan, run->times.size()};
    return quality_of(model_force, run->forces, run->force_scale);
  }
};

ImpactPrediction predict(const ContactModel& model, const FemRun& run, double c, double n,
                         double p, double tolerance) {
  const reduced::ContactSetup setup{run.mass, c, n};
  ImpactPrediction prediction{nan, nan, nan, nan, nan, nan};
  try {
    prediction.damping = model.damping(p, run.impact_velocity, setup);
    if (model.name == "hunt-crossley" && prediction.damping >= 0) {
      const reduced::HuntCrossleyImpact impact(run.mass, c, n, prediction.damping,
                                               run.impact_velocity);
      const auto response = impact.response();
      prediction.restitution = response.restitution;
      prediction.contact_time = response.contact_time;
      prediction.force_max = response.force_max;
      prediction.time_force_max = response.time_force_max;
      prediction.approach_max = response.approach_max;
    } else {
      const auto impact = reduced::integrate_impact(
          run.mass, run.impact_velocity, model.force_law(prediction.damping, setup), tolerance);
      prediction.restitution = impact.restitution;
      prediction.contact_time = impact.contact_time;
      prediction.force_max = impact.force_max;
      prediction.time_force_max = impact.time_force_max;
      prediction.approach_max = impact.approach_max;
    }
  } catch (const std::exception&) {
  }
  return prediction;
}

std::string format_number(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

class Progress {
public:
  explicit Progress(const std::function<void(const std::string&)>& sink) : sink_(sink) {}
  void operator()(const std::string& line) const {
    if (sink_) sink_(line);
  }
  void start() { start_ = std::chrono::steady_clock::now(); }
  std::string elapsed() const {
    return format_number(
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()) +
           " s";
  }

private:
  const std::function<void(const std::string&)>& sink_;
  std::chrono::steady_clock::time_point start_;
};

// ---- Per run --------------------------------------------------------------------------

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

detail::FitParameter exponent_parameter(double initial, bool fixed) {
  detail::FitParameter parameter{initial};
  parameter.lower = 0.3;
  parameter.upper = 4;
  parameter.fixed = fixed;
  parameter.step = 1e-6;
  return parameter;
}

// The loading branch: F = c x^n (1 + b v(x)), b fixed (from the restitution).
std::optional<ModelFit> fit_loading(const PreparedRun& run, double damping,
                                    const CalibrationOptions& options,
                                    std::vector<CalibrationProblem>& problems) {
  const FemRun& fem = *run.run;
  if (run.loading_force.size() < 3) {
    problems.push_back({fem.source, "input",
                        "the loading branch has " + std::to_string(run.loading_force.size()) +
                            " samples with positive force and approach; at least 3 are needed "
                            "for the loading fit"});
    return std::nullopt;
  }
  const auto [c0, n0] = log_space_start(run);
  static const ContactModel model = hunt_crossley_model();
  FitSetup setup{&model, {fem.approach_max, damping > 0 ? damping : 1.0}, {}};
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
    const double b = map.parameter(theta);
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
  detail::ResidualBlock block{run.loading_force.size(), [&run, force](const double* theta,
                                                                      double* residual) {
                                if (!force(theta, residual)) return false;
                                for (std::size_t i = 0; i < run.loading_force.size(); ++i)
                                  residual[i] =
                                      (residual[i] - run.loading_force[i]) / run.force_scale;
                                return true;
                              }};
  const auto result = detail::solve_least_squares(setup.parameters, {block},
                                                  {options.max_iterations, 1});
  ModelFit fit = to_model_fit(setup, result, options.confidence_level);
  std::vector<double> model_force(run.loading_force.size());
  fit.quality = force(result.theta.data(), model_force.data())
                    ? quality_of(model_force, run.loading_force, run.force_scale)
                    : FitQuality{nan, nan, model_force.size()};
  if (!fit.converged)
    problems.push_back({fem.source, "convergence",
                        "the loading-branch fit did not converge: " + fit.solver_message});
  return fit;
}

std::optional<ModelFit> fit_history(const PreparedRun& run, double c0, double n0, double b0,
                                    const CalibrationOptions& options,
                                    std::vector<CalibrationProblem>& problems) {
  const FemRun& fem = *run.run;
  static const ContactModel model = hunt_crossley_model();
  const double scale =
      model.damping_for_restitution(std::min(fem.restitution, 0.95), fem.impact_velocity, {});
  FitSetup setup{&model, {fem.approach_max, scale}, {}};
  setup.parameters = {{setup.parametrisation.log_reference_force(c0, n0)},
                      exponent_parameter(n0, false),
                      {b0 / scale}};
  setup.parameters[2].lower = 0;
  const HistoryEvaluator evaluator{&model, &run, setup.parametrisation, options.ode_tolerance};
  detail::ResidualBlock block{run.times.size(), [evaluator](const double* theta, double* r) {
                                return evaluator.residuals(theta, r);
                              }};
  const auto result = detail::solve_least_squares(setup.parameters, {block},
                                                  {options.max_iterations, 1});
  ModelFit fit = to_model_fit(setup, result, options.confidence_level);
  fit.quality = evaluator.quality(result.theta.data());
  if (!fit.converged)
    problems.push_back({fem.source, "convergence",
                        "the force-history fit did not converge: " + fit.solver_message});
  return fit;
}

RunCalibration calibrate_run(const PreparedRun& run, const CalibrationOptions& options,
                             std::vector<CalibrationProblem>& problems) {
  const FemRun& fem = *run.run;
  RunCalibration result;
  result.source = fem.source;
  result.velocity = fem.impact_velocity;
  result.mass = fem.mass;
  result.measured = {fem.restitution, fem.contact_time, fem.force_max,
                     fem.time_force_max - fem.first_contact_time, fem.approach_max};
  result.damping_from_restitution =
      fem.restitution < 1 ? reduced::damping_from_restitution(fem.restitution, fem.impact_velocity)
                          : 0.0;
  result.impact_parameter = result.damping_from_restitution * fem.impact_velocity;
  if (fem.restitution > 1)
    problems.push_back({fem.source, "input",
                        "the restitution " + format_number(fem.restitution) +
                            " exceeds 1 (energy gained?); b from the restitution is set to 0"});

  result.loading = fit_loading(run, result.damping_from_restitution, options, problems);
  double c0 = result.loading ? result.loading->stiffness.value : nan;
  double n0 = result.loading ? result.loading->exponent.value : 1.5;
  if (!(std::isfinite(c0) && c0 > 0)) {
    n0 = 1.5;
    c0 = fem.force_max / std::pow(fem.approach_max, n0);
  }
  result.history = fit_history(run, c0, n0, result.damping_from_restitution, options, problems);
  if (result.history) {
    static const ContactModel model = hunt_crossley_model();
    result.history_prediction =
        predict(model, fem, result.history->stiffness.value, result.history->exponent.value,
                result.history->parameter.value, options.ode_tolerance);
  }
  return result;
}

// ---- Campaign -------------------------------------------------------------------------

double median(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(),
                              [](double v) { return !std::isfinite(v); }),
               values.end());
  if (values.empty()) return nan;
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

double geometric_mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += std::log(v);
  return std::exp(sum / double(values.size()));
}

struct CampaignStart {
  double reference_approach;
  double log_reference_force;
  double exponent;
  double restitution;  // median measured
  double velocity;     // geometric mean
  double mass;         // median
};

// One (c, n, p) of `model` for all runs. n is held fixed at the model's required exponent,
// else at `exponent` when given (Hunt–Crossley at the Hertz value), else fitted.
CampaignModelFit fit_campaign_model(const ContactModel& model,
                                    const std::vector<PreparedRun>& runs,
                                    const CampaignStart& start, double initial_damping,
                                    const CalibrationOptions& options,
                                    std::vector<CalibrationProblem>& problems,
                                    std::optional<double> exponent = std::nullopt) {
  if (model.required_exponent) exponent = model.required_exponent;
  const bool fixed_exponent = exponent.has_value();
  const double n0 = fixed_exponent ? *exponent : start.exponent;
  const double c0 = std::exp(start.log_reference_force - n0 * std::log(start.reference_approach));
  const reduced::ContactSetup reference_setup{start.mass, c0, n0};
  double scale = 1, p0 = start.restitution;
  if (model.parameter == DissipationParameter::damping) {
    scale = model.damping_for_restitution(std::min(start.restitution, 0.95), start.velocity,
                                          reference_setup);
    p0 = std::isfinite(initial_damping)
             ? initial_damping
             : (start.restitution < 1 ? model.damping_for_restitution(
                                            start.restitution, start.velocity, reference_setup)
                                      : 0.0);
  }
  FitSetup setup{&model, {start.reference_approach, scale}, {}};
  setup.parameters = {{start.log_reference_force}, exponent_parameter(n0, fixed_exponent),
                      {p0 / scale}};
  if (model.parameter == DissipationParameter::damping) {
    setup.parameters[2].lower = 0;
  } else {
    setup.parameters[2].initial = std::clamp(p0, 1e-3, 1.0);
    setup.parameters[2].lower = 1e-3;
    setup.parameters[2].upper = 1;
  }

  std::vector<HistoryEvaluator> evaluators;
  std::vector<detail::ResidualBlock> blocks;
  for (const auto& run : runs) {
    evaluators.push_back({&model, &run, setup.parametrisation, options.ode_tolerance});
    blocks.push_back({run.times.size(), [evaluator = evaluators.back()](const double* theta,
                                                                         double* r) {
                        return evaluator.residuals(theta, r);
                      }});
  }
  const auto result = detail::solve_least_squares(setup.parameters, blocks,
                                                  {options.max_iterations, options.threads});
  CampaignModelFit campaign_fit;
  campaign_fit.fit = to_model_fit(setup, result, options.confidence_level);
  campaign_fit.formula = model.formula;
  campaign_fit.reference = model.reference;
  campaign_fit.damping_name = model.damping_name;
  campaign_fit.damping_unit = model.damping_unit;
  std::vector<FitQuality> parts;
  const ModelFit& fit = campaign_fit.fit;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const FemRun& fem = *runs[i].run;
    RunResidual residual{fem.source, fem.impact_velocity,
                         evaluators[i].quality(result.theta.data()),
                         predict(model, fem, fit.stiffness.value, fit.exponent.value,
                                 fit.parameter.value, options.ode_tolerance)};
    parts.push_back(residual.quality);
    campaign_fit.runs.push_back(residual);
  }
  campaign_fit.fit.quality = combine(parts);
  if (!fit.converged)
    problems.push_back(
        {model.name, "convergence",
         "the campaign fit of " + model.name +
             (fixed_exponent && !model.required_exponent
                  ? " with n fixed at " + format_number(*exponent)
                  : std::string()) +
             " did not converge: " + fit.solver_message});
  return campaign_fit;
}

} // namespace

Calibration calibrate(const std::vector<FemRun>& runs, const CalibrationOptions& options) {
  if (!(options.confidence_level > 0 && options.confidence_level < 1))
    throw reduced::InvalidInput("confidence_level", "the confidence level must be in (0, 1)");
  if (options.max_iterations < 1)
    throw reduced::InvalidInput("max_iterations", "the iteration limit must be at least 1");
  std::vector<ContactModel> laws;
  for (const auto& name : options.laws) laws.push_back(comparison_model(name));

  Calibration calibration;
  calibration.confidence_level = options.confidence_level;
  Progress progress(options.progress);

  std::vector<PreparedRun> prepared;
  for (const auto& run : runs) prepared.push_back(prepare(run));
  for (std::size_t i = 0; i < prepared.size(); ++i) {
    progress.start();
    calibration.runs.push_back(calibrate_run(prepared[i], options, calibration.problems));
    progress("run " + std::to_string(i + 1) + "/" + std::to_string(runs.size()) + " (V = " +
             format_number(runs[i].impact_velocity) + " m/s): restitution, loading and "
             "force-history fits done in " + progress.elapsed());
  }

  // The campaign needs two distinct velocities to tell a constant b from a constant e.
  CampaignCalibration& campaign = calibration.campaign;
  for (const auto& run : runs) {
    const bool known = std::any_of(campaign.velocities.begin(), campaign.velocities.end(),
                                   [&](double v) {
                                     return std::abs(v - run.impact_velocity) <=
                                            1e-6 * run.impact_velocity;
                                   });
    if (!known) campaign.velocities.push_back(run.impact_velocity);
  }
  std::sort(campaign.velocities.begin(), campaign.velocities.end());
  if (campaign.velocities.size() < 2) {
    campaign.reason =
        runs.empty() ? "no usable run"
                     : "the runs have a single impact velocity (" +
                           format_number(campaign.velocities.front()) +
                           " m/s); a campaign fit needs at least two distinct velocities to "
                           "tell how the damping depends on the velocity";
    return calibration;
  }

  CampaignStart start;
  std::vector<double> approaches, velocities, masses, restitutions;
  for (const auto& run : runs) {
    approaches.push_back(run.approach_max);
    velocities.push_back(run.impact_velocity);
    masses.push_back(run.mass);
    restitutions.push_back(run.restitution);
  }
  start.reference_approach = geometric_mean(approaches);
  start.velocity = geometric_mean(velocities);
  start.mass = median(masses);
  start.restitution = std::min(median(restitutions), 1.0);
  std::vector<double> log_forces, exponents, dampings;
  for (const auto& run : calibration.runs) {
    const auto& fit = run.history ? run.history : run.loading;
    if (!fit) continue;
    log_forces.push_back(std::log(fit->stiffness.value) +
                         fit->exponent.value * std::log(start.reference_approach));
    exponents.push_back(fit->exponent.value);
    dampings.push_back(run.history ? run.history->parameter.value : run.damping_from_restitution);
  }
  start.log_reference_force = median(log_forces);
  start.exponent = median(exponents);
  if (!std::isfinite(start.log_reference_force)) {
    start.exponent = 1.5;
    start.log_reference_force = std::log(median(std::vector<double>{runs.front().force_max}));
  }

  progress.start();
  campaign.hunt_crossley = fit_campaign_model(hunt_crossley_model(), prepared, start,
                                              median(dampings), options, calibration.problems);
  progress("campaign: hunt-crossley fitted to " + std::to_string(runs.size()) + " runs in " +
           progress.elapsed());
  // The comparison laws start from the Hunt–Crossley elastic part.
  const ModelFit& hc = campaign.hunt_crossley->fit;
  if (hc.stiffness.value > 0 && std::isfinite(hc.exponent.value)) {
    start.exponent = hc.exponent.value;
    start.log_reference_force =
        std::log(hc.stiffness.value) + hc.exponent.value * std::log(start.reference_approach);
  }
  // Hunt–Crossley with n at the Hertz value: its c (N/m^1.5) is the one to compare with the
  // Hertz stiffness. Starts from the free fit's F_ref and b.
  progress.start();
  campaign.hunt_crossley_hertz_exponent =
      fit_campaign_model(hunt_crossley_model(), prepared, start, hc.parameter.value, options,
                         calibration.problems, hertz_exponent);
  progress("campaign: hunt-crossley with n = " + format_number(hertz_exponent) +
           " fitted in " + progress.elapsed());
  for (const auto& law : laws) {
    progress.start();
    try {
      campaign.comparison_laws.push_back(
          fit_campaign_model(law, prepared, start, nan, options, calibration.problems));
      progress("campaign: " + law.name + " fitted in " + progress.elapsed());
    } catch (const std::exception& error) {
      calibration.problems.push_back(
          {law.name, "convergence", "the campaign fit of " + law.name + " failed: " + error.what()});
    }
  }
  campaign.fitted = true;
  return calibration;
}

} // namespace impact::postprocess
