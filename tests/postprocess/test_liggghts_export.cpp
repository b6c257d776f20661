// The LIGGGHTS export's pieces: the plastic contact read from the runs' parameters (which
// body yields, rigid plate, missing constants named) and its mapping to LIGGGHTS' inputs (E*
// reproduced by LIGGGHTS' mixing rule, coefficientYieldRatio from Thornton's limiting contact
// radius, the density of the campaign's mass). That LIGGGHTS reproduces the law is
// tests/consumers (consumers.liggghts).

#include "impact_postprocess/export/liggghts.hpp"
#include "impact_postprocess/export/simulator_export.hpp"
#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace impact::postprocess;

constexpr double pi = 3.14159265358979323846;

FemRun run_with(const std::string& sphere_model, const std::string& plate_model) {
  FemRun run;
  run.source = "run.h5";
  run.text_attributes["Sphere/Material model"] = sphere_model;
  run.text_attributes["Plate/Material model"] = plate_model;
  const auto section = [](std::string model) {
    model[0] = char(std::toupper((unsigned char)model[0]));
    return model;
  };
  run.text_attributes["Sphere/" + section(sphere_model) + "/Young's modulus"] = "2.1e11";
  run.text_attributes["Sphere/" + section(sphere_model) + "/Poisson's ratio"] = "0.3";
  if (plate_model != "rigid") {
    run.text_attributes["Plate/" + section(plate_model) + "/Young's modulus"] = "7e10";
    run.text_attributes["Plate/" + section(plate_model) + "/Poisson's ratio"] = "0.33";
  }
  return run;
}

// LIGGGHTS' mixing rule (global_properties.cpp): 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2).
double liggghts_contact_modulus(const LiggghtsContact& c) {
  return 1 / ((1 - c.sphere_poisson_ratio * c.sphere_poisson_ratio) / c.sphere_youngs_modulus +
              (1 - c.wall_poisson_ratio * c.wall_poisson_ratio) / c.wall_youngs_modulus);
}

TEST(LiggghtsExport, TheBodyWithTheLowerYieldStrengthSetsJohnsonsPressure) {
  FemRun run = run_with("elastic-plastic", "elastic-plastic");
  run.text_attributes["Sphere/Elastic-plastic/Yield strength"] = "2e9";
  run.text_attributes["Plate/Elastic-plastic/Yield strength"] = "3.5e8";
  const auto contact = scenario_plastic_contact({run});
  ASSERT_TRUE(contact);
  EXPECT_DOUBLE_EQ(contact->yield_pressure, 1.6 * 3.5e8);
  EXPECT_NE(contact->yield_basis.find("Plate/Elastic-plastic/Yield strength"), std::string::npos);
  const double e_star = 1 / ((1 - 0.09) / 2.1e11 + (1 - 0.33 * 0.33) / 7e10);
  EXPECT_NEAR(contact->contact_modulus, e_star, 1e-15 * e_star);

  const double mass = 0.1, radius = 0.01452;
  const LiggghtsContact liggghts = liggghts_contact(*contact, mass, radius);
  EXPECT_NEAR(liggghts_contact_modulus(liggghts), e_star, 1e-15 * e_star);
  // a_y = pi p_y R / (2 E*) over R.
  EXPECT_NEAR(liggghts.yield_ratio, pi * 1.6 * 3.5e8 / (2 * e_star), 1e-16);
  EXPECT_NEAR(liggghts.density * 4.0 / 3.0 * pi * std::pow(radius, 3), mass, 1e-15 * mass);
  // V_y = sqrt(pi^5 R^3 p_y^5 / (30 m E*^4)), by hand.
  const double v_y = std::sqrt(std::pow(pi, 5) * std::pow(radius, 3) * std::pow(1.6 * 3.5e8, 5) /
                               (30 * mass * std::pow(e_star, 4)));
  EXPECT_NEAR(liggghts.yield_velocity, v_y, 1e-13 * v_y);
}

TEST(LiggghtsExport, ARigidPlateGetsOneMaterialWithTheSameContactModulus) {
  FemRun run = run_with("elastic-plastic", "rigid");
  run.text_attributes["Sphere/Elastic-plastic/Yield strength"] = "1e9";
  const auto contact = scenario_plastic_contact({run});
  ASSERT_TRUE(contact);
  EXPECT_FALSE(contact->plate_youngs_modulus);
  const double e_star = 2.1e11 / (1 - 0.09);
  EXPECT_NEAR(contact->contact_modulus, e_star, 1e-15 * e_star);
  const LiggghtsContact liggghts = liggghts_contact(*contact, 0.1, 0.01);
  EXPECT_EQ(liggghts.sphere_youngs_modulus, liggghts.wall_youngs_modulus);
  EXPECT_NEAR(liggghts_contact_modulus(liggghts), e_star, 1e-15 * e_star);
}

TEST(LiggghtsExport, TheCheckedStrengthOfAnElasticBodyIsUsedAndNoStrengthMeansNoExport) {
  FemRun run = run_with("kelvin-voigt", "kelvin-voigt");
  EXPECT_FALSE(scenario_plastic_contact({run}));
  run.text_attributes["Sphere/Yield strength"] = "0"; // impact-fem's "none"
  EXPECT_FALSE(scenario_plastic_contact({run}));
  run.text_attributes["Sphere/Yield strength"] = "2.03e9";
  const auto contact = scenario_plastic_contact({run});
  ASSERT_TRUE(contact);
  EXPECT_DOUBLE_EQ(contact->yield_pressure, 1.6 * 2.03e9);
  EXPECT_FALSE(scenario_plastic_contact({}));
}

TEST(LiggghtsExport, MissingElasticConstantsAreNamed) {
  FemRun run = run_with("elastic-plastic", "elastic-plastic");
  run.text_attributes["Sphere/Elastic-plastic/Yield strength"] = "1e9";
  run.text_attributes.erase("Plate/Elastic-plastic/Young's modulus");
  try {
    scenario_plastic_contact({run});
    FAIL() << "no error";
  } catch (const PlasticContactError& error) {
    EXPECT_NE(std::string(error.what()).find("Plate"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("run.h5"), std::string::npos) << error.what();
  }
}

TEST(LiggghtsExport, AYieldPressureAboveLiggghtsRangeIsRefused) {
  FemRun run = run_with("elastic-plastic", "rigid");
  run.text_attributes["Sphere/Elastic-plastic/Yield strength"] = "1e11"; // ratio > 1
  const auto contact = scenario_plastic_contact({run});
  ASSERT_TRUE(contact);
  EXPECT_THROW(liggghts_contact(*contact, 0.1, 0.01), ExportInputError);
}

} // namespace
