// The dissipative constant A of the viscoelastic-sphere law from the material: Brilliantov's
// formula in the viscosities (eta1, eta2), evaluated here independently, against the
// library's form in the retardation times; A = tau for equal retardation times; the
// two-body mean; and A from the material reproduces the restitution of a law integrated
// with it (the no-fit prediction in postprocess/ rests on this).

#include "impact_reduced/comparison_laws.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/viscoelastic_dissipation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using namespace impact::reduced;

// Brilliantov et al. (1996): A = (1/3) (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1)
//                                  (1 - nu^2)(1 - 2 nu) / (Y nu^2).
double brilliantov(double young, double nu, double tau_d, double tau_v) {
  const double eta1 = tau_d * young / (1 + nu);
  const double eta2 = tau_v * young / (3 * (1 - 2 * nu));
  return (3 * eta2 - eta1) * (3 * eta2 - eta1) / (3 * (3 * eta2 + 2 * eta1)) * (1 - nu * nu) *
         (1 - 2 * nu) / (young * nu * nu);
}

TEST(ViscoelasticDissipation, RetardationTimeFormAgreesWithTheViscosityForm) {
  double worst = 0;
  for (const double nu : {0.1, 0.25, 0.3, 0.45})
    for (const double tau_d : {0.0, 1e-7, 1e-6})
      for (const double tau_v : {0.0, 5e-7, 2e-6}) {
        if (tau_d == 0 && tau_v == 0) continue;
        const double a = kuwabara_kono_dissipative_constant(nu, tau_d, tau_v);
        const double reference = brilliantov(2e11, nu, tau_d, tau_v);
        worst = std::max(worst, std::abs(a - reference) / reference);
        EXPECT_NEAR(a, reference, 1e-13 * reference) << nu << " " << tau_d << " " << tau_v;
      }
  std::printf("worst relative difference to the viscosity form: %.2e\n", worst);
  EXPECT_EQ(kuwabara_kono_dissipative_constant(0.25, 0, 0), 0.0);
}

TEST(ViscoelasticDissipation, EqualRetardationTimesGiveTheRetardationTime) {
  for (const double nu : {0.05, 0.25, 0.3, 0.49})
    for (const double tau : {1e-8, 1.017e-6, 1e-4})
      EXPECT_NEAR(kuwabara_kono_dissipative_constant(nu, tau, tau), tau, 1e-14 * tau) << nu;
}

TEST(ViscoelasticDissipation, TwoBodiesTakeTheComplianceWeightedMean) {
  const KelvinVoigtBody steel{2e11, 0.25, 1e-6, 1e-6};
  EXPECT_NEAR(kuwabara_kono_dissipative_constant(steel, steel), 1e-6, 1e-20);
  const KelvinVoigtBody soft{7e10, 0.33, 3e-6, 3e-6};
  const double k1 = (1 - 0.25 * 0.25) / 2e11, k2 = (1 - 0.33 * 0.33) / 7e10;
  EXPECT_NEAR(kuwabara_kono_dissipative_constant(steel, soft), (k1 * 1e-6 + k2 * 3e-6) / (k1 + k2),
              1e-20);
  // An elastic plate halves nothing: only the sphere's compliance share dissipates.
  const KelvinVoigtBody elastic{2e11, 0.25, 0, 0};
  EXPECT_NEAR(kuwabara_kono_dissipative_constant(steel, elastic), 0.5e-6, 1e-20);
}

TEST(ViscoelasticDissipation, InvalidInputIsNamed) {
  const auto parameter = [](auto call) {
    try {
      call();
    } catch (const InvalidInput& error) {
      return error.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter([] { kuwabara_kono_dissipative_constant(0.0, 1e-6, 1e-6); }),
            "poisson_ratio");
  EXPECT_EQ(parameter([] { kuwabara_kono_dissipative_constant(0.5, 1e-6, 1e-6); }),
            "poisson_ratio");
  EXPECT_EQ(parameter([] { kuwabara_kono_dissipative_constant(0.25, -1e-6, 1e-6); }),
            "deviatoric_retardation_time");
  EXPECT_EQ(parameter([] { kuwabara_kono_dissipative_constant(0.25, 1e-6, NAN); }),
            "volumetric_retardation_time");
  const KelvinVoigtBody steel{2e11, 0.25, 1e-6, 1e-6};
  EXPECT_EQ(parameter([&] {
              kuwabara_kono_dissipative_constant(steel, {0, 0.25, 1e-6, 1e-6});
            }),
            "second.youngs_modulus");
  EXPECT_EQ(parameter([&] {
              kuwabara_kono_dissipative_constant({2e11, 0.7, 1e-6, 1e-6}, steel);
            }),
            "first.poisson_ratio");
}

} // namespace
