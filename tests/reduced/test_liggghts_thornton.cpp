// LIGGGHTS' thornton_ning impact (zero surface energy): the library's closed form and quadrature
// against an independent long-double RKF7(8) integration of m x'' = -F(x) with the law written
// again here, the elastic limit, and the yield-ratio mapping.

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/liggghts_thornton.hpp"
#include "impact_reduced/thornton.hpp"
#include "plastic_impact_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace {

using namespace impact::reduced;
constexpr long double pi_l = 3.141592653589793238462643383279502884L;

// Steel ball R = 10 mm on a steel flat, Johnson's p_y for Y = 1 GPa (as test_thornton.cpp).
const ThorntonParameters steel{4.0 / 3.0 * 3.14159265358979323846 * 1e-6 * 7800, 0.01,
                               2.1e11 / 1.82, 1.6e9};

double relative(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// The LIGGGHTS law in long double: Thornton's loading, unloading F* - c (x_max^1.5 - x^1.5).
impact::testing::PlasticReferenceLaw reference_law(const ThorntonParameters& p) {
  const long double R = p.radius, E = p.contact_modulus, py = p.yield_pressure;
  const long double a_y = pi_l * py * R / (2 * E); // LIGGGHTS' yield contact radius
  const long double x_y = a_y * a_y / R;
  const long double c = 4.0L / 3.0L * E * std::sqrt(R);
  const long double f_y = c * std::pow(x_y, 1.5L);
  const long double k = 2 * E * a_y; // LIGGGHTS' plastic slope
  const auto loading = [=](long double x) {
    return x <= x_y ? c * std::pow(std::max(x, 0.0L), 1.5L) : f_y + k * (x - x_y);
  };
  impact::testing::PlasticReferenceLaw law;
  law.loading = loading;
  law.breakpoints = {x_y};
  law.unloading = [=](long double x, long double x_max) {
    return loading(x_max) - c * (std::pow(x_max, 1.5L) - std::pow(std::max(x, 0.0L), 1.5L));
  };
  law.separation_approach = [=](long double x_max) {
    return std::pow(std::max(std::pow(x_max, 1.5L) - loading(x_max) / c, 0.0L), 2.0L / 3.0L);
  };
  return law;
}

TEST(LiggghtsThornton, AgreesWithAnIndependentIntegration) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const auto law = reference_law(steel);
  double worst = 0;
  for (const double ratio : {0.5, 1.5, 5.0, 20.0, 300.0}) {
    const auto library = LiggghtsThorntonImpact(steel, ratio * v_y).response();
    const auto ode = impact::testing::integrate_plastic_reference(steel.mass, ratio * v_y, law,
                                                                  library.approach_max);
    const double errors[] = {relative(double(ode.approach_max), library.approach_max),
                             relative(double(-ode.rebound_velocity / (ratio * v_y)),
                                      library.restitution),
                             relative(double(ode.compression_time), library.compression_time),
                             relative(double(ode.contact_time), library.contact_time),
                             std::abs(double(ode.separation_approach) - library.residual_approach) /
                                 library.approach_max};
    for (const double error : errors) {
      EXPECT_LT(error, 1e-10) << "V/V_y = " << ratio;
      worst = std::max(worst, error);
    }
  }
  std::cout << "LIGGGHTS thornton_ning: worst relative difference to the RKF7(8) integration "
            << worst << "\n";
}

TEST(LiggghtsThornton, SharesThorntonsLoadingAndDiffersInTheUnloading) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  for (const double ratio : {1.5, 5.0, 20.0}) {
    const auto thornton = ThorntonImpact(steel, ratio * v_y).response();
    const LiggghtsThorntonImpact liggghts(steel, ratio * v_y);
    const auto response = liggghts.response();
    EXPECT_EQ(response.approach_max, thornton.approach_max);
    EXPECT_EQ(response.force_max, thornton.force_max);
    EXPECT_EQ(response.compression_time, thornton.compression_time);
    // The unloading branch leaves the peak at the Hertz slope 2 E* sqrt(R x_max), stiffer than
    // Thornton's on R_p: less energy comes back.
    EXPECT_LT(response.restitution, thornton.restitution) << ratio;
    EXPECT_NEAR(liggghts.unloading_force(response.approach_max), response.force_max,
                1e-12 * response.force_max);
    EXPECT_EQ(liggghts.unloading_force(response.residual_approach * 0.999), 0.0);
  }
}

TEST(LiggghtsThornton, BelowYieldItIsHertz) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const auto hertz = ThorntonImpact(steel, 0.7 * v_y).response();
  const auto response = LiggghtsThorntonImpact(steel, 0.7 * v_y).response();
  EXPECT_EQ(response.restitution, 1.0);
  EXPECT_EQ(response.contact_time, hertz.contact_time);
}

TEST(LiggghtsThornton, YieldRatioIsThorntonsLimitingContactRadiusOverR) {
  // a_y = pi p_y R / (2 E*), by hand for p_y = 1.6 GPa, E* = 2.1e11 / 1.82 Pa.
  EXPECT_NEAR(liggghts_yield_ratio(1.6e9, 2.1e11 / 1.82),
              3.14159265358979323846 * 1.6e9 * 1.82 / (2 * 2.1e11), 1e-16);
  EXPECT_THROW(liggghts_yield_ratio(0, 1e11), InvalidInput);
  try {
    liggghts_yield_ratio(1e11, 1e11);
    FAIL() << "a ratio above 1 was accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.parameter(), "yield_pressure");
  }
  EXPECT_THROW(LiggghtsThorntonImpact(steel, -1.0), InvalidInput);
  const LiggghtsThorntonImpact impact(steel, 5.0);
  EXPECT_THROW(impact.unloading_force(2 * impact.response().approach_max), InvalidInput);
}

} // namespace
