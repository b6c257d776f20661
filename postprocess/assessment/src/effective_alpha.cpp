// The FEM's "effective alpha" (1 - e)/V against the measured range the seed paper compares
// it with (steps.hpp).

#include "steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

double effective_alpha(const ReportRun& run) {
  return run.velocity > 0 ? (1 - run.fem.restitution) / run.velocity
                          : std::numeric_limits<double>::quiet_NaN();
}

std::string effective_alpha_text(const std::vector<ReportRun>& runs) {
  double low = INFINITY, high = -INFINITY;
  std::size_t below = 0, inside = 0, above = 0, count = 0;
  for (const auto& run : runs) {
    const double alpha = effective_alpha(run);
    if (!std::isfinite(alpha)) continue;
    ++count;
    low = std::min(low, alpha);
    high = std::max(high, alpha);
    if (alpha < measured_alpha_low)
      ++below;
    else if (alpha > measured_alpha_high)
      ++above;
    else
      ++inside;
  }
  if (count == 0) return "";
  std::string where;
  if (inside == count)
    where = "inside that range at every run";
  else if (below == count)
    where = "below that range at every run";
  else if (above == count)
    where = "above that range at every run";
  else
    where = std::to_string(below) + " run(s) below, " + std::to_string(inside) + " inside and " +
            std::to_string(above) + " above that range";
  return "Effective alpha (1 - e)/V of the FEM (the per-run table): " + short_number(low) + " to " +
         short_number(high) +
         " s/m. The seed paper compares this number with the 0.08–0.32 s/m measured for steel, "
         "glass and brass (Goldsmith's experiments); the FEM's values lie " +
         where +
         ". (1 - e)/V is constant only where 1 - e grows like V (Hunt–Crossley's small-damping "
         "limit 1 - e = (2/3) b V, so alpha = (2/3) b): where the FEM's 1 - e grows more slowly "
         "(velocity trend), "
         "its effective alpha falls with V and one measured alpha holds at one velocity only.";
}

} // namespace impact::postprocess::detail
