#include <impact_fem/verification/grid_convergence.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace impact_fem
{
  namespace verification
  {
    GridConvergence
    grid_convergence(const double fine,
                     const double medium,
                     const double coarse,
                     const double r,
                     const double formal_order)
    {
      if (!(r > 1) || !(formal_order > 0) || !std::isfinite(fine) ||
          !std::isfinite(medium) || !std::isfinite(coarse))
        throw std::invalid_argument(
          "grid_convergence: needs finite values, a refinement ratio > 1 and "
          "a positive formal order");
      GridConvergence g;
      g.fine             = fine;
      g.medium           = medium;
      g.coarse           = coarse;
      g.refinement_ratio = r;
      const double e21 = medium - fine, e32 = coarse - medium;
      const double scale =
        std::max({std::abs(fine), std::abs(medium), std::abs(coarse), 1e-300});
      const double round_off =
        64 * std::numeric_limits<double>::epsilon() * scale;
      auto relative = [&](const double absolute) {
        return fine != 0 ? absolute / std::abs(fine) : __builtin_nan("");
      };
      if (std::abs(e21) <= round_off && std::abs(e32) <= round_off)
        {
          g.convergence  = "converged";
          g.extrapolated = fine;
          g.gci_absolute = 0;
          g.gci_relative = relative(0);
          return g;
        }
      if (std::abs(e21) <= round_off)
        {
          // The two finest agree: converged there, order unbounded.
          g.convergence  = "monotone";
          g.extrapolated = fine;
          g.gci_absolute = 0;
          g.gci_relative = relative(0);
          return g;
        }
      const double R = std::abs(e32) > round_off ?
                         e21 / e32 :
                         std::numeric_limits<double>::infinity();
      if (R > 0 && R < 1)
        {
          g.convergence    = "monotone";
          g.observed_order = std::log(e32 / e21) / std::log(r);
          const double rp  = std::pow(r, g.observed_order);
          g.extrapolated   = (rp * fine - medium) / (rp - 1);
          const double q   = std::min(g.observed_order, formal_order);
          g.gci_absolute   = 1.25 * std::abs(e21) / (std::pow(r, q) - 1);
        }
      else
        {
          g.convergence  = R < 0 ? "oscillatory" : "divergent";
          g.gci_absolute = 3 * std::max(std::abs(e21), std::abs(e32));
        }
      g.gci_relative = relative(g.gci_absolute);
      return g;
    }
  } // namespace verification
} // namespace impact_fem
