#include "branch_point.hpp"

#include <boost/math/special_functions/lambert_w.hpp>

#include <cmath>
#include <limits>

namespace impact::reduced::detail {


double branch_excess(double y) {
  if (std::fabs(y) < 0.25) return y * y * small_branch_excess_ratio<double, 11>(y);
  return -y - std::log1p(-y);
}

double log1p_excess_ratio(double t) {
  if (std::fabs(t) < 0.25) return small_branch_excess_ratio<double, 11>(-t);
  return (t - std::log1p(t)) / (t * t);
}

double branch_offset(double s, bool principal) {
  if (s == 0.0) return 0.0;
  double y;
  if (s < 0.05) {
    // Branch-point series in p = +-sqrt(2 s); error O(p^4) before the Newton steps.
    const double p = principal ? std::sqrt(2.0 * s) : -std::sqrt(2.0 * s);
    y = p * (1.0 + p * (-1.0 / 3.0 + p / 36.0));
  } else if (principal) {
    // Away from the branch point Boost's W0 is accurate. For s > 30, y = 1 + W0(z) with
    // |z| < 1e-13 is exact to double precision and S(y) is too steep for Newton.
    y = 1.0 + boost::math::lambert_w0(-std::exp(-1.0 - s));
    if (s > 30.0) return y;
  } else if (s < 700.0) {
    y = 1.0 + boost::math::lambert_wm1(-std::exp(-1.0 - s));
  } else {
    // exp(-1 - s) underflows: asymptotic start, -y = s + log(1 + s) + ..., then Newton.
    y = -(s + std::log1p(s));
  }
  // Newton on S(y) = s; S'(y) = y / (1 - y). Converges in one or two steps from these starts.
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double correction = (branch_excess(y) - s) * (1.0 - y) / y;
    y -= correction;
    if (std::fabs(correction) <= 4 * std::numeric_limits<double>::epsilon() * std::fabs(y)) break;
  }
  return y;
}

double branch_ratio(double p) {
  if (std::fabs(p) < 1e-6) return 1.0 + p * (-1.0 / 3.0 + p / 36.0);
  return branch_offset(0.5 * p * p, p > 0) / p;
}

} // namespace impact::reduced::detail
