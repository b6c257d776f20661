#ifndef IMPACT_FEM_VERIFICATION_GRID_CONVERGENCE_H
#define IMPACT_FEM_VERIFICATION_GRID_CONVERGENCE_H

#include <string>

namespace impact_fem
{
  namespace verification
  {
    /**
     * Numerical uncertainty of one quantity from three systematically
     * refined discretisations with a constant refinement ratio r > 1
     * (f_fine on the finest), after Roache's grid convergence index in the
     * procedure of Celik et al., J. Fluids Eng. 130 (2008) 078001, the one
     * ASME V&V 20 uses:
     *   e21 = f_medium - f_fine, e32 = f_coarse - f_medium, R = e21 / e32;
     *   observed order p = ln(e32 / e21) / ln r              (0 < R < 1),
     *   extrapolated f_ext = (r^p f_fine - f_medium) / (r^p - 1),
     *   GCI_fine = Fs |e21| / (r^q - 1),  Fs = 1.25,  q = min(p, formal order).
     * q is capped at the formal order so that an observed order above it
     * (two errors that partly cancel) does not make the index smaller than
     * the formal rate supports. Oscillatory (R < 0) or divergent (R >= 1)
     * sequences have no observed order; their index is the conservative
     * Fs max(|e21|, |e32|) with Fs = 3 (Roache's factor for an unreliable
     * order). Identical values (to round-off) are "converged", index 0.
     */
    struct GridConvergence
    {
      double      fine = 0, medium = 0, coarse = 0;
      double      refinement_ratio = 0;
      double      observed_order   = __builtin_nan(""); ///< NaN if none
      double      extrapolated     = __builtin_nan(""); ///< NaN if none
      double      gci_absolute     = 0; ///< in the quantity's unit
      double      gci_relative = 0; ///< gci_absolute / |fine|, NaN if fine = 0
      std::string convergence; ///< monotone|oscillatory|divergent|converged
    };

    /// @p formal_order: the scheme's order (2 here: time integration and
    /// contact), > 0; @p refinement_ratio > 1.
    GridConvergence
    grid_convergence(const double fine,
                     const double medium,
                     const double coarse,
                     const double refinement_ratio,
                     const double formal_order);
  } // namespace verification
} // namespace impact_fem

#endif
