#include "impact_reduced/sphere_flat_fits.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "octave_work_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::reduced {

namespace {

constexpr double pi = 3.14159265358979323846;
// The end of the Hertz branch of Jackson-Green, omega* = 1.9.
constexpr double jackson_green_transition = 1.9;

void validate(const SphereFlatContact& contact) {
  require_positive("radius", contact.radius);
  require_positive("contact_modulus", contact.contact_modulus);
  require_positive("yield_strength", contact.yield_strength);
  require_open_interval("poisson_ratio", contact.poisson_ratio, -1.0, 0.5);
}

double hertz_load(double interference, const SphereFlatContact& contact) {
  return hertz_coefficient(contact.contact_modulus, contact.radius) * std::pow(interference, 1.5);
}

// B = 0.14 exp(23 Y / E*), the exponent of the contact radius's growth.
double jackson_green_b(const SphereFlatContact& contact) {
  return 0.14 * std::exp(23 * (contact.yield_strength / contact.contact_modulus));
}

// P / P_c of the Jackson-Green fit (omega* > 1.9) without validation, B given.
double jackson_green_fit(double ratio, const SphereFlatContact& contact, double c, double b) {
  const double yield_strain = contact.yield_strength / contact.contact_modulus;
  // a / R = sqrt(omega / R) (omega*/1.9)^(B/2), omega / R = omega* (pi C Y / (2 E*))^2.
  const double relative_radius = std::sqrt(ratio) * pi * c * yield_strain / 2 *
                                 std::pow(ratio / jackson_green_transition, b / 2);
  const double hardness_ratio = 2.84 * (1 - std::exp(-0.82 * std::pow(relative_radius, -0.7)));
  return std::exp(-0.25 * std::pow(ratio, 5.0 / 12.0)) * std::pow(ratio, 1.5) +
         4 * hardness_ratio / c * (1 - std::exp(-std::pow(ratio, 5.0 / 9.0) / 25)) * ratio;
}

// d(P / P_c) / d omega* of the fit (omega* > 1.9), differentiated term by term:
//   d/dw [exp(-w^(5/12) / 4) w^(3/2)] = exp(-w^(5/12) / 4) w^(1/2) (3/2 - (5/48) w^(5/12)),
//   d/dw [(4 H / C) G w] = (4 / C) (H' G w + H G' w + H G),  G = 1 - exp(-w^(5/9) / 25),
//   G' w = exp(-w^(5/9) / 25) w^(5/9) / 45,  a/R = rho ~ w^((1 + B) / 2),
//   H' w = -2.84 (0.82 * 0.7) rho^(-0.7) exp(-0.82 rho^(-0.7)) (1 + B) / 2.
double jackson_green_fit_slope(double ratio, const SphereFlatContact& contact, double c, double b) {
  const double yield_strain = contact.yield_strength / contact.contact_modulus;
  const double relative_radius = std::sqrt(ratio) * pi * c * yield_strain / 2 *
                                 std::pow(ratio / jackson_green_transition, b / 2);
  const double decay = std::exp(-0.82 * std::pow(relative_radius, -0.7));
  const double hardness_ratio = 2.84 * (1 - decay);
  const double hardness_slope_times_ratio =
      -2.84 * 0.82 * 0.7 * std::pow(relative_radius, -0.7) * decay * (1 + b) / 2;
  const double shape_decay = std::exp(-std::pow(ratio, 5.0 / 9.0) / 25);
  const double shape = 1 - shape_decay;
  const double shape_slope_times_ratio = shape_decay * std::pow(ratio, 5.0 / 9.0) / 45;
  const double hertz_like = std::exp(-0.25 * std::pow(ratio, 5.0 / 12.0)) * std::sqrt(ratio) *
                            (1.5 - 5.0 / 48.0 * std::pow(ratio, 5.0 / 12.0));
  return hertz_like + 4 / c *
                          (hardness_slope_times_ratio * shape +
                           hardness_ratio * shape_slope_times_ratio + hardness_ratio * shape);
}

// P / P_c and its slope in omega* at once (omega* > 1.9): the terms of jackson_green_fit and
// jackson_green_fit_slope evaluated once, each result formed exactly as there.
std::pair<double, double> jackson_green_fit_and_slope(double ratio,
                                                      const SphereFlatContact& contact, double c,
                                                      double b) {
  const double yield_strain = contact.yield_strength / contact.contact_modulus;
  const double relative_radius = std::sqrt(ratio) * pi * c * yield_strain / 2 *
                                 std::pow(ratio / jackson_green_transition, b / 2);
  const double radius_power = std::pow(relative_radius, -0.7);
  const double decay = std::exp(-0.82 * radius_power);
  const double hardness_ratio = 2.84 * (1 - decay);
  const double hardness_slope_times_ratio = -2.84 * 0.82 * 0.7 * radius_power * decay * (1 + b) / 2;
  const double power = std::pow(ratio, 5.0 / 9.0);
  const double shape_decay = std::exp(-power / 25);
  const double shape = 1 - shape_decay;
  const double shape_slope_times_ratio = shape_decay * power / 45;
  const double twelfth = std::pow(ratio, 5.0 / 12.0);
  const double hertz_decay = std::exp(-0.25 * twelfth);
  const double ratio_power =
      hertz_decay * std::pow(ratio, 1.5) + 4 * hardness_ratio / c * shape * ratio;
  const double hertz_like = hertz_decay * std::sqrt(ratio) * (1.5 - 5.0 / 48.0 * twelfth);
  const double slope =
      hertz_like + 4 / c *
                       (hardness_slope_times_ratio * shape +
                        hardness_ratio * shape_slope_times_ratio + hardness_ratio * shape);
  return {ratio_power, slope};
}

} // namespace

