// Hunt-Crossley impact: the published example, agreement with a direct ODE integration,
// the Hertz limit, the general-law path, the time history and invalid input.
// (The accuracy table of the spec, against 50-digit references, is in
// test_hunt_crossley_accuracy.cpp.)

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/hunt_crossley.hpp"
#include "impact_reduced/impact_ode.hpp"
#include "impact_reduced/invalid_input.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

namespace {

using namespace impact::reduced;

// The published steel example.
constexpr double mass = 0.1;
constexpr double stiffness = 1.7135e10;
constexpr double exponent = 1.5;
constexpr double damping = 0.1;

// |value - printed| within half a unit of the printed value's last digit.
void expect_printed(double value, double printed, int significant_digits, const char* name) {
  const double unit =
      std::pow(10.0, std::floor(std::log10(std::fabs(printed))) - (significant_digits - 1));
  EXPECT_LE(std::fabs(value - printed), 0.5 * unit)
      << name << ": computed " << value << ", published " << printed;
}

TEST(HuntCrossley, PublishedExampleToAllPrintedDigits) {
  const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, 1.0);
  const ImpactResponse response = impact.response();
  expect_printed(response.approach_max, 3.42046253e-5, 9, "x_max");
  expect_printed(response.force_max, 3441.11223, 9, "force_max");
  expect_printed(response.restitution, 0.937475580, 9, "restitution");
  // The published contact time 1.03994694e-4 is one unit above the correctly rounded
  // 1.03994693e-4: the exact value is 1.039946934950e-4 (closed form here, ODE at rtol 1e-13
  // and the 50-digit reference agree), which rounds to ...694 only through ...6935.
  expect_printed(response.contact_time, 1.039946935e-4, 10, "contact_time");
  EXPECT_LE(std::fabs(response.contact_time - 1.03994694e-4), 1e-12);
  std::cout << std::setprecision(12) << "published example: x_max " << response.approach_max
            << " m, force_max " << response.force_max << " N, contact_time "
            << response.contact_time << " s, restitution " << response.restitution << '\n';
}

TEST(HuntCrossley, DampingForRestitutionNinetyPercent) {
  expect_printed(damping_from_restitution(0.9, 1.0), 0.166481951, 9, "damping");
  EXPECT_NEAR(restitution_from_impact_parameter(impact_parameter_from_restitution(0.9)), 0.9,
              1e-15);
}

TEST(HuntCrossley, HertzStiffnessOfTheSteelBallOnASteelPlate) {
  const double density = 7800.0;
  const double radius =
      std::cbrt(3.0 * mass / (4.0 * boost::math::constants::pi<double>() * density));
  EXPECT_NEAR(radius, 14.52e-3, 0.005e-3);
  // The published check value 1.7135e10 is 1.5e-4 below the formula's 1.71376e10 for
  // R = 14.52 mm (it corresponds to R = 14.516 mm): agreement to 2e-4 is what it supports.
  const double c = hertz_stiffness({2e11, 0.25, 14.52e-3}, {2e11, 0.25});
  EXPECT_NEAR(c / 1.7135e10, 1.0, 2e-4) << c;
  EXPECT_NEAR(c, 4.0 / 3.0 * 2e11 / (2 * (1 - 0.0625)) * std::sqrt(14.52e-3), 1e-15 * c);
  EXPECT_NEAR(hertz_stiffness({2e11, 0.25, radius}, {2e11, 0.25}) / c, 1.0, 2e-4);
  // Symmetric in the two bodies, and two equal spheres have half the curvature radius.
  EXPECT_EQ(hertz_stiffness({2e11, 0.25}, {2e11, 0.25, 14.52e-3}), c);
  EXPECT_NEAR(hertz_stiffness({2e11, 0.25, 2 * 14.52e-3}, {2e11, 0.25, 2 * 14.52e-3}) / c, 1.0,
              1e-15);
}

