#include "impact_reduced/ghaednia.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "octave_work_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace impact::reduced {

namespace {

constexpr double pi = 3.14159265358979323846;
// omega* = 1.9: the end of the Hertz branch (as in Jackson-Green 2005).
constexpr double transition_ratio = 1.9;

[[noreturn]] void reject(const char* parameter, double value, const std::string& allowed) {
  std::ostringstream message;
  message.precision(17);
  message << parameter << " must be " << allowed << " (got " << value << ")";
  throw InvalidInput(parameter, message.str());
}

const SphereFlatContact& validated(const SphereFlatContact& contact) {
  require_positive("radius", contact.radius);
  require_positive("contact_modulus", contact.contact_modulus);
  require_positive("yield_strength", contact.yield_strength);
  require_open_interval("poisson_ratio", contact.poisson_ratio, -1.0, 0.5);
  return contact;
}

} // namespace

// The pieces of the fit at one approach x > 1.9 delta_c.
struct GhaedniaContact::FitPoint {
  double ratio;          // omega* = x / delta_c
  double hertz_radius;   // a_e = sqrt(R x)
  double plastic_radius; // a_p = a_e (omega* / 1.9)^(B/2)
  double upsilon;        // Upsilon(x)
  double decay;          // exp(Upsilon)
  double radius;         // a = a_e + (a_p - a_e) exp(Upsilon)
  double hardness;       // H_G / Y
  double shape;          // 1 - exp(-omega*^(5/9) / 25)
  double plastic_force;  // F_p
  double hertz_force;    // F_e
};

GhaedniaContact::GhaedniaContact(const SphereFlatContact& contact, double youngs_modulus,
                                 double tangent_modulus)
    : contact_(validated(contact)) {
  require_positive("youngs_modulus", youngs_modulus);
  // 1/E* = (1 - nu^2)/E_s + (1 - nu_f^2)/E_f with a non-negative flat compliance.
  const double rigid_flat_modulus =
      contact.contact_modulus * (1 - contact.poisson_ratio * contact.poisson_ratio);
  if (youngs_modulus < rigid_flat_modulus * (1 - 1e-12)) {
    std::ostringstream allowed;
    allowed.precision(17);
    allowed << ">= contact_modulus (1 - poisson_ratio^2) = " << rigid_flat_modulus
            << " (a flat of non-negative compliance)";
    reject("youngs_modulus", youngs_modulus, allowed.str());
  }
  require_non_negative("tangent_modulus", tangent_modulus);
  if (!(tangent_modulus < youngs_modulus)) {
    std::ostringstream allowed;
    allowed.precision(17);
    allowed << "< youngs_modulus = " << youngs_modulus;
    reject("tangent_modulus", tangent_modulus, allowed.str());
  }

  const double e_star = contact.contact_modulus;
  const double yield_strength = contact.yield_strength;
  c_ = jackson_green_yield_coefficient(contact.poisson_ratio);
  b_ = 0.14 * std::exp(23 * yield_strength / e_star);
  const double critical_strain = pi * c_ * yield_strength / (2 * e_star);
  critical_interference_ = critical_strain * critical_strain * contact.radius;
  const double radius_ratio = contact.radius / e_star;
  const double pressure = c_ * pi * yield_strength / 2;
  critical_load_ = 4.0 / 3.0 * radius_ratio * radius_ratio * pressure * pressure * pressure;
  hertz_coefficient_ = hertz_coefficient(e_star, contact.radius);

  modulus_ratio_ = tangent_modulus / youngs_modulus;
  log_modulus_ratio_ = modulus_ratio_ > 0 ? std::log(modulus_ratio_) : 0.0;
  const double stiffness_ratio = std::sqrt(youngs_modulus / yield_strength);
  upsilon_scale_ =
      2 * stiffness_ratio /
      ((4 - 3 * std::exp(-2 * stiffness_ratio * modulus_ratio_)) * (1 - modulus_ratio_));
  elastic_weight_ = -std::expm1(-3.3 * modulus_ratio_);
  transition_ = transition_ratio * critical_interference_;
  transition_work_ = 0.4 * hertz_coefficient_ * std::pow(transition_, 2.5);
  work_table_ = std::make_shared<detail::OctaveWorkTable>(transition_, transition_work_);
}

