// The contract of impact-fem's result files (impact_fem/result_files.h) as the reader uses
// it: the units of the swept parameters and of the summary keys come from it (no guessing
// from a parameter's name), and the material constants of a body are found under the
// subsection the contract names, the names written here as literals the way impact-fem's
// parameter files spell them.

#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace {

namespace fem_format = impact::postprocess::fem_format;
namespace fs = std::filesystem;

TEST(ResultFilesContract, SweptParametersCarryTheirUnits) {
  EXPECT_EQ(fem_format::parameter_unit("Scenario/Plate thickness"), "m");
  EXPECT_EQ(fem_format::parameter_unit("Scenario/Sphere radius"), "m");
  EXPECT_EQ(fem_format::parameter_unit("Scenario/Impact velocity"), "m/s");
  EXPECT_EQ(std::string(impact::postprocess::velocity_axis), "Scenario/Impact velocity");
  // A count and a text: no unit (a guess from the name gave the first one "m").
  EXPECT_EQ(fem_format::parameter_unit("Mesh/Elements across the plate thickness"), "");
  EXPECT_EQ(fem_format::parameter_unit("Scenario/Plate bottom"), "");
}

TEST(ResultFilesContract, EverySummaryNumberHasAUnit) {
  const fs::path directory = impact::testing::scratch_directory("result_files_contract");
  const impact::postprocess::FemRun run =
      impact::testing::synthetic_run({0.1, 1.7135e10, 1.5, 0.1}, 1.0);
  const fs::path file = impact::postprocess::write_fem_run(run, directory);
  std::ifstream in(file.parent_path() / fem_format::summary_file);
  const nlohmann::json summary = nlohmann::json::parse(in);
  fs::remove_all(directory);
  ASSERT_FALSE(summary.empty());
  for (const auto& [key, value] : summary.items()) {
    if (value.is_boolean()) {
      EXPECT_EQ(fem_format::summary_unit(key), nullptr) << key;
      continue;
    }
    ASSERT_NE(fem_format::summary_unit(key), nullptr) << key;
  }
  EXPECT_STREQ(fem_format::summary_unit("restitution"), "1");
  EXPECT_STREQ(fem_format::summary_unit("force_max"), "N");
  EXPECT_STREQ(fem_format::summary_unit("von_mises_max_plate"), "Pa");
  EXPECT_EQ(fem_format::summary_unit("no such key"), nullptr);
}

TEST(ResultFilesContract, MaterialConstantsUnderTheModelsSubsection) {
  EXPECT_EQ(fem_format::material_subsection("kelvin-voigt"), "Kelvin-voigt");
  EXPECT_EQ(fem_format::material_parameter("Plate", "elastic-plastic", fem_format::yield_strength),
            "Plate/Elastic-plastic/Yield strength");
  impact::postprocess::FemRun run;
  run.text_attributes = {{"Plate/Material model", "kelvin-voigt"},
                         {"Plate/Kelvin-voigt/Density", "7800"},
                         {"Plate/Elastic/Density", "1"}};
  const auto density =
      impact::postprocess::material_constant(run, fem_format::plate_body, fem_format::density);
  ASSERT_TRUE(density);
  EXPECT_EQ(*density, 7800);
  EXPECT_FALSE(
      impact::postprocess::material_constant(run, fem_format::sphere_body, fem_format::density));
}

} // namespace
