#include "impact_reduced/contact_formulas.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/special_functions/beta.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace impact::reduced {

namespace {

constexpr double pi = 3.14159265358979323846;

void require_poisson(const char* name, double nu) {
  require_open_interval(name, nu, -1.0, 0.5);
}

// A positive quantity that may also be +infinity (a flat, a fixed body).
void require_positive_or_infinite(const char* name, double value) {
  if (value == std::numeric_limits<double>::infinity()) return;
  require_positive(name, value);
}

void validate(const ElasticBody& body, const std::string& name) {
  if (body.youngs_modulus != std::numeric_limits<double>::infinity()) // rigid_body()
    require_positive((name + ".youngs_modulus").c_str(), body.youngs_modulus);
  require_open_interval((name + ".poisson_ratio").c_str(), body.poisson_ratio, -1.0, 0.5);
  if (!(body.radius > 0) || std::isnan(body.radius))
    throw InvalidInput(name + ".radius", name + ".radius must be > 0 (infinity for a plate)");
}

void require_impact(double coefficient, double mass, double velocity) {
  require_positive("coefficient", coefficient);
  require_positive("mass", mass);
  require_non_negative("velocity", velocity);
}

} // namespace

double contact_compliance(double youngs_modulus_1, double poisson_ratio_1, double youngs_modulus_2,
                          double poisson_ratio_2) {
  return (1.0 - poisson_ratio_1 * poisson_ratio_1) / youngs_modulus_1 +
         (1.0 - poisson_ratio_2 * poisson_ratio_2) / youngs_modulus_2;
}

double contact_modulus(double youngs_modulus_1, double poisson_ratio_1, double youngs_modulus_2,
                       double poisson_ratio_2) {
  require_positive_or_infinite("youngs_modulus_1", youngs_modulus_1);
  require_poisson("poisson_ratio_1", poisson_ratio_1);
  require_positive_or_infinite("youngs_modulus_2", youngs_modulus_2);
  require_poisson("poisson_ratio_2", poisson_ratio_2);
  if (std::isinf(youngs_modulus_1) && std::isinf(youngs_modulus_2))
    throw InvalidInput("youngs_modulus_2",
                       "youngs_modulus_2: two rigid bodies have no contact "
                       "modulus (both moduli are infinite)");
  const double e_star = 1.0 / contact_compliance(youngs_modulus_1, poisson_ratio_1,
                                                 youngs_modulus_2, poisson_ratio_2);
  if (!std::isfinite(e_star))
    throw InvalidInput("youngs_modulus_1",
                       "youngs_modulus_1: the contact modulus of these "
                       "bodies overflows (is not a finite number)");
  return e_star;
}

double effective_radius(double radius_1, double radius_2) {
  require_positive_or_infinite("radius_1", radius_1);
  require_positive_or_infinite("radius_2", radius_2);
  if (std::isinf(radius_1) && std::isinf(radius_2))
    throw InvalidInput("radius_2",
                       "radius_2: two flats have no Hertz contact (both radii "
                       "are infinite)");
  return 1.0 / (1.0 / radius_1 + 1.0 / radius_2);
}

double effective_mass(double mass_1, double mass_2) {
  require_positive_or_infinite("mass_1", mass_1);
  require_positive_or_infinite("mass_2", mass_2);
  if (std::isinf(mass_1) && std::isinf(mass_2))
    throw InvalidInput("mass_2",
                       "mass_2: two fixed bodies cannot collide (both masses are "
                       "infinite)");
  return 1.0 / (1.0 / mass_1 + 1.0 / mass_2);
}

double hertz_coefficient(double contact_modulus, double radius) {
  require_positive("contact_modulus", contact_modulus);
  require_positive("radius", radius);
  return 4.0 / 3.0 * contact_modulus * std::sqrt(radius);
}

double hertz_stiffness(const ElasticBody& first, const ElasticBody& second) {
  validate(first, "first");
  validate(second, "second");
  const double curvature = 1.0 / first.radius + 1.0 / second.radius;
  if (!(curvature > 0))
    throw InvalidInput("radius", "at least one of the two radii must be finite");
  const double compliance = contact_compliance(first.youngs_modulus, first.poisson_ratio,
                                               second.youngs_modulus, second.poisson_ratio);
  if (!(compliance > 0))
    throw InvalidInput("youngs_modulus",
                       "two rigid bodies have no Hertz contact (both moduli "
                       "are infinite)");
  const double stiffness = 1.0 / (0.75 * compliance * std::sqrt(curvature));
  if (!std::isfinite(stiffness))
    throw InvalidInput("youngs_modulus",
                       "the Hertz stiffness of these bodies overflows (is not "
                       "a finite number)");
  return stiffness;
}