// A rigid flat, named: c = (4/3) E/(1 - nu^2) sqrt(R) (the flat's compliance 0), twice the c
// of two equal bodies; two rigid bodies have no Hertz contact. The solid sphere's mass.
TEST(HuntCrossley, HertzStiffnessOnARigidFlatAndTheSphereMass) {
  const double c = hertz_stiffness({2e11, 0.25, 14.52e-3}, rigid_body());
  EXPECT_NEAR(c, 4.0 / 3.0 * 2e11 / (1 - 0.0625) * std::sqrt(14.52e-3), 1e-15 * c);
  EXPECT_NEAR(c / hertz_stiffness({2e11, 0.25, 14.52e-3}, {2e11, 0.25}), 2.0, 1e-15);
  EXPECT_EQ(hertz_stiffness(rigid_body(), {2e11, 0.25, 14.52e-3}), c);
  EXPECT_THROW(hertz_stiffness(rigid_body(0.01), rigid_body()), InvalidInput);
  EXPECT_THROW(hertz_stiffness({-2e11, 0.25, 0.01}, rigid_body()), InvalidInput);
  const double pi = boost::math::constants::pi<double>();
  EXPECT_NEAR(solid_sphere_mass(14.52e-3, 7800), 4.0 / 3.0 * pi * std::pow(14.52e-3, 3) * 7800,
              1e-15);
  EXPECT_THROW(solid_sphere_mass(0, 7800), InvalidInput);
  EXPECT_THROW(solid_sphere_mass(1e300, 7800), InvalidInput); // overflows
}

// Every quantity of the closed form against a direct integration of m x'' = -F at rtol 1e-13,
// at the other velocities of the published example.
TEST(HuntCrossley, OtherVelocitiesAgreeWithOdeIntegration) {
  double worst = 0.0;
  for (const double velocity : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0}) {
    const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, velocity);
    const ImpactResponse closed = impact.response();
    const OdeImpactResult ode = integrate_impact(
        mass, velocity,
        [](double x, double v) { return stiffness * std::pow(x, exponent) * (1 + damping * v); },
        1e-13);
    const std::pair<double, double> pairs[] = {{closed.approach_max, ode.approach_max},
                                               {closed.force_max, ode.force_max},
                                               {closed.time_force_max, ode.time_force_max},
                                               {closed.compression_time, ode.compression_time},
                                               {closed.contact_time, ode.contact_time},
                                               {closed.restitution, ode.restitution},
                                               {closed.rebound_velocity, ode.rebound_velocity}};
    for (const auto& [exact, integrated] : pairs) {
      const double error = std::fabs(exact / integrated - 1.0);
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-10) << "V = " << velocity << ": " << exact << " vs " << integrated;
    }
  }
  std::cout << "worst relative difference closed form vs ODE (rtol 1e-13): " << worst << '\n';
}

// b = 0: t_c V / x_max = 2 (1/p) B(1/p, 1/2), p = n + 1, and beta -> 0 is continuous.
TEST(HuntCrossley, HertzLimit) {
  using Real = boost::multiprecision::cpp_bin_float_50;
  for (const double n : {1.0, 1.5, 2.0, 3.0}) {
    const Real p = Real(n) + 1;
    const double exact = static_cast<double>(2 / p * boost::math::beta(1 / p, Real(0.5)));
    const HuntCrossleyImpact elastic(mass, stiffness, n, 0.0, 1.0);
    const double ratio = elastic.contact_time() * 1.0 / elastic.approach_max();
    EXPECT_NEAR(ratio / exact, 1.0, 1e-12) << "n = " << n;
    EXPECT_EQ(elastic.restitution(), 1.0);
    const HuntCrossleyImpact tiny(mass, stiffness, n, 1e-12, 1.0);
    EXPECT_NEAR(tiny.contact_time() / elastic.contact_time(), 1.0, 1e-11);
    EXPECT_NEAR(tiny.restitution(), 1.0 - 2.0 / 3.0 * 1e-12, 1e-15);
    if (n == 1.5) {
      EXPECT_NEAR(ratio, 2.94327518432, 1e-11);
      std::cout << std::setprecision(15) << "Hertz: t_c V / x_max = " << ratio << " (exact "
                << exact << ")\n";
    }
  }
  EXPECT_NEAR(HuntCrossleyImpact(mass, stiffness, 1.0, 0.0, 1.0).contact_time(),
              boost::math::constants::pi<double>() * std::sqrt(mass / stiffness), 1e-18);
}