double jackson_green_critical_interference(const SphereFlatContact& contact) {
  validate(contact);
  const double ratio = pi * jackson_green_yield_coefficient(contact.poisson_ratio) *
                       contact.yield_strength / (2 * contact.contact_modulus);
  return ratio * ratio * contact.radius;
}

double jackson_green_critical_load(const SphereFlatContact& contact) {
  validate(contact);
  const double radius_ratio = contact.radius / contact.contact_modulus;
  const double pressure =
      jackson_green_yield_coefficient(contact.poisson_ratio) * pi * contact.yield_strength / 2;
  return 4.0 / 3.0 * radius_ratio * radius_ratio * pressure * pressure * pressure;
}

double jackson_green_contact_radius(double interference, const SphereFlatContact& contact) {
  require_non_negative("interference", interference);
  const double ratio = interference / jackson_green_critical_interference(contact);
  const double hertz = std::sqrt(contact.radius * interference);
  if (ratio <= jackson_green_transition) return hertz;
  const double b = 0.14 * std::exp(23 * contact.yield_strength / contact.contact_modulus);
  return hertz * std::pow(ratio / jackson_green_transition, b / 2);
}

double jackson_green_load_ratio(double interference_ratio, const SphereFlatContact& contact) {
  validate(contact);
  require_non_negative("interference_ratio", interference_ratio);
  if (interference_ratio <= jackson_green_transition) return std::pow(interference_ratio, 1.5);
  return jackson_green_fit(interference_ratio, contact,
                           jackson_green_yield_coefficient(contact.poisson_ratio),
                           jackson_green_b(contact));
}

double jackson_green_load(double interference, const SphereFlatContact& contact) {
  require_non_negative("interference", interference);
  const double critical = jackson_green_critical_interference(contact);
  return jackson_green_critical_load(contact) *
         jackson_green_load_ratio(interference / critical, contact);
}

double kogut_etsion_critical_interference(const SphereFlatContact& contact) {
  validate(contact);
  const double k = 0.454 + 0.41 * contact.poisson_ratio;
  const double ratio = pi * k * 2.8 * contact.yield_strength / (2 * contact.contact_modulus);
  return ratio * ratio * contact.radius;
}

double kogut_etsion_critical_load(const SphereFlatContact& contact) {
  const double critical = kogut_etsion_critical_interference(contact);
  const double k = 0.454 + 0.41 * contact.poisson_ratio;
  return 2.0 / 3.0 * pi * k * 2.8 * contact.yield_strength * contact.radius * critical;
}

double kogut_etsion_load_ratio(double interference_ratio, double poisson_ratio) {
  require_non_negative("interference_ratio", interference_ratio);
  require_open_interval("poisson_ratio", poisson_ratio, -1.0, 0.5);
  const double w = interference_ratio;
  if (w <= 1) return std::pow(w, 1.5);
  if (w <= 6) return 1.03 * std::pow(w, 1.425);
  if (w <= 110) return 1.40 * std::pow(w, 1.263);
  return 3 / (0.454 + 0.41 * poisson_ratio) * w;
}

double jackson_green_residual_interference(double interference_max,
                                           const SphereFlatContact& contact,
                                           JacksonGreenUnloading rule) {
  require_non_negative("interference_max", interference_max);
  validate(contact);
  if (interference_max == 0) return 0.0;
  const JacksonGreenContact law(contact, rule);
  return std::max(0.0, law.unloading(interference_max).residual_approach);
}

