// The loading stiffness dF_L/dx of the elastic-plastic contact laws against a fourth-order
// central difference of their loading force (independent of the analytic derivatives).

#include "impact_reduced/ghaednia.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "impact_reduced/thornton.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace impact::reduced;

// Fourth-order central difference with step h; error ~ h^4 F^(5) + eps F / h.
double central_difference(const ElasticPlasticContact& contact, double x, double h) {
  return (-contact.loading_force(x + 2 * h) + 8 * contact.loading_force(x + h) -
          8 * contact.loading_force(x - h) + contact.loading_force(x - 2 * h)) /
         (12 * h);
}

void expect_stiffness_matches(const ElasticPlasticContact& contact, double x) {
  const double h = 1e-3 * x;
  const double analytic = contact.loading_stiffness(x);
  EXPECT_NEAR(analytic, central_difference(contact, x, h), 1e-9 * std::abs(analytic))
      << "x = " << x;
}

TEST(LoadingStiffness, ThorntonOnBothBranches) {
  const ThorntonContact contact(5e-3, 1.1e11, 3.2e9);
  const double x_y = contact.yield_approach();
  for (const double ratio : {0.05, 0.3, 0.9, 1.1, 3.0, 50.0, 1e3})
    expect_stiffness_matches(contact, ratio * x_y);
  // The plastic branch is linear with slope pi p_y R; the Hertz branch 2 E* sqrt(R x).
  EXPECT_DOUBLE_EQ(contact.loading_stiffness(2 * x_y), contact.plastic_stiffness());
  EXPECT_NEAR(contact.loading_stiffness(0.5 * x_y), 2 * 1.1e11 * std::sqrt(5e-3 * 0.5 * x_y),
              1e-14 * contact.plastic_stiffness());
}

TEST(LoadingStiffness, JacksonGreenOnBothBranches) {
  for (const double poisson : {0.0, 0.3, 0.45})
    for (const double yield_strain : {1e-3, 5e-3, 1e-2}) {
      const SphereFlatContact sphere{5e-3, 1.1e11, yield_strain * 1.1e11, poisson};
      const JacksonGreenContact contact(sphere);
      const double critical = contact.critical_interference();
      for (const double ratio : {0.2, 1.0, 1.85, 1.95, 3.0, 10.0, 100.0, 1e3, 1e4})
        expect_stiffness_matches(contact, ratio * critical);
    }
}

// loading_force_and_stiffness (one evaluation of the fit's terms, for Kuwabara-Kono) gives
// exactly the values of the two separate calls, on both sides of the transition.
TEST(LoadingStiffness, ForceAndStiffnessAtOnceAreTheSeparateValues) {
  for (const double poisson : {0.0, 0.3, 0.45})
    for (const double yield_strain : {1e-3, 5e-3, 1e-2}) {
      const SphereFlatContact sphere{5e-3, 1.1e11, yield_strain * 1.1e11, poisson};
      const JacksonGreenContact jackson_green(sphere);
      const GhaedniaContact ghaednia({sphere.radius, 2.1e11 / (1 - poisson * poisson),
                                      sphere.yield_strength, poisson},
                                     2.1e11, 0.02 * 2.1e11);
      const double critical = jackson_green.critical_interference();
      for (const ElasticPlasticContact* law :
           {static_cast<const ElasticPlasticContact*>(&jackson_green),
            static_cast<const ElasticPlasticContact*>(&ghaednia)})
        for (const double ratio : {0.2, 1.0, 1.85, 1.9, 1.95, 3.0, 10.0, 100.0, 1e3}) {
          const double x = ratio * critical;
          const auto [force, stiffness] = law->loading_force_and_stiffness(x);
          EXPECT_EQ(force, law->loading_force(x)) << "x = " << x;
          EXPECT_EQ(stiffness, law->loading_stiffness(x)) << "x = " << x;
        }
    }
}

} // namespace
