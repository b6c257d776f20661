#include "branch_point.hpp"

#include <boost/math/special_functions/lambert_w.hpp>

#include <cmath>
#include <limits>

namespace impact::reduced::detail {

// Below |y| = 1/2 the literal -y - log1p(-y) cancels (the terms are up to 9 times the
// result), so the series serves there: 11 terms reach double precision for |y| < 1/4
// (|u| <= 1/7), 20 terms for |y| < 1/2 (|u| <= 1/3).
double branch_excess_ratio(double y) {
  const double magnitude = std::fabs(y);
  if (magnitude < 0.25) return small_branch_excess_ratio<double, 11>(y);
  if (magnitude < 0.5) return small_branch_excess_ratio<double, 20>(y);
  return (-y - std::log1p(-y)) / (y * y);
}

double branch_excess(double y) {
  if (std::fabs(y) < 0.5) return y * y * branch_excess_ratio(y);
  return -y - std::log1p(-y);
}

double log1p_excess_ratio(double t) {
  return branch_excess_ratio(-t);
}

namespace {

// y / p from the branch-point series y = sum a_k p^k of the root of S(y) = p^2 / 2,
// obtained by reverting p = y sqrt(2 S(y)) / y in exact rational arithmetic. With 11
// terms the truncation error is below 1e-7 |p|^11 relative: 4e-22 at |p| = 0.05.
double series_ratio(double p) {
  constexpr double coefficients[] = {1.0,
                                     -1.0 / 3.0,
                                     1.0 / 36.0,
                                     1.0 / 270.0,
                                     1.0 / 4320.0,
                                     -1.0 / 17010.0,
                                     -139.0 / 5443200.0,
                                     -1.0 / 204120.0,
                                     -571.0 / 2351462400.0,
                                     281.0 / 1515591000.0,
                                     163879.0 / 2172751257600.0};
  double ratio = 0.0;
  for (int k = 10; k >= 0; --k) ratio = ratio * p + coefficients[k];
  return ratio;
}

// One Newton step on S(y) = s; S'(y) = y / (1 - y).
double newton_step(double y, double s) {
  return y - (branch_excess(y) - s) * (1.0 - y) / y;
}

constexpr double series_only_limit = 0.05; // |p| below: the series alone is exact
constexpr double series_start_limit = 0.5; // |p| below: series + one Newton step

} // namespace

double branch_offset(double s, bool principal) {
  if (s == 0.0) return 0.0;
  const double magnitude = std::sqrt(2.0 * s);
  if (magnitude < series_start_limit) {
    const double p = principal ? magnitude : -magnitude;
    const double y = p * series_ratio(p);
    return magnitude < series_only_limit ? y : newton_step(y, s);
  }
  double y;
  if (principal) {
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
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double next = newton_step(y, s);
    const bool converged =
        std::fabs(next - y) <= 4 * std::numeric_limits<double>::epsilon() * std::fabs(next);
    y = next;
    if (converged) break;
  }
  return y;
}

double branch_ratio(double p) {
  const double magnitude = std::fabs(p);
  if (magnitude < series_only_limit) return series_ratio(p);
  if (magnitude < series_start_limit) return newton_step(p * series_ratio(p), 0.5 * p * p) / p;
  return branch_offset(0.5 * p * p, p > 0) / p;
}

} // namespace impact::reduced::detail
