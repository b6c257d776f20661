#include "impact_reduced/lambert_w.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "branch_point.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/lambert_w.hpp>

#include <cmath>

namespace impact::reduced {

double lambert_w0(double z) {
  require_finite("z", z);
  const double branch_point = -boost::math::constants::exp_minus_one<double>();
  if (z < branch_point)
    throw InvalidInput("z", "z must be >= -1/e for the principal branch W0");
  return boost::math::lambert_w0(z);
}

double lambert_wm1(double z) {
  require_finite("z", z);
  const double branch_point = -boost::math::constants::exp_minus_one<double>();
  if (z < branch_point || z >= 0)
    throw InvalidInput("z", "z must be in [-1/e, 0) for the lower branch W-1");
  return boost::math::lambert_wm1(z);
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