TEST(HuntCrossley, LargeImpactParameterStaysFinite) {
  const HuntCrossleyImpact impact(mass, stiffness, exponent, 1e4, 1.0);
  const ImpactResponse response = impact.response();
  for (const double value : {response.approach_max, response.force_max, response.time_force_max,
                             response.compression_time, response.contact_time, response.restitution,
                             response.energy_loss})
    EXPECT_TRUE(std::isfinite(value));
  EXPECT_NEAR(response.restitution * 1e4, 1.0, 1e-3);
}

// The general-law path (tanh-sinh, root-found inverse potential) against the power-law fast
// path (closed-form inverse, Gauss-Jacobi), on the same law.
TEST(HuntCrossley, CustomLawMatchesThePowerLaw) {
  const auto custom = std::make_shared<CustomElasticForce>(
      [](double x) { return stiffness * std::pow(x, exponent); },
      [](double x) { return stiffness * std::pow(x, exponent + 1) / (exponent + 1); },
      [](double x) { return exponent * stiffness * std::pow(x, exponent - 1); });
  for (const double velocity : {0.5, 2.0}) {
    const ImpactResponse general = HuntCrossleyImpact(mass, custom, damping, velocity).response();
    const ImpactResponse power =
        HuntCrossleyImpact(mass, stiffness, exponent, damping, velocity).response();
    EXPECT_NEAR(general.approach_max / power.approach_max, 1.0, 1e-14);
    EXPECT_NEAR(general.force_max / power.force_max, 1.0, 1e-13);
    EXPECT_NEAR(general.time_force_max / power.time_force_max, 1.0, 1e-12);
    EXPECT_NEAR(general.contact_time / power.contact_time, 1.0, 1e-12);
    EXPECT_EQ(general.restitution, power.restitution);
  }
}

// Restitution depends on beta alone, whatever the elastic law (a hardening exponential here).
TEST(HuntCrossley, RestitutionIndependentOfTheElasticLaw) {
  const double k0 = 1e7, length = 1e-5;
  const auto exponential = std::make_shared<CustomElasticForce>(
      [=](double x) { return k0 * length * std::expm1(x / length); },
      [=](double x) { return k0 * length * length * (std::expm1(x / length) - x / length); },
      [=](double x) { return k0 * std::exp(x / length); });
  const HuntCrossleyImpact impact(mass, exponential, 0.3, 2.0);
  EXPECT_EQ(impact.restitution(), restitution_from_impact_parameter(0.6));
  const OdeImpactResult ode = integrate_impact(
      mass, 2.0, [&](double x, double v) { return exponential->force(x) * (1 + 0.3 * v); }, 1e-12);
  EXPECT_NEAR(impact.restitution() / ode.restitution, 1.0, 1e-10);
  EXPECT_NEAR(impact.contact_time() / ode.contact_time, 1.0, 1e-9);
  EXPECT_NEAR(impact.force_peak().force / ode.force_max, 1.0, 1e-9);
}