double solid_sphere_mass(double radius, double density) {
  require_positive("radius", radius);
  require_positive("density", density);
  const double mass = 4.0 / 3.0 * pi * radius * radius * radius * density;
  if (!std::isfinite(mass) || !(mass > 0)) {
    std::ostringstream message;
    message.precision(17);
    message << "mass: the sphere of radius " << radius << " m and density " << density
            << " kg/m^3 has a mass " << mass << " kg outside the finite positive numbers";
    throw InvalidInput("mass", message.str());
  }
  return mass;
}

double hertz_peak_approach(double coefficient, double mass, double velocity) {
  require_impact(coefficient, mass, velocity);
  // The impact's energy m V^2 / 2 is the spring's work (2/5) c x_max^(5/2).
  return std::pow(5.0 * mass * velocity * velocity / (4.0 * coefficient), 0.4);
}

double hertz_peak_force(double coefficient, double mass, double velocity) {
  return coefficient * std::pow(hertz_peak_approach(coefficient, mass, velocity), 1.5);
}

double hertz_contact_time(double coefficient, double mass, double velocity) {
  require_positive("velocity", velocity);
  // Twice the compression time (x_max / V) integral_0^1 du / sqrt(1 - u^(5/2)).
  static const double factor = 0.8 * boost::math::beta(0.4, 0.5);
  return factor * hertz_peak_approach(coefficient, mass, velocity) / velocity;
}

double hertz_impact_velocity(double coefficient, double mass, double approach) {
  require_positive("coefficient", coefficient);
  require_positive("mass", mass);
  require_non_negative("approach", approach);
  return std::sqrt(0.8 * coefficient * std::pow(approach, 2.5) / mass);
}

double hertz_peak_pressure(double coefficient, double radius, double approach) {
  require_positive("coefficient", coefficient);
  require_positive("radius", radius);
  require_non_negative("approach", approach);
  // p0 = (2 E* / pi) sqrt(x / R) with E* = 3 c / (4 sqrt(R)).
  return 3 * coefficient * std::sqrt(approach) / (2 * pi * radius);
}

double johnson_yield_pressure(double yield_strength) {
  require_positive("yield_strength", yield_strength);
  return 1.6 * yield_strength;
}

double jackson_green_yield_coefficient(double poisson_ratio) {
  require_poisson("poisson_ratio", poisson_ratio);
  return 1.295 * std::exp(0.736 * poisson_ratio);
}

double yield_pressure(YieldCriterion criterion, double yield_strength, double poisson_ratio) {
  require_positive("yield_strength", yield_strength);
  require_poisson("poisson_ratio", poisson_ratio);
  return criterion == YieldCriterion::johnson
             ? johnson_yield_pressure(yield_strength)
             : jackson_green_yield_coefficient(poisson_ratio) * yield_strength;
}

double yield_approach(double yield_pressure, double contact_modulus, double radius) {
  require_positive("yield_pressure", yield_pressure);
  require_positive("contact_modulus", contact_modulus);
  require_positive("radius", radius);
  const double ratio = pi * yield_pressure / (2 * contact_modulus);
  return radius * ratio * ratio;
}

double yield_force(double yield_pressure, double contact_modulus, double radius) {
  require_positive("yield_pressure", yield_pressure);
  require_positive("contact_modulus", contact_modulus);
  require_positive("radius", radius);
  return pi * pi * pi * radius * radius * yield_pressure * yield_pressure * yield_pressure /
         (6 * contact_modulus * contact_modulus);
}

double yield_velocity(double yield_pressure, double contact_modulus, double radius, double mass) {
  require_positive("yield_pressure", yield_pressure);
  require_positive("contact_modulus", contact_modulus);
  require_positive("radius", radius);
  require_positive("mass", mass);
  // Written as products of ratios so that no intermediate power overflows.
  const double pressure_ratio = yield_pressure / contact_modulus;
  const double pi5 = pi * pi * pi * pi * pi;
  return std::sqrt(pi5 * radius * radius * radius / (30 * mass) * yield_pressure *
                   std::pow(pressure_ratio, 4));
}

double half_space_yield_velocity(double yield_pressure, double contact_modulus, double density) {
  require_positive("yield_pressure", yield_pressure);
  require_positive("contact_modulus", contact_modulus);
  require_positive("density", density);
  const double pressure_ratio = yield_pressure / contact_modulus;
  return pi * pi / std::sqrt(40.0) *
         std::sqrt(yield_pressure / density * std::pow(pressure_ratio, 4));
}

} // namespace impact::reduced