double GhaedniaContact::upsilon(double approach) const {
  require_non_negative("approach", approach);
  // E_t = 0: the limit E_t -> 0+ of r^p (p > 0 for x < R + delta_c), Upsilon = 0.
  if (modulus_ratio_ == 0) return 0.0;
  const double exponent = 1 - (approach - critical_interference_) / contact_.radius;
  return -upsilon_scale_ * std::pow(modulus_ratio_, exponent);
}

GhaedniaContact::FitPoint GhaedniaContact::fit(double approach) const {
  FitPoint p;
  p.ratio = approach / critical_interference_;
  p.hertz_radius = std::sqrt(contact_.radius * approach);
  p.plastic_radius = p.hertz_radius * std::pow(p.ratio / transition_ratio, b_ / 2);
  p.upsilon = upsilon(approach);
  p.decay = std::exp(p.upsilon);
  p.radius = p.hertz_radius + (p.plastic_radius - p.hertz_radius) * p.decay;
  // 1 - cos(t) = 2 sin^2(t/2), without cancellation for small a/R.
  const double half_angle = std::sin(pi * p.radius / (2 * contact_.radius));
  p.hardness = 2.84 - 0.92 * 2 * half_angle * half_angle;
  p.shape = -std::expm1(-std::pow(p.ratio, 5.0 / 9.0) / 25);
  p.plastic_force =
      critical_load_ * (std::exp(-0.25 * std::pow(p.ratio, 5.0 / 12.0)) * std::pow(p.ratio, 1.5) +
                        4 * p.hardness / c_ * p.shape * p.ratio);
  p.hertz_force = hertz_coefficient_ * approach * std::sqrt(approach);
  return p;
}

double GhaedniaContact::contact_radius(double approach) const {
  require_non_negative("approach", approach);
  if (approach <= transition_) return std::sqrt(contact_.radius * approach);
  return fit(approach).radius;
}

double GhaedniaContact::fit_force(double approach) const {
  const FitPoint p = fit(approach);
  return p.plastic_force + (p.hertz_force - p.plastic_force) * elastic_weight_;
}

double GhaedniaContact::loading_force(double approach) const {
  require_non_negative("approach", approach);
  if (approach <= transition_) return hertz_coefficient_ * approach * std::sqrt(approach);
  return fit_force(approach);
}

// dF/dx above the transition, F = (1 - w) F_p + w F_e:
//   F_e' = 2 E* sqrt(R x) = (3/2) F_e / x;
//   a_e' = a_e / (2x),  a_p' = a_p (1 + B) / (2x),  Upsilon' = -Upsilon ln(r) / R,
//   a' = a_e' + (a_p' - a_e') e^Upsilon + (a_p - a_e) e^Upsilon Upsilon';
//   (H_G/Y)' = -0.92 (pi / R) sin(pi a / R) a';
//   F_p' = (P_c / delta_c) [e^(-w^(5/12)/4) w^(1/2) (3/2 - (5/48) w^(5/12))
//           + (4/C) (H_G/Y) (G + w G')] + P_c (4/C) G w (H_G/Y)'   (w = omega*),
//   G = 1 - exp(-w^(5/9)/25),  w G' = exp(-w^(5/9)/25) w^(5/9) / 45.
double GhaedniaContact::loading_stiffness(double approach) const {
  require_non_negative("approach", approach);
  if (approach < transition_)
    return 2 * contact_.contact_modulus * std::sqrt(contact_.radius * approach);
  return fit_slope(approach, fit(approach));
}

std::pair<double, double> GhaedniaContact::loading_force_and_stiffness(double approach) const {
  if (approach <= transition_) return {loading_force(approach), loading_stiffness(approach)};
  const FitPoint p = fit(approach); // as fit_force and loading_stiffness form them
  return {p.plastic_force + (p.hertz_force - p.plastic_force) * elastic_weight_,
          fit_slope(approach, p)};
}

