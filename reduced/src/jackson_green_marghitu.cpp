#include "impact_reduced/jackson_green_marghitu.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/contact_formulas.hpp"

#include <cmath>
#include <string>

namespace impact::reduced {

double jackson_green_marghitu_restitution(double velocity_ratio, double yield_strain) {
  require_non_negative("velocity_ratio", velocity_ratio);
  require_open_interval("yield_strain", yield_strain, 0.0, 1.0);
  if (velocity_ratio <= 1) return 1;
  const double e = 1 - 0.0361 * std::pow(yield_strain, -0.114) * std::log(velocity_ratio) *
                           std::pow(velocity_ratio - 1, 9.5 * yield_strain);
  if (!(e > 0))
    throw InvalidInput("velocity_ratio",
                       "velocity_ratio: the Jackson-Green-Marghitu fit gives e = " +
                           std::to_string(e) +
                           " <= 0 at V/V_c = " + std::to_string(velocity_ratio) +
                           " (eps_y = " + std::to_string(yield_strain) +
                           "): the velocity is beyond the range the fit can describe");
  return e;
}

double jackson_green_marghitu_yield_strain(const SphereFlatContact& contact) {
  require_positive("contact_modulus", contact.contact_modulus);
  require_positive("yield_strength", contact.yield_strength);
  return jackson_green_yield_coefficient(contact.poisson_ratio) * contact.yield_strength /
         contact.contact_modulus;
}

double jackson_green_marghitu_critical_velocity(const SphereFlatContact& contact, double mass) {
  const double p_c =
      yield_pressure(YieldCriterion::jackson_green, contact.yield_strength, contact.poisson_ratio);
  return yield_velocity(p_c, contact.contact_modulus, contact.radius, mass);
}

double jackson_green_marghitu_restitution(double velocity, const SphereFlatContact& contact,
                                          double mass) {
  require_non_negative("velocity", velocity);
  const double v_c = jackson_green_marghitu_critical_velocity(contact, mass);
  return jackson_green_marghitu_restitution(velocity / v_c,
                                            jackson_green_marghitu_yield_strain(contact));
}

} // namespace impact::reduced