JacksonGreenContact::JacksonGreenContact(const SphereFlatContact& contact,
                                         JacksonGreenUnloading rule)
    : contact_(contact),
      rule_(rule),
      critical_interference_(jackson_green_critical_interference(contact)),
      transition_(jackson_green_transition * critical_interference_),
      transition_work_(0.4 * hertz_load(transition_, contact) * transition_),
      critical_load_(jackson_green_critical_load(contact)),
      c_(jackson_green_yield_coefficient(contact.poisson_ratio)),
      b_(jackson_green_b(contact)),
      work_table_(std::make_shared<detail::OctaveWorkTable>(transition_, transition_work_)) {}

double JacksonGreenContact::fit_force(double approach) const {
  return critical_load_ * jackson_green_fit(approach / critical_interference_, contact_, c_, b_);
}

double JacksonGreenContact::loading_force(double approach) const {
  if (approach <= transition_) return hertz_load(approach, contact_);
  return fit_force(approach);
}

double JacksonGreenContact::loading_stiffness(double approach) const {
  if (approach < transition_)
    return 2 * contact_.contact_modulus * std::sqrt(contact_.radius * approach);
  return critical_load_ / critical_interference_ *
         jackson_green_fit_slope(approach / critical_interference_, contact_, c_, b_);
}

std::pair<double, double> JacksonGreenContact::loading_force_and_stiffness(double approach) const {
  if (approach <= transition_) return {loading_force(approach), loading_stiffness(approach)};
  const auto [ratio_power, slope] =
      jackson_green_fit_and_slope(approach / critical_interference_, contact_, c_, b_);
  return {critical_load_ * ratio_power, critical_load_ / critical_interference_ * slope};
}

std::pair<double, double> JacksonGreenContact::loading_force_and_stiffness_from_table(
    double approach) const {
  if (approach <= transition_) return loading_force_and_stiffness(approach);
  return work_table_->force_and_slope(approach, [this](double x) { return fit_force(x); });
}

double JacksonGreenContact::loading_work(double approach) const {
  if (approach <= transition_) return 0.4 * hertz_load(approach, contact_) * approach;
  return work_table_->work(approach, [this](double x) { return fit_force(x); });
}

double JacksonGreenContact::loading_approach(double work) const {
  if (!(work > 0)) return 0.0;
  if (work <= transition_work_) {
    const double stiffness = hertz_coefficient(contact_.contact_modulus, contact_.radius);
    return std::pow(2.5 * work / stiffness, 0.4);
  }
  return work_table_->approach(work, [this](double x) { return fit_force(x); });
}

double JacksonGreenContact::loading_force_at_work(double work) const {
  if (!(work > transition_work_)) return loading_force(loading_approach(work));
  return work_table_->force_at_work(work, [this](double x) { return fit_force(x); });
}

std::pair<double, double> JacksonGreenContact::loading_force_and_stiffness_at_work(
    double work) const {
  if (!(work > transition_work_)) return loading_force_and_stiffness(loading_approach(work));
  return work_table_->force_and_slope_at_work(work, [this](double x) { return fit_force(x); });
}

double JacksonGreenContact::loading_work_below(double approach_max, double distance) const {
  return work_table_->work_below_over_hertz(hertz_coefficient(contact_.contact_modulus,
                                                              contact_.radius),
                                            approach_max, distance,
                                            [this](double x) { return fit_force(x); });
}

std::optional<PowerLawCoefficients> JacksonGreenContact::loading_power_law() const {
  // The stiffness exactly as hertz_load forms it, so that c x^(3/2) is loading_force.
  return PowerLawCoefficients{hertz_coefficient(contact_.contact_modulus, contact_.radius), 1.5};
}

HertzianUnloading JacksonGreenContact::unloading(double approach_max) const {
  require_positive("approach_max", approach_max);
  const double force = loading_force(approach_max);
  if (approach_max <= transition_) // Hertz: R_u = R, no residual, exactly.
    return {hertz_coefficient(contact_.contact_modulus, contact_.radius), 0.0};
  if (rule_ == JacksonGreenUnloading::brake) {
    // Elastic recovery x_max P_m / P_Hertz(x_max); F = P_m at x_max fixes the stiffness.
    const double recovery = approach_max * force / hertz_load(approach_max, contact_);
    return {force / std::pow(recovery, 1.5), approach_max - recovery};
  }
  const double radius = jackson_green_contact_radius(approach_max, contact_);
  const double unloading_radius =
      4 * contact_.contact_modulus * radius * radius * radius / (3 * force);
  const double elastic_approach = 3 * force / (4 * contact_.contact_modulus * radius);
  return {hertz_coefficient(contact_.contact_modulus, unloading_radius),
          approach_max - elastic_approach};
}

} // namespace impact::reduced
