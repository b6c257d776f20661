#ifndef IMPACT_FEM_HERTZ_H
#define IMPACT_FEM_HERTZ_H

#include <impact_reduced/contact_formulas.hpp>

#include <cmath>

namespace impact_fem
{
  /**
   * Hertz's quasi-static theory of a sphere (radius R, mass m) hitting a
   * half-space at speed V. The model uses it only for estimates: the time
   * step, the expected end of the run and the extent of the contact zone.
   * The formulas are the reduced library's (impact_reduced/contact_formulas.hpp).
   * Units SI.
   */
  struct HertzImpact
  {
    double effective_modulus; ///< E* = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2) [Pa]
    double radius;            ///< sphere radius R [m]
    double mass;              ///< sphere mass m [kg]
    double velocity;          ///< impact speed V [m/s]

    /// Stiffness of F = k delta^(3/2) [N/m^1.5].
    double
    stiffness() const
    {
      return impact::reduced::hertz_coefficient(effective_modulus, radius);
    }

    /// Peak approach [m].
    double
    approach_max() const
    {
      return impact::reduced::hertz_peak_approach(stiffness(), mass, velocity);
    }

    /// Peak force [N].
    double
    force_max() const
    {
      return impact::reduced::hertz_peak_force(stiffness(), mass, velocity);
    }

    /// Contact radius at peak force [m].
    double
    contact_radius_max() const
    {
      return std::sqrt(radius * approach_max());
    }

    /// Contact time [s]: 2.9432 delta_max / V, Hertz's factor rounded to
    /// five digits (impact::reduced::hertz_contact_time has it exact,
    /// 2.943275). Every run's time step is a fraction of this estimate, so
    /// the rounded factor stays: runs and campaigns keep their steps;
    /// tests/fem/test_hertz_estimates.cpp ties the two within 3e-5.
    double
    contact_time() const
    {
      return 2.9432 * approach_max() / velocity;
    }
  };

} // namespace impact_fem

#endif
