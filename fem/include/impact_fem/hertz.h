#ifndef IMPACT_FEM_HERTZ_H
#define IMPACT_FEM_HERTZ_H

#include <cmath>

namespace impact_fem
{
  /**
   * Hertz's quasi-static theory of a sphere (radius R, mass m) hitting a
   * half-space at speed V. The model uses it only for estimates: the time
   * step, the expected end of the run and the extent of the contact zone.
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
      return 4.0 / 3.0 * effective_modulus * std::sqrt(radius);
    }

    /// Peak approach [m].
    double
    approach_max() const
    {
      return std::pow(5.0 * mass * velocity * velocity / (4.0 * stiffness()),
                      0.4);
    }

    /// Peak force [N].
    double
    force_max() const
    {
      return stiffness() * std::pow(approach_max(), 1.5);
    }

    /// Contact radius at peak force [m].
    double
    contact_radius_max() const
    {
      return std::sqrt(radius * approach_max());
    }

    /// Contact time [s]: 2.94 delta_max / V (exact constant 2.9432).
    double
    contact_time() const
    {
      return 2.9432 * approach_max() / velocity;
    }
  };

} // namespace impact_fem

#endif
