#include "impact_postprocess/run/force_smoothness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t excluded_steps = 5; // at each end of the contact

// Index of the largest force, and of the first zero-force step after it (size if none).
std::pair<std::size_t, std::size_t> peak_and_release(const std::vector<double>& force) {
  const std::size_t peak =
      std::size_t(std::max_element(force.begin(), force.end()) - force.begin());
  std::size_t release = peak;
  while (release < force.size() && force[release] > 0) ++release;
  return {peak, release};
}

} // namespace

ForceSmoothness force_smoothness(const std::vector<double>& force) {
  ForceSmoothness smoothness{nan, nan};
  if (force.empty()) return smoothness;
  const auto [peak, release] = peak_and_release(force);
  const double force_max = force[peak];
  if (!(force_max > 0)) return smoothness;
  double after = 0;
  for (std::size_t i = release; i < force.size(); ++i) after = std::max(after, force[i]);
  smoothness.after_release = after / force_max;

  std::size_t first = force.size(), last = 0;
  for (std::size_t i = 0; i < force.size(); ++i)
    if (force[i] > 0) {
      first = std::min(first, i);
      last = i;
    }
  // The steps [first + 5, last - 5) are inside; each measured step has both neighbours there
  // (as impact-fem's own measure and tests/fem/smoothness.py count them).
  if (last < first + 2 * excluded_steps + 3) return smoothness;
  const std::size_t begin = first + excluded_steps, end = last - excluded_steps; // [begin, end)
  double worst = 0;
  for (std::size_t i = begin + 1; i + 2 <= end; ++i)
    worst = std::max(worst, std::abs(force[i] - 0.5 * (force[i - 1] + force[i + 1])));
  smoothness.oscillation = worst / force_max;
  return smoothness;
}

double release_span(const std::vector<double>& time, const std::vector<double>& force) {
  if (force.empty() || time.size() != force.size()) return nan;
  const auto [peak, release] = peak_and_release(force);
  if (release >= force.size()) return 0;
  std::size_t last = release;
  for (std::size_t i = release; i < force.size(); ++i)
    if (force[i] > 0) last = i;
  return last > release ? time[last] - time[release] : 0.0;
}

} // namespace impact::postprocess
