#ifndef IMPACT_FEM_ANALYSIS_INDENTATION_H
#define IMPACT_FEM_ANALYSIS_INDENTATION_H

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * The load program of the quasi-static indentation (Scenario/Analysis =
   * indentation, subsection "Indentation"): the base of the hemisphere is
   * moved towards the plate in equal steps up to the maximum approach and
   * back in the same steps until the contact force vanishes.
   *
   * The geometry is that of the finite-element studies of elastic-plastic
   * sphere-flat contact (Kogut & Etsion 2002, J. Appl. Mech. 69:657;
   * Jackson & Green 2005, J. Tribol. 127:343): a deformable hemisphere
   * whose base, the equatorial plane, is displaced by the interference
   * towards a flat (fem/README.md, "Indentation").
   */
  struct IndentationControl
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read and check the subsection; the errors name the entry.
    void
    parse_parameters(ParameterHandler &prm);

    /// Approaches of all steps [m]: 0, loading to the maximum, unloading
    /// back to 0 (the run stops earlier when the force vanishes).
    std::vector<double>
    approaches() const;

    double       maximum_approach = 0; ///< [m]
    unsigned int steps            = 0; ///< load steps, each way [-]
    /// The base also held radially (u_r = 0), not only moved vertically.
    bool base_fixed_radially = false;
  };
} // namespace impact_fem

#endif
