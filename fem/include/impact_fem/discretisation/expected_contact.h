#ifndef IMPACT_FEM_DISCRETISATION_EXPECTED_CONTACT_H
#define IMPACT_FEM_DISCRETISATION_EXPECTED_CONTACT_H

#include <impact_fem/hertz.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace impact_fem
{
  namespace discretisation
  {
    /**
     * What the contact of a run will be, estimated before it runs: the size
     * of the contact zone and its duration, from which the mesh and the time
     * step are sized (automatic_discretisation.h). Elastic bodies: Hertz's
     * impact. A body that can yield (elastic-plastic): the reduced library's
     * elastic-plastic impact under Jackson & Green's (2005) loading fit with
     * a Hertzian unloading (impact_reduced/sphere_flat_fits.hpp) — Hertz's
     * law below first yield, and above it a contact radius that outgrows
     * Hertz's (a = sqrt(R x) (x / (1.9 x_c))^(B/2)), as the plastic contact
     * radius does. The yielding body is the one with the lower limiting
     * pressure C(nu) Y. The sphere's mass is the moving mass (the plate is
     * held). Units SI.
     */
    struct ExpectedContact
    {
      /// "Hertz" or "Jackson-Green": the law of the estimate.
      std::string law;
      /// The body whose yield strength the estimate uses ("sphere" or
      /// "plate"), empty for Hertz.
      std::string yielding_body;
      double      approach_max   = 0; ///< x_max [m]
      double      contact_radius = 0; ///< a at x_max [m]
      double      contact_time   = 0; ///< [s], 0 for a static load
      /// V / V_y, V_y = sqrt(pi^5 R^3 p_y^5 / (30 m E*^4)) with p_y = C(nu)
      /// Y (impact_reduced/contact_formulas.hpp); 0 for Hertz.
      double velocity_ratio = 0;

      /// A body that can yield: its name, yield strength Y [Pa] and
      /// Poisson's ratio.
      struct YieldingBody
      {
        std::string name;
        double      yield_strength;
        double      poissons_ratio;
      };

      /// The impact of the sphere (hertz: E*, R, m, V) with the bodies that
      /// can yield (none: Hertz). The one with the lower limiting pressure
      /// C(nu) Y yields first and sets the estimate.
      static ExpectedContact
      of_impact(const HertzImpact               &hertz,
                const std::vector<YieldingBody> &yielding_bodies);

      /// A static force F [N] on the contact (Hertz).
      static ExpectedContact
      of_static_force(const HertzImpact &hertz, double force);

      /// An indentation to the approach x_max [m] (Hertz's contact radius
      /// sqrt(R x_max)).
      static ExpectedContact
      of_indentation(const HertzImpact &hertz, double approach_max);

      /// One line for the run's log.
      std::string
      describe() const;

      nlohmann::json
      to_json() const;
    };
  } // namespace discretisation
} // namespace impact_fem

#endif
