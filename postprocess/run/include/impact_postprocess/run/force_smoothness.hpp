#pragma once
/// @file
/// How clean a discrete contact-force history is, with the definitions of impact-fem's
/// summary keys "force_oscillation" and "force_after_release" (so that runs which do not
/// record them are measured the same way):
///   - oscillation: max_i |F_i - (F_{i-1} + F_{i+1}) / 2| / F_max over the steps inside the
///     contact (first to last step with F > 0), 5 steps at each end excluded. A smooth history
///     gives |F''| dt^2 / 2, of order (pi / N)^2 / 2 for N steps per contact (5e-5 at
///     N = 300); a force that alternates by +-a from step to step gives 2a.
///   - after_release: max F after the first zero-force step that follows the peak, / F_max
///     (0 for a clean release; the chatter of a contact that re-closes otherwise).

#include <vector>

namespace impact::postprocess {

struct ForceSmoothness {
  double oscillation;   ///< fraction of the peak force; NaN below 14 steps in contact
  double after_release; ///< fraction of the peak force; NaN without contact
};

/// The two measures of a force history sampled at equal steps (one value per step).
ForceSmoothness force_smoothness(const std::vector<double>& force);

/// Time [s] from the first zero-force step after the peak to the last step with F > 0: the
/// length of the release chatter (0 for a clean release).
double release_span(const std::vector<double>& time, const std::vector<double>& force);

} // namespace impact::postprocess