TEST(HuntCrossley, HistoryFollowsTheOdeSolution) {
  const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, 2.0);
  const auto history = impact.history(41);
  ASSERT_EQ(history.size(), 41u);
  EXPECT_EQ(history.front().time, 0.0);
  EXPECT_EQ(history.front().approach, 0.0);
  EXPECT_EQ(history.back().approach, 0.0);
  EXPECT_DOUBLE_EQ(history.back().time, impact.contact_time());
  EXPECT_DOUBLE_EQ(history.back().approach_rate, impact.rebound_velocity());
  const auto ode = integrate_impact_history(
      mass, 2.0,
      [](double x, double v) { return stiffness * std::pow(x, exponent) * (1 + damping * v); }, 41,
      1e-13);
  ASSERT_EQ(ode.size(), history.size());
  const double force_scale = impact.force_peak().force;
  const double approach_scale = impact.approach_max();
  for (std::size_t i = 0; i < history.size(); ++i) {
    EXPECT_NEAR(history[i].time, ode[i].time, 1e-12 * impact.contact_time()) << i;
    EXPECT_NEAR(history[i].approach, ode[i].approach, 1e-9 * approach_scale) << i;
    EXPECT_NEAR(history[i].approach_rate, ode[i].approach_rate, 1e-9 * 2.0) << i;
    EXPECT_NEAR(history[i].force, ode[i].force, 1e-9 * force_scale) << i;
    EXPECT_LE(history[i].force, force_scale * (1 + 1e-14));
    if (i > 0) {
      EXPECT_GT(history[i].time, history[i - 1].time);
    }
  }
}

TEST(HuntCrossley, ApproachRateMatchesTheHistory) {
  const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, 3.0);
  for (const auto& state : impact.history(9)) {
    if (state.approach == 0.0) continue;
    const ImpactPhase phase =
        state.approach_rate >= 0 ? ImpactPhase::compression : ImpactPhase::restitution;
    EXPECT_NEAR(impact.approach_rate(state.approach, phase), state.approach_rate, 1e-9 * 3.0);
  }
  // At the double nearest x_max the rate is ~V sqrt((n + 1) eps): v(x) is that steep there.
  EXPECT_LE(impact.approach_rate(impact.approach_max(), ImpactPhase::compression), 1e-7 * 3.0);
  EXPECT_DOUBLE_EQ(impact.approach_rate(0.0, ImpactPhase::restitution), impact.rebound_velocity());
}

void expect_invalid(const std::function<void()>& call, const std::string& parameter) {
  try {
    call();
    ADD_FAILURE() << "no error for bad " << parameter;
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.parameter(), parameter);
    EXPECT_NE(std::string(error.what()).find(parameter), std::string::npos) << error.what();
  }
}

TEST(HuntCrossley, InvalidInputNamesTheParameter) {
  const double nan = std::nan(""), inf = INFINITY;
  for (const double bad : {0.0, -1.0, nan, inf}) {
    expect_invalid([&] { HuntCrossleyImpact(bad, stiffness, exponent, damping, 1.0); }, "mass");
    expect_invalid([&] { HuntCrossleyImpact(mass, bad, exponent, damping, 1.0); }, "stiffness");
    expect_invalid([&] { HuntCrossleyImpact(mass, stiffness, bad, damping, 1.0); }, "exponent");
    expect_invalid([&] { HuntCrossleyImpact(mass, stiffness, exponent, damping, bad); },
                   "velocity");
    expect_invalid([&] { impact_parameter_from_restitution(bad); }, "restitution");
    expect_invalid([&] { damping_from_restitution(0.5, bad); }, "velocity");
  }
  for (const double bad : {-1.0, nan, inf}) {
    expect_invalid([&] { HuntCrossleyImpact(mass, stiffness, exponent, bad, 1.0); }, "damping");
    expect_invalid([&] { restitution_from_impact_parameter(bad); }, "beta");
  }
  expect_invalid([&] { impact_parameter_from_restitution(1.5); }, "restitution");
  const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, 1.0);
  expect_invalid([&] { impact.approach_rate(2 * impact.approach_max(), ImpactPhase::compression); },
                 "approach");
  expect_invalid([&] { impact.history(1); }, "points");
}

} // namespace
