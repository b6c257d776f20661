// The shared fit machinery of fit_model.hpp: preparing a run, the estimates of a fit.

#include "fit_model.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace impact::postprocess::detail {

PreparedRun prepare(const FemRun& run) {
  PreparedRun prepared{&run, {}, {}, run.force_max,
                       {},   {}, 0,  1 - run.restitution * run.restitution};
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
  // Samples of each simulated impact, interpolated (cubic Hermite) at the FEM's instants: as
  // many as the FEM has in contact, at least 400. Four times as many (the former rule) cost
  // 2.6 times as much in the Kuwabara–Kono fits (each sample is a re-taken ODE step) and moved
  // no fitted parameter of either study by more than 5.4e-4 relative (b of
  // hunt-crossley-thornton in the plastic study, 0.2 % of its 95 % interval's half-width), no
  // ranking score by more than 6.7e-6 relative, and no rank (2026-12-05).
  prepared.points = std::clamp<std::size_t>(in_contact, 400, 20000);
  return prepared;
}

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

// ModelFit from the solver's result; quality filled by the caller.
ModelFit to_model_fit(const FitSetup& setup, const LeastSquaresResult& result,
                      double confidence_level) {
  const double* theta = result.theta.data();
  const Parametrisation& map = setup.parametrisation;
  const std::size_t k = map.size();
  ModelFit fit;
  fit.model = setup.model->name;
  fit.parameter_name = setup.model->parameter_name();
  fit.parameter_unit = setup.model->parameter_unit();
  fit.stiffness_fixed = setup.parameters[0].fixed;
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

FitParameter exponent_parameter(double initial, bool fixed) {
  FitParameter parameter{initial};
  parameter.lower = 0.3;
  parameter.upper = 4;
  parameter.fixed = fixed;
  parameter.step = 1e-6;
  return parameter;
}

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

} // namespace impact::postprocess::detail
