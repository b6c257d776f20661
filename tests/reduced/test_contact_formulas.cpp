// The contact formulas: E*, effective radius and mass, the Hertz impact (coefficient, peak
// approach, peak force, contact time) and the yield velocity for both criteria, against values
// worked out here from the formulas with numbers (and 30-digit values from mpmath, command in
// the comment).

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/contact_formulas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace impact::reduced;
constexpr double pi = 3.14159265358979323846;

// A steel ball, R = 10 mm, rho = 7800 kg/m^3, on a steel flat: E = 210 GPa, nu = 0.3,
// Y = 1 GPa.
constexpr double youngs = 2.1e11, poisson = 0.3, strength = 1e9, radius = 0.01, density = 7800;

TEST(YieldVelocity, ContactModulusAndEffectiveQuantities) {
  // 1/E* = 2 (1 - 0.09) / 2.1e11  =>  E* = 2.1e11 / 1.82 = 1.1538461538461538e11 Pa.
  EXPECT_NEAR(contact_modulus(youngs, poisson, youngs, poisson), 2.1e11 / 1.82, 1e-4);
  EXPECT_DOUBLE_EQ(effective_radius(0.01, 0.02), 0.02 / 3);
  EXPECT_DOUBLE_EQ(effective_radius(0.01, std::numeric_limits<double>::infinity()), 0.01);
  EXPECT_DOUBLE_EQ(effective_mass(2.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(effective_mass(2.0, std::numeric_limits<double>::infinity()), 2.0);
  // A rigid flat (infinite modulus): E* is the sphere's own, E / (1 - nu^2).
  const double rigid = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(contact_modulus(youngs, poisson, rigid, 0.0), youngs / 0.91);
  EXPECT_DOUBLE_EQ(contact_modulus(rigid, 0.0, youngs, poisson), youngs / 0.91);
}

TEST(YieldVelocity, JohnsonCriterionByHand) {
  const double e_star = 2.1e11 / 1.82;
  const double p_y = 1.6 * 1e9; // Johnson: 1.6 Y
  EXPECT_DOUBLE_EQ(yield_pressure(YieldCriterion::johnson, strength, poisson), p_y);
  // m = 4/3 pi R^3 rho = 0.032672563597333850 kg.
  const double mass = 4.0 / 3.0 * pi * 1e-6 * 7800;
  EXPECT_NEAR(mass, 0.0326725635973338497, 1e-17);
  // x_y = R (pi p_y / (2 E*))^2 = 0.01 (pi 1.6e9 / 2.3076923e11)^2 = 4.7442e-6 m.
  const double x_y = 0.01 * std::pow(pi * 1.6e9 / (2 * e_star), 2);
  EXPECT_NEAR(yield_approach(p_y, e_star, radius), x_y, 1e-15 * x_y);
  // F_y = (4/3) E* sqrt(R) x_y^(3/2) must equal pi^3 R^2 p_y^3 / (6 E*^2).
  EXPECT_NEAR(yield_force(p_y, e_star, radius), 4.0 / 3.0 * e_star * 0.1 * std::pow(x_y, 1.5),
              1e-13 * yield_force(p_y, e_star, radius));
  // (1/2) m V_y^2 = (8/15) E* sqrt(R) x_y^(5/2).
  const double by_energy = std::sqrt(2 * 8.0 / 15.0 * e_star * 0.1 * std::pow(x_y, 2.5) / mass);
  // mpmath, 30 digits: sqrt(pi^5 R^3 p_y^5 / (30 m E*^4)) = 0.135902232645787693117451561 m/s
  // (python3 -c "from mpmath import *; mp.dps=30; E=mpf('2.1e11')/mpf('1.82'); ...").
  const double v_y = yield_velocity(p_y, e_star, radius, mass);
  EXPECT_NEAR(v_y, 0.135902232645787693, 2e-16 * 5);
  EXPECT_NEAR(v_y, by_energy, 1e-14);
  // The half-space form 1.56 sqrt(p_y^5 / (E*^4 rho)) is the same number.
  EXPECT_NEAR(half_space_yield_velocity(p_y, e_star, density), v_y, 1e-15);
  EXPECT_NEAR(pi * pi / std::sqrt(40.0), 1.5605, 1e-4);
}

TEST(YieldVelocity, JacksonGreenCriterionByHand) {
  const double e_star = 2.1e11 / 1.82;
  // C(0.3) = 1.295 exp(0.2208) = 1.6149608181154712; p_y = C Y.
  const double c = 1.295 * std::exp(0.736 * 0.3);
  EXPECT_NEAR(jackson_green_yield_coefficient(0.3), 1.61496081811547117, 1e-15);
  const double p_y = yield_pressure(YieldCriterion::jackson_green, strength, poisson);
  EXPECT_DOUBLE_EQ(p_y, c * 1e9);
  const double mass = 4.0 / 3.0 * pi * 1e-6 * 7800;
  // mpmath: 0.139101434886517900717964209714 m/s.
  EXPECT_NEAR(yield_velocity(p_y, e_star, radius, mass), 0.139101434886517901, 1e-15);
  // Jackson-Green's omega_c is the approach at which p0 = C Y.
  const double omega_c = std::pow(pi * c * strength / (2 * e_star), 2) * radius;
  EXPECT_NEAR(yield_approach(p_y, e_star, radius), omega_c, 1e-15 * omega_c);
}

TEST(YieldVelocity, TwoSpheresUseEffectiveRadiusAndMass) {
  const double e_star = 2.1e11 / 1.82;
  const double m1 = 4.0 / 3.0 * pi * std::pow(0.01, 3) * 7800;
  const double m2 = 4.0 / 3.0 * pi * std::pow(0.02, 3) * 7800;
  // R = 0.02/3 m, m = m1 m2 / (m1 + m2) = 8/9 m1; mpmath: 0.0784631906015166711 m/s.
  const double v_y =
      yield_velocity(1.6e9, e_star, effective_radius(0.01, 0.02), effective_mass(m1, m2));
  EXPECT_NEAR(v_y, 0.0784631906015166711, 1e-15);
}

// mpmath, mp.dps = 30: Es = 1/(2 (1 - 0.3^2)/210e9), c = 4/3 Es sqrt(0.01),
// m = 4/3 pi 0.01^3 7800, x = (5 m / (4 c))^0.4, F = c x^1.5, t = 0.8 beta(0.4, 0.5) x
// (and 2 quad(1/sqrt(1 - u^2.5), [0, 1]) = 2.9432751843247046... for the factor).
TEST(HertzImpact, AgainstMpmath) {
  const double e_star = contact_modulus(youngs, poisson, youngs, poisson);
  const double c = hertz_coefficient(e_star, radius);
  EXPECT_NEAR(c / 15384615384.6153846153846153846, 1.0, 4e-16);
  const double mass = solid_sphere_mass(radius, density);
  EXPECT_NEAR(hertz_peak_approach(c, mass, 1.0) / 0.0000234208489227732190356612054841, 1.0, 1e-15);
  EXPECT_NEAR(hertz_peak_force(c, mass, 1.0) / 1743.77558351251172447323665832, 1.0, 1e-15);
  EXPECT_NEAR(hertz_contact_time(c, mass, 1.0) / 0.0000689340034302164078340830985446, 1.0, 1e-15);
  // The body-level stiffness is the same c.
  EXPECT_NEAR(hertz_stiffness({youngs, poisson, radius}, {youngs, poisson}) / c, 1.0, 4e-16);
  // x_max scales as V^(4/5), t_c as V^(-1/5).
  EXPECT_NEAR(hertz_peak_approach(c, mass, 2.0) / hertz_peak_approach(c, mass, 1.0),
              std::pow(2.0, 0.8), 1e-15);
  EXPECT_NEAR(hertz_contact_time(c, mass, 2.0) / hertz_contact_time(c, mass, 1.0),
              std::pow(2.0, -0.2), 1e-15);
}

TEST(HertzImpact, InvalidInputNamesTheParameter) {
  const auto names = [](auto call, const char* parameter) {
    try {
      call();
      ADD_FAILURE() << "no throw for " << parameter;
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.parameter(), parameter);
    }
  };
  names([] { hertz_coefficient(0.0, 0.01); }, "contact_modulus");
  names([] { hertz_coefficient(1e11, -1.0); }, "radius");
  names([] { hertz_peak_approach(1e10, 0.0, 1.0); }, "mass");
  names([] { hertz_peak_force(1e10, 1.0, std::nan("")); }, "velocity");
  names([] { hertz_contact_time(-1.0, 1.0, 1.0); }, "coefficient");
}

TEST(YieldVelocity, InvalidInputNamesTheParameter) {
  const auto parameter_of = [](auto call) {
    try {
      call();
    } catch (const InvalidInput& error) {
      return error.parameter();
    }
    return std::string("(nothing thrown)");
  };
  EXPECT_EQ(parameter_of([] { yield_velocity(-1, 1e11, 0.01, 1); }), "yield_pressure");
  EXPECT_EQ(parameter_of([] { yield_velocity(1e9, 0, 0.01, 1); }), "contact_modulus");
  EXPECT_EQ(parameter_of([] { yield_velocity(1e9, 1e11, NAN, 1); }), "radius");
  EXPECT_EQ(parameter_of([] { yield_velocity(1e9, 1e11, 0.01, -2); }), "mass");
  EXPECT_EQ(parameter_of([] { jackson_green_yield_coefficient(0.5); }), "poisson_ratio");
  EXPECT_EQ(parameter_of([] { johnson_yield_pressure(0); }), "yield_strength");
  EXPECT_EQ(parameter_of([] { half_space_yield_velocity(1e9, 1e11, 0); }), "density");
  EXPECT_EQ(parameter_of([] { contact_modulus(1e11, 0.3, 1e11, -1); }), "poisson_ratio_2");
  EXPECT_EQ(parameter_of([] {
              contact_modulus(std::numeric_limits<double>::infinity(), 0.3,
                              std::numeric_limits<double>::infinity(), 0.3);
            }),
            "youngs_modulus_2");
  EXPECT_EQ(parameter_of([] {
              effective_radius(std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity());
            }),
            "radius_2");
}

} // namespace
