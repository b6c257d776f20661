// The restitution fit of Jackson, Green & Marghitu (2010) against 30-digit values of the
// formula as read (reduced/include/impact_reduced/jackson_green_marghitu.hpp), computed with
// mpmath (/usr/bin/python3, mp.dps = 30: 1 - 0.0361 eps^-0.114 ln(V*) (V* - 1)^(9.5 eps)),
// and its critical velocity against the yield velocity of Jackson-Green's criterion.

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/jackson_green_marghitu.hpp"
#include "impact_reduced/contact_formulas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace impact::reduced;
constexpr double pi = 3.14159265358979323846;

TEST(JacksonGreenMarghitu, FormulaAgainstHighPrecisionValues) {
  EXPECT_NEAR(jackson_green_marghitu_restitution(2.0, 0.01), 0.9577007503992532263, 4e-16);
  EXPECT_NEAR(jackson_green_marghitu_restitution(10.0, 0.01), 0.8268685648769976726, 4e-16);
  EXPECT_NEAR(jackson_green_marghitu_restitution(50.0, 0.015), 0.6030944791630401161, 4e-16);
  EXPECT_NEAR(jackson_green_marghitu_restitution(1.5, 0.001), 0.9680404317028079856, 4e-16);
}

TEST(JacksonGreenMarghitu, ElasticUpToTheCriticalVelocityAndFallingBeyond) {
  EXPECT_EQ(jackson_green_marghitu_restitution(0.0, 0.01), 1.0);
  EXPECT_EQ(jackson_green_marghitu_restitution(1.0, 0.01), 1.0);
  // Continuous at V* = 1 (ln 1 = 0) and decreasing above it.
  EXPECT_GT(jackson_green_marghitu_restitution(1.0 + 1e-9, 0.01), 1.0 - 1e-9);
  double last = 1.0;
  for (double ratio = 1.1; ratio < 100; ratio *= 1.1) {
    const double e = jackson_green_marghitu_restitution(ratio, 0.01);
    EXPECT_LT(e, last) << "V/V_c = " << ratio;
    last = e;
  }
}

TEST(JacksonGreenMarghitu, TheStudysBallOnARigidFlat) {
  // R = 14.52 mm, E = 200 GPa, nu = 0.3, rho = 7810 kg/m^3, Y = 2.03 GPa on a rigid flat
  // (fem/scenarios/plastic_on_rigid.prm): E* = E / (1 - nu^2), mpmath 30 digits:
  // V_c = 0.22496351852169464451 m/s, eps_y = C Y / E* = 0.014916585596523549494,
  // e(0.5 m/s) = 0.95208801553925251128, e(2 m/s) = 0.82928236407200325748.
  const SphereFlatContact contact{0.01452, 2e11 / (1 - 0.09), 2.03e9, 0.3};
  const double mass = 4.0 / 3.0 * pi * std::pow(0.01452, 3) * 7810;
  const double v_c = jackson_green_marghitu_critical_velocity(contact, mass);
  EXPECT_NEAR(v_c, 0.22496351852169464451, 1e-15);
  EXPECT_NEAR(jackson_green_marghitu_yield_strain(contact), 0.014916585596523549494, 1e-17);
  EXPECT_NEAR(v_c,
              yield_velocity(yield_pressure(YieldCriterion::jackson_green, 2.03e9, 0.3),
                             contact.contact_modulus, contact.radius, mass),
              1e-16);
  EXPECT_NEAR(jackson_green_marghitu_restitution(0.5, contact, mass), 0.95208801553925251128,
              1e-15);
  EXPECT_NEAR(jackson_green_marghitu_restitution(2.0, contact, mass), 0.82928236407200325748,
              1e-15);
  EXPECT_EQ(jackson_green_marghitu_restitution(0.2, contact, mass), 1.0);
}

TEST(JacksonGreenMarghitu, BadInputIsRefusedWithTheParameterNamed) {
  const auto parameter_of = [](auto&& call) {
    try {
      call();
    } catch (const InvalidInput& error) {
      return error.parameter();
    }
    return std::string("none");
  };
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(parameter_of([] { jackson_green_marghitu_restitution(-1.0, 0.01); }), "velocity_ratio");
  EXPECT_EQ(parameter_of([&] { jackson_green_marghitu_restitution(inf, 0.01); }), "velocity_ratio");
  EXPECT_EQ(parameter_of([] { jackson_green_marghitu_restitution(2.0, 0.0); }), "yield_strain");
  EXPECT_EQ(parameter_of([] { jackson_green_marghitu_restitution(2.0, 1.5); }), "yield_strain");
  // Far beyond the fit's reach the formula gives e <= 0: refused, not returned.
  EXPECT_EQ(parameter_of([] { jackson_green_marghitu_restitution(1e4, 0.015); }), "velocity_ratio");
  const SphereFlatContact contact{0.01452, 2e11, 2.03e9, 0.3};
  EXPECT_EQ(parameter_of([&] { jackson_green_marghitu_restitution(-1.0, contact, 0.1); }),
            "velocity");
  EXPECT_EQ(parameter_of([&] { jackson_green_marghitu_restitution(1.0, contact, 0.0); }), "mass");
  EXPECT_EQ(parameter_of([&] {
              jackson_green_marghitu_restitution(1.0, SphereFlatContact{0.01, 2e11, 2e9, 0.6}, 0.1);
            }),
            "poisson_ratio");
}

} // namespace
