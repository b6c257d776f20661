// Thornton's elastic-plastic impact: the closed forms against (a) the form quoted from the
// paper, (b) the library's quadrature of the same law (elastic_plastic_impact) and (c) an
// independent long-double RKF7(8) integration of m x'' = -F(x) with the law re-written here.

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/thornton.hpp"
#include "impact_reduced/contact_formulas.hpp"
#include "plastic_impact_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace impact::reduced;
constexpr long double pi_l = 3.141592653589793238462643383279502884L;

// Steel ball R = 10 mm on a steel flat, Johnson's p_y for Y = 1 GPa.
const ThorntonParameters steel{4.0 / 3.0 * 3.14159265358979323846 * 1e-6 * 7800, 0.01,
                               2.1e11 / 1.82, 1.6e9};

double relative(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// Thornton's law written again in long double for the reference integration.
impact::testing::PlasticReferenceLaw reference_law(const ThorntonParameters& p) {
  const long double R = p.radius, E = p.contact_modulus, py = p.yield_pressure;
  const long double x_y = R * (pi_l * py / (2 * E)) * (pi_l * py / (2 * E));
  const long double c = 4.0L / 3.0L * E * std::sqrt(R);
  const long double f_y = c * std::pow(x_y, 1.5L);
  const long double k = pi_l * py * R;
  impact::testing::PlasticReferenceLaw law;
  law.loading = [=](long double x) {
    return x <= x_y ? c * std::pow(std::max(x, 0.0L), 1.5L) : f_y + k * (x - x_y);
  };
  law.breakpoints = {x_y};
  // Unloading on R_p with a_p^2 = (2 F* + F_y) / (2 pi p_y), R_p = 4 E* a_p^3 / (3 F*).
  const auto branch = [=](long double x_max, long double& stiffness, long double& x_p) {
    if (x_max <= x_y) {
      stiffness = c;
      x_p = 0;
      return;
    }
    const long double f_max = f_y + k * (x_max - x_y);
    const long double a_p = std::sqrt((2 * f_max + f_y) / (2 * pi_l * py));
    const long double r_p = 4 * E * a_p * a_p * a_p / (3 * f_max);
    stiffness = 4.0L / 3.0L * E * std::sqrt(r_p);
    x_p = x_max - 3 * f_max / (4 * E * a_p);
  };
  law.unloading = [=](long double x, long double x_max) {
    long double stiffness, x_p;
    branch(x_max, stiffness, x_p);
    return stiffness * std::pow(std::max(x - x_p, 0.0L), 1.5L);
  };
  law.separation_approach = [=](long double x_max) {
    long double stiffness, x_p;
    branch(x_max, stiffness, x_p);
    return x_p;
  };
  return law;
}

TEST(Thornton, ClosedFormRestitutionIsThePublishedForm) {
  double worst = 0;
  for (double r = 1e-4; r < 1; r *= 1.07) {
    const double velocity = 1.0;
    ThorntonParameters p = steel;
    const ThorntonImpact impact(p, velocity * ThorntonImpact(p, 1.0).yield_velocity() / r);
    worst =
        std::max(worst, relative(impact.response().restitution, thornton_restitution_formula(r)));
  }
  EXPECT_LT(worst, 2e-15);
  EXPECT_EQ(thornton_restitution_formula(1.0), 1.0);
  EXPECT_EQ(thornton_restitution_formula(3.0), 1.0);
}

TEST(Thornton, FarAboveYieldRestitutionFallsLikeVelocityToTheMinusQuarter) {
  // e (V/V_y)^(1/4) -> (3/2) (sqrt(15/2) / (15/4))^(3/4) = 1.18503... as V/V_y -> infinity.
  const double limit = 1.5 * std::pow(std::sqrt(7.5) / 3.75, 0.75);
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const ThorntonImpact far(steel, 1e8 * v_y);
  EXPECT_NEAR(far.response().restitution * std::pow(1e8, 0.25), limit, 1e-3);
  // Log-log slope between V/V_y = 1e6 and 1e7: -1/4 within 1e-3.
  const double e6 = ThorntonImpact(steel, 1e6 * v_y).response().restitution;
  const double e7 = ThorntonImpact(steel, 1e7 * v_y).response().restitution;
  EXPECT_NEAR(std::log10(e7 / e6), -0.25, 1e-3);
}

TEST(Thornton, BelowYieldItIsHertz) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const double velocity = 0.5 * v_y;
  const auto response = ThorntonImpact(steel, velocity).response();
  EXPECT_EQ(response.restitution, 1.0);
  EXPECT_EQ(response.residual_approach, 0.0);
  const double c = 4.0 / 3.0 * steel.contact_modulus * std::sqrt(steel.radius);
  const double x_max = std::pow(1.25 * steel.mass * velocity * velocity / c, 0.4);
  EXPECT_NEAR(response.approach_max, x_max, 1e-15 * x_max);
  // Hertz: t_c = 2.9432 x_max / V (the spec's elastic check value).
  EXPECT_NEAR(response.contact_time * velocity / x_max, 2.9432, 1e-4);
}

