#pragma once
// Cancellation-free evaluation of the Lambert W function near its branch point, in the
// variables the Hunt-Crossley impact formulas use. Internal to the library.
//
// With y = 1 + W(-exp(-1 - s)), the defining equation W e^W = z becomes
//     S(y) := -y - log(1 - y) = s,          y < 1,
// an equation without exponentials of large arguments and without the branch point: S is
// smooth and S(y) = y^2/2 + y^3/3 + ... near y = 0. The principal branch is the root y >= 0,
// the lower branch the root y <= 0. The impact needs S(-t) = t - log(1 + t) as well (the
// impact parameter beta enters through s = S(-beta)).

namespace impact::reduced::detail {

/// S(y) = -y - log(1 - y) for y < 1, to about 1 ulp relative (series for |y| < 1/2).
double branch_excess(double y);

/// S(y) / y^2 for y < 1, y != 0 (1/2 at y = 0).
double branch_excess_ratio(double y);

/// t - log(1 + t) for t > -1 (= S(-t)), to about 1 ulp relative.
inline double log1p_excess(double t) {
  return branch_excess(-t);
}

/// The root y of S(y) = s on the principal (y >= 0) or lower (y <= 0) branch, s >= 0.
double branch_offset(double s, bool principal);

/// y / p, where y is the root of S(y) = p^2 / 2 with the sign of p (p > 0: principal,
/// p < 0: lower branch). Equals 1 at p = 0 and is analytic there; this is the form
/// that stays exact as the damping goes to zero.
double branch_ratio(double p);

/// (t - log(1 + t)) / t^2 for t > -1, with the limit 1/2 at t = 0.
double log1p_excess_ratio(double t);

/// The series part of S(y) / y^2 for |y| < 1/4 in any floating type: with u = y / (2 - y),
///     S(y) / y^2 = (u/y) + 2 u (u/y)^2 (1/3 + u^2/5 + u^4/7 + ...),
/// every term free of cancellation (-log(1 - y) = 2 atanh(u) and 2u - y = y u).
/// |u| <= 1/7 makes the series converge by a factor 1/49 per term: `terms` = 11 gives
/// double precision, 22 quadruple precision.
template <class Real, int terms>
Real small_branch_excess_ratio(Real y) {
  const Real u_over_y = Real(1) / (Real(2) - y);
  const Real u = y * u_over_y;
  const Real u2 = u * u;
  Real series = 0;
  for (int k = terms - 1; k >= 0; --k) series = series * u2 + Real(1) / Real(2 * k + 3);
  return u_over_y + Real(2) * u * u_over_y * u_over_y * series;
}

} // namespace impact::reduced::detail
