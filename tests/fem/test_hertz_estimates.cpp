// The FEM's Hertz estimates (time step, run length, contact zone) are the reduced library's
// contact formulas: the same numbers, bit for bit, except the contact time, whose factor the
// FEM keeps rounded to five digits (every run's step is a fraction of it).
#include <impact_fem/hertz.h>
#include <impact_reduced/contact_formulas.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

// A 10 mm steel ball (7800 kg/m^3) on a steel half-space, E = 210 GPa, nu = 0.3, at 1 m/s:
// E*, c, x_max, F_max and t_c worked out with 30-digit mpmath (t_c from (4/5) B(2/5, 1/2)).
constexpr double e_star = 115384615384.615384615384615385;
constexpr double mass = 0.0326725635973338496800114911861;
constexpr double approach = 0.0000234208489227732190356612054841;
constexpr double force = 1743.77558351251172447323665832;
constexpr double contact_time = 0.0000689340034302164078340830985446;

TEST(HertzEstimates, AreTheLibrarysFormulas) {
  const impact_fem::HertzImpact hertz{e_star, 0.01, mass, 1.0};
  EXPECT_EQ(hertz.stiffness(), impact::reduced::hertz_coefficient(e_star, 0.01));
  EXPECT_EQ(hertz.approach_max(),
            impact::reduced::hertz_peak_approach(hertz.stiffness(), mass, 1.0));
  EXPECT_EQ(hertz.force_max(), impact::reduced::hertz_peak_force(hertz.stiffness(), mass, 1.0));
  EXPECT_NEAR(hertz.approach_max() / approach, 1.0, 1e-14);
  EXPECT_NEAR(hertz.force_max() / force, 1.0, 1e-14);
}

TEST(HertzEstimates, ContactTimeWithinItsRoundedFactor) {
  const impact_fem::HertzImpact hertz{e_star, 0.01, mass, 1.0};
  const double exact = impact::reduced::hertz_contact_time(hertz.stiffness(), mass, 1.0);
  EXPECT_NEAR(exact / contact_time, 1.0, 1e-14);
  // 2.9432 against 2.943275...: 2.6e-5 short.
  EXPECT_NEAR(hertz.contact_time() / exact, 1.0, 3e-5);
  EXPECT_LT(hertz.contact_time(), exact);
}

} // namespace
