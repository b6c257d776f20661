// Accuracy of the Lambert W functions of the reduced library against 100-digit references
// computed here (Boost.Math's W in cpp_bin_float_100, and the branch-point series where
// even 100 digits cannot form the argument): one_plus_lambert_w on both branches for
// s in [1e-300, 1e5], the lambert_w0 / lambert_wm1 wrappers, log1p_excess.

#include "high_precision_reference.hpp"

#include "impact_reduced/lambert_w.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <vector>

namespace {

using namespace impact::reduced;
using hp::expect_target;
using hp::Real100;
using hp::relative_error;
using hp::report;
using hp::WorstError;

constexpr double eps = std::numeric_limits<double>::epsilon();

/// `per_decade` points per decade from `first` to `last` (> 0), both included.
std::vector<double> log_grid(double first, double last, int per_decade) {
  const double decades = std::log10(last / first);
  const int count = std::max(2, static_cast<int>(std::ceil(decades * per_decade)) + 1);
  std::vector<double> grid;
  for (int i = 0; i < count; ++i) grid.push_back(first * std::pow(10.0, decades * i / (count - 1)));
  grid.front() = first;
  grid.back() = last;
  return grid;
}

// The references themselves: the branch-point series and Boost's 100-digit W agree where
// both are valid, Boost's W in 50 digits is as accurate near the branch point as the
// conditioning allows, and W satisfies its defining equation ln(-W) + W = ln(-z) (log
// form: well conditioned away from the branch point).
TEST(LambertWAccuracy, ReferenceSelfCheck) {
  for (const bool principal : {true, false}) {
    for (const double s : {1e-40, 1e-36, 1e-32, 1e-28, 1e-24, 1e-20}) {
      const Real100 series = hp::one_plus_w_series(Real100(s), principal);
      const Real100 z = -exp(-1 - Real100(s));
      const Real100 boost_w =
          1 + (principal ? boost::math::lambert_w0(z) : boost::math::lambert_wm1(z));
      const double difference = static_cast<double>(abs((series - boost_w) / boost_w));
      EXPECT_LT(difference, 1e-55) << "s = " << s << (principal ? " W0" : " W-1");
    }
  }
  // Boost's W in 50 digits, argument formed in 50 digits, is accurate near the branch point
  // to its conditioning: relative error of 1 + W ~ 1e-50 / s.
  for (const bool principal : {true, false}) {
    for (const double s : {1e-20, 1e-12, 1e-6, 1e-2, 1.0, 10.0}) {
      const hp::Real50 z = -exp(-1 - hp::Real50(s));
      const Real100 y50 =
          Real100(1 + (principal ? boost::math::lambert_w0(z) : boost::math::lambert_wm1(z)));
      const Real100 y100 = hp::one_plus_w_reference(Real100(s), principal);
      EXPECT_LT(static_cast<double>(abs((y50 - y100) / y100)), 1e-47 / s + 1e-47)
          << "50-digit W at s = " << s << (principal ? " W0" : " W-1");
    }
  }
  for (const double s : {1e-3, 0.1, 1.0, 30.0, 700.0, 1e5}) {
    const Real100 w = hp::one_plus_w_reference(Real100(s), false) - 1;
    const double residual = static_cast<double>(abs(log(-w) + w - (-1 - Real100(s))));
    EXPECT_LT(residual, 1e-80) << "W-1 residual at s = " << s;
  }
  for (const double s : {1e-3, 0.1, 1.0, 30.0}) {
    const Real100 w = hp::one_plus_w_reference(Real100(s), true) - 1;
    const double residual = static_cast<double>(abs(log(-w) + w - (-1 - Real100(s))));
    EXPECT_LT(residual, 1e-80) << "W0 residual at s = " << s;
  }
}

// one_plus_lambert_w(s, branch) = 1 + W(-exp(-1 - s)): target a few ulps, <= 4e-16.
TEST(LambertWAccuracy, OnePlusLambertWBothBranches) {
  std::vector<double> grid = log_grid(1e-300, 1e5, 8);
  for (const double s : log_grid(1e-4, 1e4, 250)) grid.push_back(s);
  for (const double s : log_grid(0.02, 0.08, 3000)) grid.push_back(s); // |1 + W| ~ 0.2 .. 0.4
  // Dense around the places where an implementation is likely to switch methods.
  for (const double centre : {1e-8, 1e-4, 0.01, 0.05, 0.25, 1.0, 30.0, 700.0})
    for (int i = -20; i <= 20; ++i) grid.push_back(centre * std::pow(10.0, i / 40.0));
  for (const double edge : {0.05, 30.0, 700.0}) {
    grid.push_back(std::nextafter(edge, 0.0));
    grid.push_back(std::nextafter(edge, 1e300));
  }
  WorstError principal("one_plus_lambert_w W0", 4e-16);
  WorstError lower("one_plus_lambert_w W-1", 4e-16);
  for (const double s : grid) {
    for (const bool is_principal : {true, false}) {
      const Real100 reference = hp::one_plus_w_reference(Real100(s), is_principal);
      double value;
      try {
        value =
            one_plus_lambert_w(s, is_principal ? LambertBranch::principal : LambertBranch::lower);
      } catch (const std::exception&) {
        value = std::numeric_limits<double>::quiet_NaN();
      }
      (is_principal ? principal : lower)
          .update(relative_error(value, reference), hp::format("s=%.17g", s));
    }
  }
  EXPECT_EQ(one_plus_lambert_w(0.0, LambertBranch::principal), 0.0);
  EXPECT_EQ(one_plus_lambert_w(0.0, LambertBranch::lower), 0.0);
  std::cout << "one_plus_lambert_w against 100-digit references:\n";
  expect_target(principal);
  expect_target(lower);
}

// lambert_w0 / lambert_wm1 wrappers against Boost's W in 100 digits at the exact double z.
// Their header promises "about 1 ulp away from the branch point": asserted as "a few ulps",
// <= 4 eps (8.9e-16), for z + 1/e >= 0.01. Closer, W(z) is ill-conditioned (dW/dz ~ 1/(1 + W)) and Boost's
// double algorithm uses the branch-point series in p = sqrt(2 (e z + 1)) with e z + 1 formed
// in double, i.e. with an absolute error of a few 1e-16; the attainable relative error is then
// ~ 1e-16 / |1 + W| (up to ~1e-9 next to -1/e), which is why the impact formulas use
// one_plus_lambert_w instead. There the wrappers are asserted against that backward-error
// bound, 4 eps + 4 eps / |1 + W| (an error of 4 ulps of 1 in e z + 1), and the raw errors are
// reported.
struct WrapperErrors {
  WorstError w0_far{"lambert_w0 (z+1/e >= 0.01)", 4 * eps};
  WorstError wm1_far{"lambert_wm1 (z+1/e >= 0.01)", 4 * eps};
  WorstError w0_near{"lambert_w0 near branch / bound", 1.0};
  WorstError wm1_near{"lambert_wm1 near branch / bound", 1.0};
  WorstError w0_near_raw{"lambert_w0 (z+1/e < 0.01), info", 1.0};
  WorstError wm1_near_raw{"lambert_wm1 (z+1/e < 0.01), info", 1.0};
};

constexpr double branch_point_double = -0.36787944117144233; // nearest double, below -1/e

WrapperErrors wrapper_errors() {
  const Real100 branch_point_exact = -exp(Real100(-1));
  std::vector<double> z0_grid, zm1_grid;
  for (const double t : log_grid(1e-16, 0.2, 8)) {
    const double z = branch_point_double + t;
    z0_grid.push_back(z);
    zm1_grid.push_back(z);
  }
  for (const double t : log_grid(1e-300, 0.35, 6)) {
    z0_grid.push_back(-t);
    zm1_grid.push_back(-t);
  }
  // Dense uniform grid over the range of the double-precision rational approximations.
  for (int i = 0; i <= 3000; ++i) {
    const double z = -0.36 + 0.359 * i / 3000.0;
    z0_grid.push_back(z);
    zm1_grid.push_back(z);
  }
  for (const double t : log_grid(1e-300, 1e300, 4)) z0_grid.push_back(t);
  for (const double t : log_grid(0.01, 100.0, 200)) z0_grid.push_back(t);
  z0_grid.push_back(0.0);

  WrapperErrors errors;
  for (const bool principal : {true, false}) {
    for (const double z : principal ? z0_grid : zm1_grid) {
      const Real100 distance = Real100(z) - branch_point_exact;
      if (distance <= 0) continue;
      const Real100 zr = z;
      const Real100 reference =
          principal ? boost::math::lambert_w0(zr) : boost::math::lambert_wm1(zr);
      double value;
      try {
        value = principal ? lambert_w0(z) : lambert_wm1(z);
      } catch (const std::exception&) {
        value = std::numeric_limits<double>::quiet_NaN();
      }
      const double error = relative_error(value, reference);
      const std::string where = hp::format("z=%.17g", z);
      if (std::getenv("HP_VERBOSE") && error > 4e-16)
        std::cout << (principal ? "W0 " : "W-1 ") << where << " error " << error << "\n";
      if (distance >= Real100(0.01)) {
        (principal ? errors.w0_far : errors.wm1_far).update(error, where);
      } else {
        const double bound = 4 * eps + 4 * eps / static_cast<double>(abs(1 + reference));
        (principal ? errors.w0_near_raw : errors.wm1_near_raw).update(error, where);
        (principal ? errors.w0_near : errors.wm1_near).update(error / bound, where);
      }
    }
  }
  return errors;
}

TEST(LambertWAccuracy, LambertWWrappersAwayFromBranchPoint) {
  const WrapperErrors errors = wrapper_errors();
  EXPECT_EQ(lambert_w0(0.0), 0.0);
  std::cout << "lambert_w0 / lambert_wm1 against 100-digit Boost W, z + 1/e >= 0.01:\n";
  expect_target(errors.w0_far);
  expect_target(errors.wm1_far);
}

TEST(LambertWAccuracy, LambertWWrappersNearBranchPoint) {
  const WrapperErrors errors = wrapper_errors();
  EXPECT_EQ(lambert_w0(branch_point_double), -1.0);
  EXPECT_EQ(lambert_wm1(branch_point_double), -1.0);
  std::cout << "lambert_w0 / lambert_wm1 against 100-digit Boost W, z + 1/e < 0.01\n"
               "(error / (4 eps + 4 eps / |1 + W|), and raw relative errors for information):\n";
  report(errors.w0_near_raw);
  report(errors.wm1_near_raw);
  expect_target(errors.w0_near);
  expect_target(errors.wm1_near);
}

// log1p_excess(t) = t - log(1 + t): "a few ulps" (header), asserted <= 4 ulps wherever the
// result is a normal double.
TEST(LambertWAccuracy, Log1pExcess) {
  std::vector<double> grid;
  for (const double t : log_grid(1e-300, 1e300, 4)) grid.push_back(t);
  for (const double t : log_grid(1e-300, 0.999999, 4)) grid.push_back(-t);
  for (const double centre : {0.25, 0.5})
    for (int i = -10; i <= 10; ++i) {
      grid.push_back(centre * (1 + i * 0.01));
      grid.push_back(-centre * (1 + i * 0.01));
    }
  WorstError worst("log1p_excess", 4 * eps);
  for (const double t : grid) {
    const Real100 tr = t;
    // Literal in 100 digits where that keeps > 60 digits (|t| >= 1e-15), else the series
    // t^2/2 - t^3/3 + t^4/4 - ... (relative truncation error < |t|^8 < 1e-120).
    Real100 reference = 0;
    if (abs(tr) >= Real100(1e-15)) {
      reference = tr - log1p(tr);
    } else {
      Real100 power = tr * tr;
      for (int k = 2; k < 10; ++k, power *= -tr) reference += power / k;
    }
    // Below the normal range (|t| < ~2e-154) the result underflows: no relative accuracy.
    if (reference < Real100(std::numeric_limits<double>::min())) continue;
    worst.update(relative_error(log1p_excess(t), reference), hp::format("t=%.17g", t));
  }
  std::cout << "log1p_excess against 100 digits:\n";
  expect_target(worst);
}

} // namespace
