#include "impact_reduced/liggghts_thornton.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <string>

namespace impact::reduced {

namespace {

constexpr double pi = 3.14159265358979323846;

// 1 - (1 - s)^(5/2) for 0 <= s <= 1, without cancellation for small s.
double five_halves_drop(double s) {
  return -std::expm1(2.5 * std::log1p(-s));
}

} // namespace

LiggghtsThorntonImpact::LiggghtsThorntonImpact(const ThorntonParameters& parameters,
                                               double velocity)
    : thornton_(parameters, velocity), response_(thornton_.response()) {
  if (thornton_.velocity_ratio() <= 1) return; // Hertz's impact: no plastic loading
  const double mass = parameters.mass;
  const double k = thornton_.contact().hertz_stiffness();
  const double x_max = response_.approach_max, f_max = response_.force_max;
  const double peak_hertz = k * std::pow(x_max, 1.5); // > F* once the contact has yielded
  const double separation = std::pow(std::max(peak_hertz - f_max, 0.0) / k, 2.0 / 3.0);
  const double u_s = std::sqrt(x_max - separation);

  // W(u) / u^2: the work of F_U from x = x_max - u^2 to x_max, divided by u^2.
  const double a = f_max - peak_hertz, b = 0.4 * k * std::pow(x_max, 1.5);
  const auto work_per_u2 = [=](double u) {
    const double s = u * u / x_max;
    return s > 0 ? a + b * five_halves_drop(s) / s : f_max;
  };
  const double stored = u_s * u_s * work_per_u2(u_s);
  const double rebound = std::sqrt(2 * stored / mass);
  const auto inverse_speed = [=](double u) { return 2 / std::sqrt(2 * work_per_u2(u) / mass); };
  const double unloading_time =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(inverse_speed, 0.0, u_s, 15,
                                                                    1e-15);

  response_.residual_approach = separation;
  response_.contact_time = response_.compression_time + unloading_time;
  response_.rebound_velocity = -rebound;
  response_.restitution = rebound / velocity;
  response_.dissipated_energy = 0.5 * mass * (velocity * velocity - rebound * rebound);
}

double LiggghtsThorntonImpact::unloading_force(double approach) const {
  const double x_max = response_.approach_max;
  if (!(approach >= 0 && approach <= x_max))
    throw InvalidInput("approach", "approach must lie in [0, " + std::to_string(x_max) +
                                       "] m (the compression of this impact), got " +
                                       std::to_string(approach));
  const double k = thornton_.contact().hertz_stiffness();
  const double force = response_.force_max - k * (std::pow(x_max, 1.5) - std::pow(approach, 1.5));
  return force > 0 ? force : 0.0;
}

double liggghts_yield_ratio(double yield_pressure, double contact_modulus) {
  require_positive("yield_pressure", yield_pressure);
  require_positive("contact_modulus", contact_modulus);
  const double ratio = pi * yield_pressure / (2 * contact_modulus);
  if (ratio > 1)
    throw InvalidInput("yield_pressure",
                       "yield_pressure must be at most 2 E* / pi = " +
                           std::to_string(2 * contact_modulus / pi) +
                           " Pa for a LIGGGHTS coefficientYieldRatio in [0, 1], got " +
                           std::to_string(yield_pressure));
  return ratio;
}

} // namespace impact::reduced
