#include "impact_reduced/lambert_w.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "branch_point.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/lambert_w.hpp>

#include <cmath>

namespace impact::reduced {

namespace {
// One Newton step on the defining equation in log form, w + log(w / z) = 0 (w and z share
// their sign). Boost 1.74's double-precision W is up to ~10 ulps off away from the branch
// point; this form of the residual has no cancellation of large terms, so one step brings
// the result to the conditioning limit, ~1 ulp / |1 + W|.
double refine(double w, double z) {
  if (z == 0.0 || w == -1.0) return w;
  const double residual = w + std::log(w / z);
  return w - residual * w / (1.0 + w);
}
} // namespace

double lambert_w0(double z) {
  require_finite("z", z);
  const double branch_point = -boost::math::constants::exp_minus_one<double>();
  if (z < branch_point) throw InvalidInput("z", "z must be >= -1/e for the principal branch W0");
  return refine(boost::math::lambert_w0(z), z);
}

double lambert_wm1(double z) {
  require_finite("z", z);
  const double branch_point = -boost::math::constants::exp_minus_one<double>();
  if (z < branch_point || z >= 0)
    throw InvalidInput("z", "z must be in [-1/e, 0) for the lower branch W-1");
  return refine(boost::math::lambert_wm1(z), z);
}

double one_plus_lambert_w(double s, LambertBranch branch) {
  require_non_negative("s", s);
  return detail::branch_offset(s, branch == LambertBranch::principal);
}

double log1p_excess(double t) {
  require_finite("t", t);
  if (!(t > -1)) throw InvalidInput("t", "t must be > -1 (got " + std::to_string(t) + ")");
  return detail::log1p_excess(t);
}

} // namespace impact::reduced