TEST(Thornton, ClosedFormsAgreeWithTheQuadratureOfTheLaw) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  for (const double ratio : {0.3, 1.0001, 1.01, 2.0, 10.0, 100.0, 1e4}) {
    const ThorntonImpact closed(steel, ratio * v_y);
    const auto exact = closed.response();
    const auto numeric = elastic_plastic_impact(steel.mass, ratio * v_y, closed.contact());
    EXPECT_LT(relative(numeric.approach_max, exact.approach_max), 1e-14) << ratio;
    EXPECT_LT(relative(numeric.force_max, exact.force_max), 1e-14) << ratio;
    EXPECT_LT(relative(numeric.restitution, exact.restitution), 1e-14) << ratio;
    EXPECT_LT(relative(numeric.compression_time, exact.compression_time), 1e-13) << ratio;
    EXPECT_LT(relative(numeric.contact_time, exact.contact_time), 1e-13) << ratio;
    if (exact.residual_approach > 0) {
      EXPECT_LT(relative(numeric.residual_approach, exact.residual_approach),
                1e-13 * exact.approach_max / exact.residual_approach)
          << ratio;
    }
  }
}

TEST(Thornton, ClosedFormsAgreeWithAnIndependentIntegration) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const auto law = reference_law(steel);
  double worst = 0;
  for (const double ratio : {0.5, 1.5, 4.0, 30.0, 300.0}) {
    const auto exact = ThorntonImpact(steel, ratio * v_y).response();
    const auto ode = impact::testing::integrate_plastic_reference(steel.mass, ratio * v_y, law,
                                                                  exact.approach_max);
    const double errors[] = {relative(double(ode.approach_max), exact.approach_max),
                             relative(double(-ode.rebound_velocity / (ratio * v_y)),
                                      exact.restitution),
                             relative(double(ode.compression_time), exact.compression_time),
                             relative(double(ode.contact_time), exact.contact_time),
                             std::abs(double(ode.separation_approach) - exact.residual_approach) /
                                 exact.approach_max};
    for (const double error : errors) {
      EXPECT_LT(error, 1e-10) << "V/V_y = " << ratio;
      worst = std::max(worst, error);
    }
  }
  std::cout << "Thornton: worst relative difference to the RKF7(8) integration " << worst << "\n";
}

TEST(Thornton, PermanentApproachAndUnloadingRadius) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const ThorntonImpact impact(steel, 10 * v_y);
  const auto response = impact.response();
  // x_p = x_max - 3 F* / (4 E* a_p), a_p^2 = (2 F* + F_y) / (2 pi p_y), by hand.
  const double f_y = impact.contact().yield_force();
  const double a_p = std::sqrt((2 * response.force_max + f_y) / (2 * M_PI * steel.yield_pressure));
  const double x_p =
      response.approach_max - 3 * response.force_max / (4 * steel.contact_modulus * a_p);
  EXPECT_NEAR(response.residual_approach, x_p, 1e-13 * response.approach_max);
  const double r_p = 4 * steel.contact_modulus * a_p * a_p * a_p / (3 * response.force_max);
  EXPECT_NEAR(impact.unloading_radius(), r_p, 1e-13 * r_p);
  EXPECT_GT(r_p, steel.radius);
  // Energy balance: dissipated = m V^2 (1 - e^2) / 2.
  const double v = 10 * v_y;
  EXPECT_NEAR(response.dissipated_energy,
              0.5 * steel.mass * v * v * (1 - response.restitution * response.restitution),
              1e-14 * steel.mass * v * v);
}

