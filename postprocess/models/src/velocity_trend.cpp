#include "impact_postprocess/models/velocity_trend.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <cstdio>

namespace impact::postprocess {

namespace {

// Least squares of ln y on ln V over the runs with 0 < e < 1; y = 1 - e or e.
std::optional<PowerLawTrend> log_log_fit(const std::vector<double>& velocity,
                                         const std::vector<double>& restitution, double level,
                                         bool of_loss) {
  std::vector<double> x, y;
  for (std::size_t i = 0; i < velocity.size() && i < restitution.size(); ++i)
    if (velocity[i] > 0 && restitution[i] > 0 && restitution[i] < 1) {
      x.push_back(std::log(velocity[i]));
      y.push_back(std::log(of_loss ? 1 - restitution[i] : restitution[i]));
    }
  const std::size_t n = x.size();
  if (n < 3) return std::nullopt;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i] / double(n);
    my += y[i] / double(n);
  }
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 0)) return std::nullopt; // a single velocity
  const double slope = sxy / sxx;
  const double intercept = my - slope * mx;
  double squares = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - intercept - slope * x[i];
    squares += r * r;
  }
  const double error = std::sqrt(squares / double(n - 2) / sxx);
  const boost::math::students_t distribution{double(n - 2)};
  const double t = boost::math::quantile(distribution, 0.5 + level / 2);
  return PowerLawTrend{slope, error, slope - t * error, slope + t * error, std::exp(intercept),
                       n,     level};
}

} // namespace

std::optional<PowerLawTrend> fit_restitution_trend(const std::vector<double>& velocity,
                                                   const std::vector<double>& restitution,
                                                   double level) {
  return log_log_fit(velocity, restitution, level, true);
}

std::optional<PowerLawTrend> fit_restitution_power_law(const std::vector<double>& velocity,
                                                       const std::vector<double>& restitution,
                                                       double level) {
  return log_log_fit(velocity, restitution, level, false);
}

bool follows_plastic_family(const PowerLawTrend& restitution_trend) {
  // The nearest reference, as for the loss trend: -1/4 against 0 (a constant restitution).
  return std::abs(restitution_trend.exponent - plastic_restitution_slope) <
         std::abs(restitution_trend.exponent);
}

const std::vector<ReferenceSlope>& reference_slopes() {
  static const std::vector<ReferenceSlope> slopes = {
      {"Hunt–Crossley with constant b", 1.0},
      {"Kuwabara–Kono / Brilliantov (viscoelastic sphere)", 0.2},
      {"constant restitution (the e-parametrised maps)", 0.0}};
  return slopes;
}

const ReferenceSlope& nearest_reference(const PowerLawTrend& trend) {
  const ReferenceSlope* nearest = nullptr;
  for (const auto& reference : reference_slopes())
    if (!nearest ||
        std::abs(reference.slope - trend.exponent) < std::abs(nearest->slope - trend.exponent))
      nearest = &reference;
  return *nearest;
}

} // namespace impact::postprocess
