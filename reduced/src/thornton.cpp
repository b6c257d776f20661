#include "impact_reduced/thornton.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/contact_formulas.hpp"

#include <boost/math/special_functions/beta.hpp>

#include <cmath>

namespace impact::reduced {

namespace {

constexpr double pi = 3.14159265358979323846;

// (1 + d)^(3/2) - 1 - 3 d / 2 without cancellation: its binomial series for small d.
double plastic_excess(double d) {
  if (d > 0.125) return std::pow(1 + d, 1.5) - 1 - 1.5 * d;
  double coefficient = 0.375; // binomial(3/2, 2)
  double power = d * d;
  double sum = 0;
  for (int k = 2; k < 60 && std::abs(coefficient * power) > 1e-18 * std::abs(sum); ++k) {
    sum += coefficient * power;
    coefficient *= (1.5 - k) / (k + 1);
    power *= d;
  }
  return sum;
}

} // namespace

ThorntonContact::ThorntonContact(double radius, double contact_modulus, double yield_pressure)
    : radius_(radius), contact_modulus_(contact_modulus), yield_pressure_(yield_pressure) {
  require_positive("radius", radius);
  require_positive("contact_modulus", contact_modulus);
  require_positive("yield_pressure", yield_pressure);
  yield_approach_ = reduced::yield_approach(yield_pressure, contact_modulus, radius);
  yield_force_ = reduced::yield_force(yield_pressure, contact_modulus, radius);
  plastic_stiffness_ = pi * yield_pressure * radius;
  hertz_stiffness_ = hertz_coefficient(contact_modulus, radius);
}

double ThorntonContact::loading_force(double approach) const {
  if (approach <= yield_approach_) return hertz_stiffness_ * std::pow(approach, 1.5);
  return yield_force_ + plastic_stiffness_ * (approach - yield_approach_);
}

double ThorntonContact::loading_work(double approach) const {
  if (approach <= yield_approach_) return 0.4 * hertz_stiffness_ * std::pow(approach, 2.5);
  const double plastic = approach - yield_approach_;
  return 0.4 * yield_force_ * yield_approach_ +
         plastic * (yield_force_ + 0.5 * plastic_stiffness_ * plastic);
}

double ThorntonContact::loading_stiffness(double approach) const {
  if (approach < yield_approach_) return 1.5 * hertz_stiffness_ * std::sqrt(approach);
  return plastic_stiffness_;
}

std::pair<double, double> ThorntonContact::loading_force_and_stiffness(double approach) const {
  if (approach < yield_approach_)
    return {hertz_stiffness_ * std::pow(approach, 1.5),
            1.5 * hertz_stiffness_ * std::sqrt(approach)};
  return {loading_force(approach), plastic_stiffness_};
}

double ThorntonContact::loading_approach(double work) const {
  if (!(work > 0)) return 0.0;
  const double yield_work = 0.4 * yield_force_ * yield_approach_;
  if (work <= yield_work) return std::pow(2.5 * work / hertz_stiffness_, 0.4);
  // F_y d + k d^2 / 2 = W - W_y, the positive root written without cancellation.
  const double excess = work - yield_work;
  return yield_approach_ + 2 * excess /
                               (yield_force_ + std::sqrt(yield_force_ * yield_force_ +
                                                         2 * plastic_stiffness_ * excess));
}

double ThorntonContact::loading_work_below(double approach_max, double distance) const {
  if (!(distance > 0)) return 0.0;
  if (approach_max <= yield_approach_)
    return detail::hertz_work_below(hertz_stiffness_, approach_max, distance);
  // Plastic branch: F_y d + (k/2) (p_max^2 - p^2) = d (F_y + k (p_max - d/2)), p = x - x_y.
  const double plastic = approach_max - yield_approach_;
  if (distance <= plastic)
    return distance * (yield_force_ + plastic_stiffness_ * (plastic - 0.5 * distance));
  return plastic * (yield_force_ + 0.5 * plastic_stiffness_ * plastic) +
         detail::hertz_work_below(hertz_stiffness_, yield_approach_, distance - plastic);
}

double ThorntonContact::unloading_radius(double approach_max) const {
  require_positive("approach_max", approach_max);
  if (approach_max <= yield_approach_) return radius_;
  // a_p^2 = a_y^2 (1 + delta), F* = F_y (1 + 3 delta / 2): R_p = R (1 + delta)^(3/2) / (1 + 3/2 delta).
  const double delta = (approach_max - yield_approach_) / yield_approach_;
  return radius_ * std::pow(1 + delta, 1.5) / (1 + 1.5 * delta);
}

HertzianUnloading ThorntonContact::unloading(double approach_max) const {
  require_positive("approach_max", approach_max);
  if (approach_max <= yield_approach_) return {hertz_stiffness_, 0.0};
  const double delta = (approach_max - yield_approach_) / yield_approach_;
  const double unloading_radius = radius_ * std::pow(1 + delta, 1.5) / (1 + 1.5 * delta);
  return {hertz_coefficient(contact_modulus_, unloading_radius),
          yield_approach_ * plastic_excess(delta) / std::sqrt(1 + delta)};
}

ThorntonImpact::ThorntonImpact(const ThorntonParameters& parameters, double velocity)
    : parameters_(parameters),
      velocity_(velocity),
      contact_(parameters.radius, parameters.contact_modulus, parameters.yield_pressure) {
  require_positive("mass", parameters.mass);
  require_positive("velocity", velocity);
  const double mass = parameters.mass;
  yield_velocity_ = reduced::yield_velocity(parameters.yield_pressure, parameters.contact_modulus,
                                            parameters.radius, mass);
  const double c = contact_.hertz_stiffness();
  const double hertz_factor = 0.4 * boost::math::beta(0.4, 0.5); // (2/5) B(2/5, 1/2)
  // The Hertz approach x_H that the velocity would reach elastically, and its phase time.
  const double hertz_approach = hertz_peak_approach(c, mass, velocity);

  ElasticPlasticImpactResponse& out = response_;
  if (velocity <= yield_velocity_) {
    out.approach_max = hertz_approach;
    out.force_max = c * std::pow(hertz_approach, 1.5);
    out.residual_approach = 0;
    out.compression_time = hertz_factor * hertz_approach / velocity;
    out.contact_time = 2 * out.compression_time;
    out.rebound_velocity = -velocity;
    out.restitution = 1;
    out.dissipated_energy = 0;
    return;
  }
  const double x_y = contact_.yield_approach();
  const double f_y = contact_.yield_force();
  const double v_y = yield_velocity_;
  const double r = v_y / velocity;
  // 1/r^2 - 1 = (V - V_y)(V + V_y) / V_y^2, without cancellation.
  const double excess = (velocity - v_y) * (velocity + v_y) / (v_y * v_y);
  const double delta = 2 * excess / (2.5 + std::sqrt(6.25 + 7.5 * excess));
  out.approach_max = x_y * (1 + delta);
  out.force_max = f_y * (1 + 1.5 * delta);
  out.restitution = r * (1 + 1.5 * delta) / std::pow(1 + delta, 0.25);
  out.residual_approach = x_y * plastic_excess(delta) / std::sqrt(1 + delta);
  out.rebound_velocity = -out.restitution * velocity;
  out.dissipated_energy =
      0.5 * mass * velocity * velocity * (1 - out.restitution) * (1 + out.restitution);

  // Hertz phase up to x_y: t = (x_H / V) (2/5) B(r^2; 2/5, 1/2) (incomplete Beta, since
  // (x_y / x_H)^(5/2) = r^2).
  const double hertz_time = 0.4 * hertz_approach / velocity * boost::math::beta(0.4, 0.5, r * r);
  // Plastic phase: harmonic about x_y - F_y / k, from x_y at speed sqrt(V^2 - V_y^2) to rest.
  const double k = contact_.plastic_stiffness();
  const double omega = std::sqrt(k / mass);
  const double speed_at_yield = std::sqrt((velocity - v_y) * (velocity + v_y));
  const double plastic_time = std::atan2(speed_at_yield, omega * f_y / k) / omega;
  out.compression_time = hertz_time + plastic_time;
  // Unloading: Hertz on R_p over x_max - x_p at rebound speed e V.
  const double elastic_approach = x_y * (1 + 1.5 * delta) / std::sqrt(1 + delta);
  out.contact_time =
      out.compression_time + hertz_factor * elastic_approach / (out.restitution * velocity);
}

double thornton_restitution_formula(double yield_velocity_ratio) {
  require_positive("velocity_ratio", yield_velocity_ratio);
  const double r = yield_velocity_ratio;
  if (r >= 1) return 1.0;
  return std::sqrt(6 * std::sqrt(3.0) / 5) * std::sqrt(1 - r * r / 6) *
         std::pow(r / (r + 2 * std::sqrt(6.0 / 5 - r * r / 5)), 0.25);
}

} // namespace impact::reduced