std::pair<double, double> GhaedniaContact::loading_force_and_stiffness_from_table(
    double approach) const {
  if (approach <= transition_) return loading_force_and_stiffness(approach);
  return work_table_->force_and_slope(approach, [this](double x) { return fit_force(x); });
}

double GhaedniaContact::fit_slope(double approach, const FitPoint& p) const {
  const double w = p.ratio;
  const double hertz_radius_slope = p.hertz_radius / (2 * approach);
  const double plastic_radius_slope = p.plastic_radius * (1 + b_) / (2 * approach);
  const double upsilon_slope =
      modulus_ratio_ == 0 ? 0.0 : -p.upsilon * log_modulus_ratio_ / contact_.radius;
  const double radius_slope = hertz_radius_slope +
                              (plastic_radius_slope - hertz_radius_slope) * p.decay +
                              (p.plastic_radius - p.hertz_radius) * p.decay * upsilon_slope;
  const double hardness_slope =
      -0.92 * pi / contact_.radius * std::sin(pi * p.radius / contact_.radius) * radius_slope;
  const double power = std::pow(w, 5.0 / 9.0);
  const double shape_slope_times_ratio = std::exp(-power / 25) * power / 45;
  const double twelfth = std::pow(w, 5.0 / 12.0);
  const double hertz_like = std::exp(-0.25 * twelfth) * std::sqrt(w) * (1.5 - 5.0 / 48.0 * twelfth);
  const double plastic_slope =
      critical_load_ / critical_interference_ *
          (hertz_like + 4 / c_ * p.hardness * (p.shape + shape_slope_times_ratio)) +
      critical_load_ * 4 / c_ * p.shape * w * hardness_slope;
  const double hertz_slope = 1.5 * p.hertz_force / approach;
  return plastic_slope + (hertz_slope - plastic_slope) * elastic_weight_;
}

double GhaedniaContact::loading_work(double approach) const {
  require_non_negative("approach", approach);
  if (approach <= transition_) return 0.4 * hertz_coefficient_ * std::pow(approach, 2.5);
  return work_table_->work(approach, [this](double x) { return fit_force(x); });
}

double GhaedniaContact::loading_approach(double work) const {
  if (!(work > 0)) return 0.0;
  if (work <= transition_work_) return std::pow(2.5 * work / hertz_coefficient_, 0.4);
  return work_table_->approach(work, [this](double x) { return fit_force(x); });
}

double GhaedniaContact::loading_force_at_work(double work) const {
  if (!(work > transition_work_)) return loading_force(loading_approach(work));
  return work_table_->force_at_work(work, [this](double x) { return fit_force(x); });
}

std::pair<double, double> GhaedniaContact::loading_force_and_stiffness_at_work(double work) const {
  if (!(work > transition_work_)) return loading_force_and_stiffness(loading_approach(work));
  return work_table_->force_and_slope_at_work(work, [this](double x) { return fit_force(x); });
}

double GhaedniaContact::loading_work_below(double approach_max, double distance) const {
  return work_table_->work_below_over_hertz(hertz_coefficient_, approach_max, distance,
                                            [this](double x) { return fit_force(x); });
}

HertzianUnloading GhaedniaContact::unloading(double approach_max) const {
  require_positive("approach_max", approach_max);
  const double e_star = contact_.contact_modulus;
  if (approach_max <= transition_) // Hertz: R_u = R, no residual.
    return {hertz_coefficient_, 0.0};
  // F and a from one evaluation of the fit (as loading_force and contact_radius form them).
  const FitPoint p = fit(approach_max);
  const double force = p.plastic_force + (p.hertz_force - p.plastic_force) * elastic_weight_;
  const double radius = p.radius;
  const double unloading_radius = 4 * e_star * radius * radius * radius / (3 * force);
  const double elastic_approach = 3 * force / (4 * e_star * radius);
  return {hertz_coefficient(e_star, unloading_radius), approach_max - elastic_approach};
}

} // namespace impact::reduced
