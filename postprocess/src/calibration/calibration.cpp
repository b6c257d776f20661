// The fits of calibration.hpp. Every fit works on the internal parameters
//     theta = (ln F_ref, n, p / p_scale, extra...),   F_ref = c x_ref^n,
// with x_ref a typical approach of the data: ln c and n are almost perfectly correlated
// (ln F = ln c + n ln x with ln x ~ -10), ln F_ref and n are not, so the solver and the
// covariance work on a well-conditioned problem; the covariance is mapped back to
// (c, n, p, ...) by the Jacobian of that change of variables.

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/same_value.hpp"

#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"
#include "calibration/least_squares.hpp"
#include "calibration/ranking.hpp"
#include "models/simulated_force.hpp"

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

namespace detail {

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

} // namespace detail

using detail::combine;
using detail::rank_campaign;

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
  double energy_loss;          // 1 - e^2 of the FEM
};

PreparedRun prepare(const FemRun& run) {
  PreparedRun prepared{&run, {}, {}, run.force_max, {}, {}, 0,
                       1 - run.restitution * run.restitution};
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

// theta = (ln F_ref, n, p_1 / scale_1, p_2 / scale_2, ...).
struct Parametrisation {
  double reference_approach;
  std::vector<double> scales; // of the dissipation parameters

  double stiffness(const double* theta) const {
    return std::exp(theta[0] - theta[1] * std::log(reference_approach));
  }
  double exponent(const double* theta) const { return theta[1]; }
  std::vector<double> dissipation(const double* theta) const {
    std::vector<double> values(scales.size());
    for (std::size_t i = 0; i < scales.size(); ++i) values[i] = theta[2 + i] * scales[i];
    return values;
  }
  double log_reference_force(double stiffness, double exponent) const {
    return std::log(stiffness) + exponent * std::log(reference_approach);
  }
  std::size_t size() const { return 2 + scales.size(); }
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
  const std::size_t k = map.size();
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
  // d(c, n, p, ...) / d theta: c depends on theta_0 and theta_1, the rest are scaled.
  std::vector<double> g(k * k, 0.0);
  g[0 * k + 0] = c;
  g[0 * k + 1] = -c * std::log(map.reference_approach);
  g[1 * k + 1] = 1;
  for (std::size_t i = 2; i < k; ++i) g[i * k + i] = map.scales[i - 2];
  std::vector<double> covariance(k * k, nan);
  const bool have_covariance = result.covariance.size() == k * k;
  if (have_covariance)
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = 0; j < k; ++j) {
        double sum = 0;
        for (std::size_t a = 0; a < k; ++a)
          for (std::size_t b = 0; b < k; ++b)
            sum += g[i * k + a] * result.covariance[a * k + b] * g[j * k + b];
        covariance[i * k + j] = sum;
      }
  fit.covariance = covariance;
  const std::size_t dof = result.residual_count > result.free_parameters
                              ? result.residual_count - result.free_parameters
                              : 0;
  const double quantile = student_quantile(confidence_level, dof);
  const std::vector<double> dissipation = map.dissipation(theta);
  fit.stiffness = estimate(c, covariance[0], quantile);
  fit.exponent = estimate(map.exponent(theta), covariance[1 * k + 1], quantile);
  fit.parameter = estimate(dissipation[0], covariance[2 * k + 2], quantile);
  for (std::size_t i = 1; i < dissipation.size(); ++i) {
    const auto& spec = setup.model->extra_parameters.at(i - 1);
    fit.extra.push_back({spec.name, spec.unit,
                         estimate(dissipation[i], covariance[(i + 2) * k + i + 2], quantile)});
  }
  fit.correlation.assign(k * k, nan);
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      const double scale = std::sqrt(covariance[i * k + i] * covariance[j * k + j]);
      fit.correlation[i * k + j] = scale > 0 ? covariance[i * k + j] / scale : nan;
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


// ---- Force histories and energy loss of a model ---------------------------------------

struct HistoryEvaluator {
  const ContactModel* model;
  const PreparedRun* run;
  Parametrisation map;
  double tolerance;

  bool force(const double* theta, double* force) const {
    const double c = map.stiffness(theta);
    const double n = map.exponent(theta);
    if (!(std::isfinite(c) && c > 0 && n > 0)) return false;
    const std::vector<double> dissipation = map.dissipation(theta);
    for (double p : dissipation)
      if (!std::isfinite(p)) return false;
    const reduced::ContactSetup setup{run->run->mass, c, n};
    double damping;
    try {
      damping = model->damping(dissipation, run->run->impact_velocity, setup);
    } catch (const std::exception&) {
      return false;
    }
    if (model->plastic_contact) try {
        return detail::simulate_plastic_force(*model->plastic_contact(damping, setup),
                                              run->run->mass, run->run->impact_velocity,
                                              run->times, run->points, tolerance, force);
      } catch (const std::exception&) {
        return false;
      }
    if (model->hunt_crossley_force())
      return detail::simulate_hunt_crossley_force(model->force_law(damping, setup), setup, damping,
                                                  run->run->impact_velocity, run->times,
                                                  run->points, force);
    return detail::simulate_force(model->force_law(damping, setup), run->run->mass,
                                  run->run->impact_velocity, run->times, run->points, tolerance,
                                  model->contact_end, force);
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

  // The run's energy-loss residual: weight sqrt(N) (L_model - L_FEM) / L_FEM, so that it
  // counts against the run's N force residuals as a relative error against their RMS.
  bool energy_residual(const double* theta, double weight, double* residual) const {
    const double restitution =
        predict_restitution(*model, run->run->mass, run->run->impact_velocity,
                            map.stiffness(theta), map.exponent(theta), map.dissipation(theta),
                            tolerance);
    if (!std::isfinite(restitution)) return false;
    const double loss = 1 - restitution * restitution;
    *residual = weight * std::sqrt(double(run->times.size())) * (loss - run->energy_loss) /
                run->energy_loss;
    return true;
  }
};

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
  detail::ResidualBlock block{run.times.size(), [evaluator](const double* theta, double* r) {
                                return evaluator.residuals(theta, r);
                              }};
  const auto result = detail::solve_least_squares(setup.parameters, {block},
                                                  {options.max_iterations, 1});
  ModelFit fit = to_model_fit(setup, result, options.confidence_level);
  fit.quality = evaluator.quality(result.theta.data());
  if (!fit.converged)
    problems.push_back({fem.source, ProblemKind::convergence,
                        "the force-history fit did not converge: " + fit.solver_message});
  return fit;
}

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
  if (result.history)
    result.history_prediction =
        predict_impact(hunt_crossley_model(), fem.mass, fem.impact_velocity,
                       result.history->stiffness.value, result.history->exponent.value,
                       result.history->dissipation(), options.ode_tolerance);
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

bool same_velocity(double a, double b) { return same_value(a, b); }

struct CampaignStart {
  double reference_approach;
  double log_reference_force;
  double exponent;
  double restitution;  // median measured
  double velocity;     // geometric mean
  double mass;         // median
};

// What distinguishes the campaign fits of one model.
struct CampaignFitRequest {
  std::string key;
  std::string label;
  std::optional<double> exponent;  // n held here (else the model's required one, else free)
  double energy_weight = 0;
  double initial_damping = nan;    // else from the median restitution
  std::vector<double> initial_extra;
};

// The residual blocks of `runs` for parameters mapped by `setup`.
std::vector<detail::ResidualBlock> residual_blocks(const std::vector<HistoryEvaluator>& evaluators,
                                                   double energy_weight) {
  std::vector<detail::ResidualBlock> blocks;
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
             : (start.restitution < 1 ? model.damping_for_restitution(
                                            start.restitution, start.velocity, reference_setup)
                                      : 0.0);
  }
  FitSetup setup{&model, {start.reference_approach, {scale}}, {}};
  setup.parameters = {{start.log_reference_force}, exponent_parameter(n0, fixed_exponent),
                      {p0 / scale}};
  if (model.parameter == DissipationParameter::damping) {
    setup.parameters[2].lower = 0;
  } else {
    setup.parameters[2].initial = std::clamp(p0, 1e-3, 1.0);
    setup.parameters[2].lower = 1e-3;
    setup.parameters[2].upper = 1;
  }
  for (std::size_t i = 0; i < model.extra_parameters.size(); ++i) {
    const auto& spec = model.extra_parameters[i];
    setup.parametrisation.scales.push_back(1.0);
    detail::FitParameter parameter{i < request.initial_extra.size() ? request.initial_extra[i]
                                                                    : spec.initial};
    parameter.lower = spec.lower;
    parameter.upper = spec.upper;
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
// from the full fit `theta`), and the jackknife of the parameters over those fits.
void add_held_out_fits(CampaignModelFit& campaign_fit, const ContactModel& model,
                       const CampaignFitRequest& request, const FitSetup& setup,
                       const std::vector<double>& theta, const std::vector<PreparedRun>& runs,
                       const std::vector<double>& velocities, const CalibrationOptions& options,
                       std::vector<Problem>& problems) {
  const std::string what =
      "the campaign fit of " + request.label + " (" + request.key + ")";
  std::vector<detail::FitParameter> restart = setup.parameters;
  for (std::size_t j = 0; j < restart.size(); ++j) restart[j].initial = theta[j];
  for (double left_out : velocities) {
    const auto others = evaluators_of(model, setup, runs, options, [left_out](const PreparedRun& run) {
      return !same_velocity(run.run->impact_velocity, left_out);
    });
    const auto held = detail::solve_least_squares(
        restart, residual_blocks(others, request.energy_weight),
        {options.max_iterations, options.threads});
    const ModelFit held_fit = to_model_fit(setup, held, options.confidence_level);
    campaign_fit.held_out.push_back({left_out, held_fit.parameter_values(), held.converged});
    if (!held.converged)
      problems.push_back({request.key, ProblemKind::convergence,
                          what + " without V = " + format_number(left_out) +
                              " m/s did not converge: " + held.message});
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
CampaignModelFit fit_campaign_model(const ContactModel& model, const CampaignFitRequest& request,
                                    const std::vector<PreparedRun>& runs,
                                    const std::vector<double>& velocities,
                                    const CampaignStart& start, const CalibrationOptions& options,
                                    std::vector<Problem>& problems) {
  const FitSetup setup = campaign_fit_setup(model, request, start);
  const std::vector<HistoryEvaluator> evaluators =
      evaluators_of(model, setup, runs, options, [](const PreparedRun&) { return true; });
  const auto result =
      detail::solve_least_squares(setup.parameters, residual_blocks(evaluators, request.energy_weight),
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
  const std::string what =
      "the campaign fit of " + request.label + " (" + request.key + ")";
  if (!fit.converged)
    problems.push_back({request.key, ProblemKind::convergence, what + " did not converge: " +
                                                        fit.solver_message});

  if (velocities.size() >= 3)
    add_held_out_fits(campaign_fit, model, request, setup, result.theta, runs, velocities, options,
                      problems);
  return campaign_fit;
}

// A model evaluated with given parameters at every run: no fit.
ReferenceModel reference_model(std::string key, std::string label, const ContactModel& model,
                               std::string basis, double stiffness, double exponent,
                               std::vector<double> dissipation,
                               const std::vector<PreparedRun>& runs,
                               const CalibrationOptions& options) {
  ReferenceModel reference{std::move(key),    std::move(label), model.name,
                           std::move(basis),  stiffness,        exponent,
                           dissipation,       model.parameter_name(), model.parameter_unit(),
                           {}};
  Parametrisation map{1.0, std::vector<double>(dissipation.size(), 1.0)};
  std::vector<double> theta{map.log_reference_force(stiffness, exponent), exponent};
  theta.insert(theta.end(), dissipation.begin(), dissipation.end());
  for (const auto& run : runs) {
    const FemRun& fem = *run.run;
    const HistoryEvaluator evaluator{&model, &run, map, options.ode_tolerance};
    const ImpactPrediction prediction =
        predict_impact(model, fem.mass, fem.impact_velocity, stiffness, exponent, dissipation,
                       options.ode_tolerance);
    reference.runs.push_back({fem.source, fem.impact_velocity, evaluator.quality(theta.data()),
                              prediction, prediction});
  }
  return reference;
}

void add_reference_models(CampaignCalibration& campaign, const std::vector<FemRun>& fem_runs,
                          const std::vector<PreparedRun>& runs,
                          const CalibrationOptions& options) {
  const ScenarioMaterials materials = scenario_materials(fem_runs);
  campaign.hertz_stiffness = materials.hertz_stiffness;
  campaign.hertz_basis = materials.hertz_basis;
  campaign.material_dissipative_constant = materials.dissipative_constant;
  campaign.material_basis = materials.dissipative_basis;
  campaign.published_damping = options.published_damping;
  const double c = materials.hertz_stiffness;
  const ContactModel hunt_crossley = hunt_crossley_model();
  campaign.reference_models.push_back(
      reference_model(std::string(model_keys::hertz), "Hertz (b = 0)", hunt_crossley,
                      "elastic Hertz impact: n = 3/2, c = " + materials.hertz_basis +
                          ", no damping",
                      c, hertz_exponent, {0.0}, runs, options));
  campaign.reference_models.push_back(reference_model(
      std::string(model_keys::hunt_crossley_published), "Hunt–Crossley (b = " + format_number(options.published_damping) +
                                     " s/m)",
      hunt_crossley,
      "the published example: b = " + format_number(options.published_damping) +
          " s/m, n = 3/2, c = " + materials.hertz_basis,
      c, hertz_exponent, {options.published_damping}, runs, options));
  if (materials.dissipative_constant)
    campaign.reference_models.push_back(reference_model(
        std::string(model_keys::kuwabara_kono_material), "Kuwabara–Kono, no tension, A from the material (no fit)",
        comparison_model("kuwabara-kono-no-tension"),
        "no fit: c = " + materials.hertz_basis + ", n = 3/2, A = " +
            format_number(*materials.dissipative_constant) + " s from " +
            materials.dissipative_basis,
        c, hertz_exponent, {*materials.dissipative_constant}, runs, options));

  if (const auto thornton = material_thornton(fem_runs))
    campaign.reference_models.push_back(reference_model(
        std::string(model_keys::thornton_material), "Thornton, p_y = 1.6 Y from the material (no fit)",
        contact_model("thornton"), thornton->basis, thornton->stiffness, hertz_exponent,
        {thornton->yield_approach}, runs, options));
  if (const auto jackson_green = material_jackson_green(fem_runs))
    campaign.reference_models.push_back(reference_model(
        std::string(model_keys::jackson_green_material),
        "Jackson–Green, E*, Y, nu from the material (no fit)", jackson_green->model,
        jackson_green->basis, jackson_green->stiffness, hertz_exponent,
        {jackson_green->yield_strength}, runs, options));

  // The restitution maps as users apply them: the FEM's e at each run, c from Hertz.
  for (const auto& name : restitution_parametrised_laws()) {
    const ContactModel law = comparison_model(name);
    RestitutionMapEvaluation evaluation{name, law.formula, {}};
    for (const auto& run : runs) {
      const FemRun& fem = *run.run;
      evaluation.runs.push_back(
          {fem.source, fem.impact_velocity, fem.restitution,
           fem.restitution > 0 && fem.restitution <= 1
               ? predict_impact(law, fem.mass, fem.impact_velocity, c, hertz_exponent,
                                {fem.restitution}, options.ode_tolerance)
               : ImpactPrediction{{nan, nan, nan, nan, nan}, nan}});
    }
    campaign.restitution_maps.push_back(std::move(evaluation));
  }
}


} // namespace

std::vector<double> ModelFit::dissipation() const {
  std::vector<double> values{parameter.value};
  for (const auto& entry : extra) values.push_back(entry.estimate.value);
  return values;
}

std::vector<double> ModelFit::parameter_values() const {
  std::vector<double> values{stiffness.value, exponent.value};
  for (double p : dissipation()) values.push_back(p);
  return values;
}

std::vector<std::string> ModelFit::parameter_names() const {
  std::vector<std::string> names{"c", "n", parameter_name};
  for (const auto& entry : extra) names.push_back(entry.name);
  return names;
}

std::size_t ModelFit::free_parameters() const {
  return 1 + (exponent_fixed ? 0 : 1) + (parameter_fixed ? 0 : 1) + extra.size();
}

std::vector<const CampaignModelFit*> CampaignCalibration::models() const {
  std::vector<const CampaignModelFit*> all;
  for (const auto* fit : {&hunt_crossley, &hunt_crossley_energy, &hunt_crossley_hertz_exponent,
                          &hunt_crossley_velocity_damping})
    if (*fit) all.push_back(&**fit);
  for (const auto& law : comparison_laws) all.push_back(&law);
  return all;
}

const CampaignModelFit* CampaignCalibration::find(const std::string& key) const {
  for (const CampaignModelFit* model : models())
    if (model->key == key) return model;
  return nullptr;
}


namespace {

void check_options(const CalibrationOptions& options) {
  if (!(options.confidence_level > 0 && options.confidence_level < 1))
    throw reduced::InvalidInput("confidence_level", "the confidence level must be in (0, 1)");
  if (options.max_iterations < 1)
    throw reduced::InvalidInput("max_iterations", "the iteration limit must be at least 1");
  if (!(options.energy_weight >= 0) || !std::isfinite(options.energy_weight))
    throw reduced::InvalidInput("energy_weight", "the energy weight must be a number >= 0");
  if (!(options.published_damping >= 0) || !std::isfinite(options.published_damping))
    throw reduced::InvalidInput("published_damping", "the published damping must be >= 0 s/m");
}

// The campaign fits' start: typical approach, velocity, mass and restitution of the runs, and
// the median of the per-run fits of F_ref and n; `damping` the median per-run b.
CampaignStart campaign_start(const std::vector<FemRun>& runs,
                             const std::vector<RunCalibration>& calibrated, double& damping) {
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
  for (const auto& run : calibrated) {
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

  damping = median(dampings);
  return start;
}

} // namespace

Calibration calibrate(const std::vector<FemRun>& runs, const CalibrationOptions& options) {
  check_options(options);
  std::vector<std::string> left_out;
  const std::vector<ContactModel> laws = comparison_models(options.laws, runs, left_out);

  Calibration calibration;
  calibration.confidence_level = options.confidence_level;
  Progress progress(options.progress);
  for (const auto& name : left_out)
    progress("law " + name + " left out: the runs do not record the sphere radius and Poisson "
             "ratio it needs");

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
  campaign.energy_weight = options.energy_weight;
  add_reference_models(campaign, runs, prepared, options);
  for (const auto& run : runs) {
    const bool known = std::any_of(campaign.velocities.begin(), campaign.velocities.end(),
                                   [&](double v) { return same_velocity(v, run.impact_velocity); });
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

  double damping = nan;
  CampaignStart start = campaign_start(runs, calibration.runs, damping);

  const auto fit = [&](const ContactModel& model, const CampaignFitRequest& request) {
    progress.start();
    CampaignModelFit result = fit_campaign_model(model, request, prepared, campaign.velocities,
                                                 start, options, calibration.problems);
    progress("campaign: " + request.key + " fitted to " + std::to_string(runs.size()) +
             " runs" +
             (result.held_out.empty()
                  ? std::string()
                  : " and once without each of the " + std::to_string(result.held_out.size()) +
                        " velocities") +
             " in " + progress.elapsed());
    return result;
  };
  const ContactModel hunt_crossley = hunt_crossley_model();
  campaign.hunt_crossley = fit(hunt_crossley, {std::string(model_keys::hunt_crossley), "Hunt–Crossley, force histories",
                                               std::nullopt, 0, damping, {}});
  // The other fits start from the Hunt–Crossley elastic part and damping.
  const ModelFit& hc = campaign.hunt_crossley->fit;
  const double hc_damping = hc.parameter.value;
  if (hc.stiffness.value > 0 && std::isfinite(hc.exponent.value)) {
    start.exponent = hc.exponent.value;
    start.log_reference_force =
        std::log(hc.stiffness.value) + hc.exponent.value * std::log(start.reference_approach);
  }
  if (options.energy_weight > 0)
    campaign.hunt_crossley_energy =
        fit(hunt_crossley, {std::string(model_keys::hunt_crossley_energy),
                            "Hunt–Crossley, force histories and energy loss", std::nullopt,
                            options.energy_weight, hc_damping, {}});
  // Hunt–Crossley with n at the Hertz value: its c (N/m^1.5) is the one to compare with the
  // Hertz stiffness.
  campaign.hunt_crossley_hertz_exponent =
      fit(hunt_crossley, {std::string(model_keys::hunt_crossley_hertz_exponent),
                          "Hunt–Crossley with n = 3/2, force histories", hertz_exponent, 0,
                          hc_damping, {}});
  campaign.hunt_crossley_velocity_damping =
      fit(velocity_damped_hunt_crossley_model(),
          {std::string(model_keys::hunt_crossley_velocity_damping),
           options.energy_weight > 0 ? "Hunt–Crossley with b(V), force histories and energy loss"
                                     : "Hunt–Crossley with b(V), force histories",
           std::nullopt, options.energy_weight, hc_damping, {0.0}});
  for (const auto& law : laws) {
    try {
      campaign.comparison_laws.push_back(
          fit(law, {law.name, law.name + ", force histories", std::nullopt, 0, nan, {}}));
    } catch (const std::exception& error) {
      calibration.problems.push_back(
          {law.name, ProblemKind::convergence, "the campaign fit of " + law.name + " failed: " + error.what()});
    }
  }
  campaign.ranking = rank_campaign(campaign, calibration.runs);
  campaign.fitted = true;
  return calibration;
}

} // namespace impact::postprocess
