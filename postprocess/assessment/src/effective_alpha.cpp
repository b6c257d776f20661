// The FEM's "effective alpha" (1 - e)/V against the measured range the seed paper compares
// it with (fem_runs.hpp).

#include "steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

double effective_alpha(const ReportRun& run) {
  return run.velocity > 0 ? (1 - run.fem.restitution) / run.velocity
                          : std::numeric_limits<double>::quiet_NaN();
}

std::optional<EffectiveAlpha> effective_alpha(const std::vector<ReportRun>& runs) {
  EffectiveAlpha alpha{INFINITY, -INFINITY};
  for (const auto& run : runs) {
    const double value = effective_alpha(run);
    if (!std::isfinite(value)) continue;
    ++alpha.count;
    alpha.low = std::min(alpha.low, value);
    alpha.high = std::max(alpha.high, value);
    if (value < measured_alpha_low)
      ++alpha.below;
    else if (value > measured_alpha_high)
      ++alpha.above;
    else
      ++alpha.inside;
  }
  if (alpha.count == 0) return std::nullopt;
  return alpha;
}

} // namespace impact::postprocess::detail
