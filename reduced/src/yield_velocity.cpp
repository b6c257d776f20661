#include "impact_reduced/yield_velocity.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <cmath>
#include <limits>

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

} // namespace

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
  const double e_star = 1.0 / ((1 - poisson_ratio_1 * poisson_ratio_1) / youngs_modulus_1 +
                               (1 - poisson_ratio_2 * poisson_ratio_2) / youngs_modulus_2);
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
