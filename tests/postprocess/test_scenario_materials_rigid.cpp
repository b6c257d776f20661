// The scenario's materials of a run on impact-fem's rigid flat ("Plate/Material model =
// rigid"): Hertz's c from the sphere's E* alone, c = 4/3 E/(1 - nu^2) sqrt(R) (Johnson,
// Contact Mechanics, 1985, eq. 4.22 with the plate's compliance 0), computed here
// independently; the Kuwabara–Kono A of a Kelvin–Voigt sphere with tau_d = tau_v = tau is
// tau (the compliance-weighted mean over the one deformable body); an elastic sphere on the
// rigid flat is the Hertz model.

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using impact::postprocess::FemRun;

FemRun rigid_flat_run(const std::string& sphere_model) {
  FemRun run;
  run.source = "synthetic rigid-flat run";
  run.text_attributes = {{"Scenario/Sphere radius", "0.01452"},
                         {"Sphere/Material model", sphere_model},
                         {"Plate/Material model", "rigid"}};
  const std::string section =
      sphere_model == "elastic" ? "Sphere/Elastic/" : "Sphere/Kelvin-voigt/";
  run.text_attributes[section + "Young's modulus"] = "2e11";
  run.text_attributes[section + "Poisson's ratio"] = "0.25";
  run.text_attributes[section + "Retardation time"] = "1e-6";
  run.text_attributes[section + "Volumetric retardation time"] = "-1";
  return run;
}

TEST(ScenarioMaterialsRigidFlat, HertzStiffnessOfTheSphereAlone) {
  const auto materials = impact::postprocess::scenario_materials({rigid_flat_run("elastic")});
  const double expected = 4.0 / 3.0 * 2e11 / (1 - 0.25 * 0.25) * std::sqrt(0.01452);
  EXPECT_TRUE(materials.hertz_from_runs);
  EXPECT_NEAR(materials.hertz_stiffness / expected - 1, 0, 1e-14);
  EXPECT_NE(materials.hertz_basis.find("rigid plate"), std::string::npos);
  EXPECT_NE(materials.dissipative_basis.find("plate rigid"), std::string::npos);
}

TEST(ScenarioMaterialsRigidFlat, KelvinVoigtSphereKeepsItsOwnA) {
  const auto materials = impact::postprocess::scenario_materials({rigid_flat_run("kelvin-voigt")});
  ASSERT_TRUE(materials.dissipative_constant.has_value());
  EXPECT_NEAR(*materials.dissipative_constant / 1e-6 - 1, 0, 1e-12);
  EXPECT_NE(materials.dissipative_basis.find("rigid plate"), std::string::npos);
}

} // namespace