TEST(Thornton, LoopEndsAtTheResponseAndKeepsTheEnergyBalance) {
  const double v_y = ThorntonImpact(steel, 1.0).yield_velocity();
  const double velocity = 10 * v_y;
  const ThorntonImpact impact(steel, velocity);
  const auto response = impact.response();
  const auto loop = elastic_plastic_impact_loop(steel.mass, velocity, impact.contact(), 101);
  ASSERT_EQ(loop.size(), 201u);
  EXPECT_EQ(loop.front().time, 0.0);
  EXPECT_EQ(loop.front().approach, 0.0);
  EXPECT_NEAR(loop.front().approach_rate, velocity, 1e-15 * velocity);
  const auto& peak = loop[100];
  EXPECT_NEAR(peak.time, response.compression_time, 1e-13 * response.compression_time);
  EXPECT_NEAR(peak.approach, response.approach_max, 1e-14 * response.approach_max);
  EXPECT_EQ(peak.approach_rate, 0.0);
  EXPECT_NEAR(peak.force, response.force_max, 1e-14 * response.force_max);
  EXPECT_NEAR(loop.back().time, response.contact_time, 1e-13 * response.contact_time);
  EXPECT_NEAR(loop.back().approach, response.residual_approach, 1e-14 * response.approach_max);
  EXPECT_NEAR(loop.back().approach_rate, response.rebound_velocity, 1e-13 * velocity);
  EXPECT_NEAR(loop.back().force, 0.0, 1e-12 * response.force_max);
  const auto unloading = impact.contact().unloading(response.approach_max);
  for (std::size_t i = 1; i < loop.size(); ++i) {
    EXPECT_GT(loop[i].time, loop[i - 1].time) << i;
    const double kinetic = 0.5 * steel.mass * loop[i].approach_rate * loop[i].approach_rate;
    const double total = 0.5 * steel.mass * velocity * velocity;
    if (i <= 100) { // loading: m v^2 / 2 + W_L(x) = m V^2 / 2
      EXPECT_NEAR(kinetic + impact.contact().loading_work(loop[i].approach), total, 1e-13 * total);
    } else { // unloading: m v^2 / 2 = energy released from x_max down to x
      const double released = 0.4 * unloading.stiffness *
                              (std::pow(response.approach_max - unloading.residual_approach, 2.5) -
                               std::pow(loop[i].approach - unloading.residual_approach, 2.5));
      EXPECT_NEAR(kinetic, released, 1e-13 * total);
    }
  }
}

TEST(Thornton, LoopTimesBelowYieldAreHertzs) {
  // Elastic impact: t(x) = (x_H / V) (2/5) B((x/x_H)^(5/2); 2/5, 1/2), the incomplete Beta
  // written here as its series sum_k (1/2)_k / k! w^(k + 2/5) / (k + 2/5).
  const double velocity = 0.5 * ThorntonImpact(steel, 1.0).yield_velocity();
  const ThorntonImpact impact(steel, velocity);
  const double x_h = impact.response().approach_max;
  const auto loop = elastic_plastic_impact_loop(steel.mass, velocity, impact.contact(), 11);
  for (int k = 1; k < 10; ++k) {
    const double w = std::pow(loop[k].approach / x_h, 2.5);
    long double sum = 0, pochhammer = 1, power = std::pow((long double)w, 0.4L);
    for (int n = 0; n < 2000; ++n) {
      sum += pochhammer * power / (n + 0.4L);
      pochhammer *= (n + 0.5L) / (n + 1);
      power *= w;
    }
    const double expected = double(0.4L * x_h / velocity * sum);
    EXPECT_NEAR(loop[k].time, expected, 1e-13 * expected) << k;
  }
}

TEST(Thornton, InvalidInputNamesTheParameter) {
  const auto parameter_of = [](ThorntonParameters p, double velocity) {
    try {
      ThorntonImpact impact(p, velocity);
    } catch (const InvalidInput& error) {
      return error.parameter();
    }
    return std::string("(nothing thrown)");
  };
  ThorntonParameters p = steel;
  EXPECT_EQ(parameter_of(p, 0.0), "velocity");
  p.mass = -1;
  EXPECT_EQ(parameter_of(p, 1.0), "mass");
  p = steel;
  p.radius = NAN;
  EXPECT_EQ(parameter_of(p, 1.0), "radius");
  p = steel;
  p.contact_modulus = 0;
  EXPECT_EQ(parameter_of(p, 1.0), "contact_modulus");
  p = steel;
  p.yield_pressure = INFINITY;
  EXPECT_EQ(parameter_of(p, 1.0), "yield_pressure");
  EXPECT_THROW(thornton_restitution_formula(0.0), InvalidInput);
}

} // namespace
