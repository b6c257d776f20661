// The restitution table of impact-export (restitution_table.hpp) on a campaign made by
// Hunt–Crossley damping on Thornton's spring: the first-ranked damped law is tabulated; its
// e, t_c, F_max equal the reduced library's called directly (within 1e-12); the CSV and the
// JSON carry every column with its unit; rows at the FEM's velocities carry the FEM's values,
// its uncertainty (the GCI of a verification where the run has one) and the law's error,
// rows between say the error is not known; a law the calibration does not have is refused.

#include "plastic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/export/restitution_table.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <impact_reduced/hunt_crossley_elastic_plastic.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/thornton.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace impact::postprocess;
namespace reduced = impact::reduced;
namespace fs = std::filesystem;
using impact::testing::Truth;

// A run of Hunt–Crossley (constant b) on Thornton's spring of `truth`, from the library's
// closed-form history, recorded as impact-fem records an elastic-plastic sphere.
FemRun damped_thornton_run(const Truth& truth, double damping, double velocity) {
  const auto spring =
      std::make_shared<reduced::ThorntonContact>(truth.radius, truth.contact_modulus,
                                                 truth.yield_pressure);
  const reduced::HuntCrossleyElasticPlasticImpact impact(truth.mass, spring, damping, velocity);
  const auto response = impact.response();
  std::vector<reduced::ImpactSample> history;
  for (const auto& state : impact.history(301))
    history.push_back({state.time, state.approach, state.approach_rate, state.force});
  FemRun run = impact::testing::sampled_run(truth.mass, velocity, response.restitution,
                                            response.contact_time, response.force_max,
                                            response.time_force_max, response.approach_max,
                                            response.separation_approach, response.rebound_velocity,
                                            history);
  impact::testing::record_elastic_plastic_sphere(run, truth.contact_modulus * (1 - 0.09), 0.3,
                                                 truth.yield_pressure / 1.6, truth.radius);
  return run;
}

// The verification.json of impact-fem with relative GCIs of e, t_c and F_max.
void write_verification(const fs::path& directory, const FemRun& run, double gci) {
  const auto quantity = [&](double fine, double relative) {
    return nlohmann::json{{"unit", "1"},
                          {"fine", fine},
                          {"medium", fine},
                          {"coarse", fine},
                          {"observed_order", 2.0},
                          {"extrapolated", fine},
                          {"gci_fine", relative},
                          {"gci_fine_absolute", relative * fine},
                          {"convergence", "monotone"}};
  };
  std::ofstream(directory / "verification.json")
      << nlohmann::json{{"format", "impact-verification"},
                        {"format_version", 1},
                        {"refinement_ratio", 1.5},
                        {"levels", nlohmann::json::array()},
                        {"quantities",
                         {{"contact_time", quantity(run.contact_time, gci)},
                          {"force_max", quantity(run.force_max, 2 * gci)},
                          {"time_force_max", quantity(run.time_force_max, gci)},
                          {"approach_max", quantity(run.approach_max, gci)},
                          {"restitution", quantity(run.restitution, 0.5 * gci)}}}}
             .dump(2);
}

// The campaign (written as impact-fem writes runs, one with a verification) and its
// calibration, made once for the tests: the fit of the damped law is the costly part.
class RestitutionTableTest : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    directory = new fs::path(fs::temp_directory_path() / "impact_restitution_table_test");
    fs::remove_all(*directory);
    const Truth truth;
    const double v_y =
        thornton_yield_velocity(truth.yield_approach(), truth.mass, truth.stiffness());
    runs = new std::vector<FemRun>;
    int index = 0;
    for (double ratio : {0.5, 4.0, 20.0}) {
      const FemRun made = damped_thornton_run(truth, b, ratio * v_y);
      const fs::path run_directory = *directory / ("run" + std::to_string(index++));
      write_fem_run(made, run_directory);
      if (index == 2) write_verification(run_directory, made, 0.004);
      runs->push_back(read_fem_run(run_directory));
    }
    CalibrationOptions options;
    options.laws = {"hunt-crossley-thornton"};
    calibration = new Calibration(calibrate(*runs, options));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*directory);
    delete directory;
    delete runs;
    delete calibration;
  }
  void SetUp() override {
    ASSERT_TRUE(calibration->campaign.fitted) << calibration->campaign.reason;
  }

  static constexpr double b = 0.05;
  static fs::path* directory;
  static std::vector<FemRun>* runs;
  static Calibration* calibration;
  const Truth truth;
};
fs::path* RestitutionTableTest::directory = nullptr;
std::vector<FemRun>* RestitutionTableTest::runs = nullptr;
Calibration* RestitutionTableTest::calibration = nullptr;

TEST_F(RestitutionTableTest, TabulatesTheFirstRankedDampedLawAsTheReducedLibraryGivesIt) {
  const RestitutionTable table = restitution_table(*calibration, *runs, std::nullopt, 9);
  EXPECT_EQ(table.law.key, "hunt-crossley-thornton");
  EXPECT_EQ(table.law.spring, "thornton");
  EXPECT_FALSE(table.law.damping_from_dissipative_constant);
  EXPECT_GE(table.law.rank, 1u);
  const CampaignModelFit* fit = calibration->campaign.find("hunt-crossley-thornton");
  ASSERT_NE(fit, nullptr);
  const double c = fit->fit.stiffness.value, x_y = fit->fit.parameter.value,
               fitted_b = fit->fit.extra.at(0).estimate.value;
  EXPECT_EQ(table.law.stiffness, c);
  EXPECT_EQ(table.law.yield_parameter, x_y);
  EXPECT_EQ(table.law.damping_parameter, fitted_b);

  // 9 log-spaced velocities with both ends at runs, and the run between: 10 rows.
  ASSERT_EQ(table.rows.size(), 10u);
  // The reduced library called directly: Thornton's spring from c and x_y (R = 1 m: the law
  // depends on R only through them), p_y = 3 c sqrt(x_y) / (2 pi R).
  const double pi = 3.14159265358979323846;
  const auto spring =
      std::make_shared<reduced::ThorntonContact>(1.0, 0.75 * c, 3 * c * std::sqrt(x_y) / (2 * pi));
  std::size_t at_fem = 0;
  double previous = 0;
  for (const auto& row : table.rows) {
    EXPECT_GT(row.velocity, previous);
    previous = row.velocity;
    const auto direct =
        reduced::HuntCrossleyElasticPlasticImpact(truth.mass, spring, fitted_b, row.velocity)
            .response();
    EXPECT_EQ(row.damping, fitted_b);
    EXPECT_NEAR(row.law.restitution / direct.restitution, 1, 1e-12) << row.velocity;
    EXPECT_NEAR(row.law.contact_time / direct.contact_time, 1, 1e-12) << row.velocity;
    EXPECT_NEAR(row.law.force_max / direct.force_max, 1, 1e-12) << row.velocity;
    EXPECT_NEAR(row.law.approach_max / direct.approach_max, 1, 1e-12) << row.velocity;
    if (!row.fem) continue;
    ++at_fem;
    // The FEM's row: its values, its uncertainty, the law's error against it.
    const FemRun* run = nullptr;
    for (const auto& candidate : *runs)
      if (std::abs(candidate.impact_velocity / row.velocity - 1) < 1e-12) run = &candidate;
    ASSERT_NE(run, nullptr);
    EXPECT_EQ(row.fem->figures.restitution, run->restitution);
    EXPECT_NEAR(row.fem->error[0], row.law.restitution / run->restitution - 1, 1e-15);
    EXPECT_NEAR(row.fem->error[1], row.law.contact_time / run->contact_time - 1, 1e-15);
    EXPECT_NEAR(row.fem->error[2], row.law.force_max / run->force_max - 1, 1e-15);
    // The campaign is the law's own: the fitted law is within the fit's accuracy of it.
    for (double error : row.fem->error) EXPECT_LT(std::abs(error), 1e-4);
    for (double error : row.fem->out_of_sample_error) EXPECT_LT(std::abs(error), 1e-4);
    if (run->source.find("run1") != std::string::npos) {
      // The GCI of the verification, as the verdict takes it (e: absolute GCI / e).
      EXPECT_NEAR(row.fem->uncertainty[0], 0.002, 1e-15);
      EXPECT_NEAR(row.fem->uncertainty[1], 0.004, 1e-15);
      EXPECT_NEAR(row.fem->uncertainty[2], 0.008, 1e-15);
      EXPECT_NE(row.fem->uncertainty_source[0].find("GCI"), std::string::npos);
    } else {
      // No verification: e's uncertainty is not known, t_c's is what the history shows.
      EXPECT_TRUE(std::isnan(row.fem->uncertainty[0]));
      EXPECT_TRUE(std::isfinite(row.fem->uncertainty[1]));
    }
  }
  EXPECT_EQ(at_fem, runs->size());
}

TEST_F(RestitutionTableTest, CsvAndJsonCarryEveryColumnWithItsUnit) {
  const RestitutionTable table = restitution_table(*calibration, *runs, std::nullopt, 5);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"impact_velocity", "m/s"},
      {"row", "-"},
      {"damping", "s/m"},
      {"restitution", "1"},
      {"contact_time", "s"},
      {"force_max", "N"},
      {"approach_max", "m"},
      {"permanent_approach", "m"},
      {"fem_restitution", "1"},
      {"fem_restitution_uncertainty", "1"},
      {"fem_contact_time", "s"},
      {"fem_contact_time_uncertainty", "1"},
      {"fem_force_max", "N"},
      {"fem_force_max_uncertainty", "1"},
      {"error_restitution", "1"},
      {"error_contact_time", "1"},
      {"error_force_max", "1"},
      {"out_of_sample_error_restitution", "1"},
      {"out_of_sample_error_contact_time", "1"},
      {"out_of_sample_error_force_max", "1"}};

  // CSV: comment lines with each column's unit, one header line, one line per row.
  const std::string csv = restitution_table_csv(table);
  std::istringstream lines(csv);
  std::string line, header;
  std::vector<std::string> data;
  std::string comments;
  while (std::getline(lines, line)) {
    if (line.rfind("#", 0) == 0)
      comments += line + "\n";
    else if (header.empty())
      header = line;
    else
      data.push_back(line);
  }
  std::string expected_header;
  for (const auto& [name, unit] : expected) {
    expected_header += (expected_header.empty() ? "" : ",") + name;
    EXPECT_NE(comments.find("#   " + name + " [" + unit + "]"), std::string::npos) << name;
  }
  EXPECT_EQ(header, expected_header);
  EXPECT_NE(comments.find("hunt-crossley-thornton"), std::string::npos);
  EXPECT_NE(comments.find("x_y = "), std::string::npos);
  ASSERT_EQ(data.size(), table.rows.size());
  for (std::size_t i = 0; i < data.size(); ++i) {
    std::vector<std::string> fields;
    std::stringstream row(data[i]);
    std::string field;
    while (std::getline(row, field, ',')) fields.push_back(field);
    if (data[i].back() == ',') fields.push_back("");
    ASSERT_EQ(fields.size(), expected.size()) << data[i];
    EXPECT_EQ(std::stod(fields[0]), table.rows[i].velocity);
    EXPECT_EQ(std::stod(fields[3]), table.rows[i].law.restitution); // the doubles, read back
    EXPECT_EQ(fields[1], table.rows[i].fem ? "fem" : "interpolated");
    // The error is given at the FEM's velocities and left empty (not known) between.
    EXPECT_EQ(fields[14].empty(), !table.rows[i].fem) << data[i];
    if (table.rows[i].fem) {
      EXPECT_EQ(std::stod(fields[14]), table.rows[i].fem->error[0]);
    }
  }

  // JSON: the same columns and units; null where not known; the law's parameters.
  const nlohmann::json json = restitution_table_json(table);
  EXPECT_EQ(json.at("format"), "impact-restitution-table");
  ASSERT_EQ(json.at("columns").size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(json.at("columns")[i], expected[i].first);
    EXPECT_EQ(json.at("units").at(expected[i].first), expected[i].second);
  }
  const auto& law = json.at("law");
  EXPECT_EQ(law.at("spring").at("name"), "thornton");
  EXPECT_EQ(law.at("spring").at("c").at("value").get<double>(), table.law.stiffness);
  EXPECT_EQ(law.at("damping").at("b").at("unit"), "s/m");
  EXPECT_EQ(law.at("mass").at("value").get<double>(), truth.mass);
  ASSERT_EQ(json.at("rows").size(), table.rows.size());
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& row = json.at("rows")[i];
    EXPECT_EQ(row.at("restitution").get<double>(), table.rows[i].law.restitution);
    EXPECT_EQ(row.at("contact_time").get<double>(), table.rows[i].law.contact_time);
    EXPECT_EQ(row.at("force_max").get<double>(), table.rows[i].law.force_max);
    EXPECT_EQ(row.at("error_known").get<bool>(), table.rows[i].fem.has_value());
    if (table.rows[i].fem) {
      EXPECT_EQ(row.at("error_force_max").get<double>(), table.rows[i].fem->error[2]);
      EXPECT_TRUE(row.contains("fem_source"));
    } else {
      EXPECT_TRUE(row.at("error_restitution").is_null());
      EXPECT_TRUE(row.at("fem_restitution").is_null());
    }
  }
}

TEST_F(RestitutionTableTest, RefusesALawTheCalibrationDoesNotHave) {
  EXPECT_THROW(restitution_table(*calibration, *runs, std::string("hunt-crossley-jackson-green"), 5),
               RestitutionTableError);
  EXPECT_THROW(restitution_table(*calibration, *runs, std::string("kuwabara-kono"), 5),
               RestitutionTableError);
  try {
    restitution_table(*calibration, *runs, std::nullopt, 1);
    ADD_FAILURE() << "one point accepted";
  } catch (const reduced::InvalidInput& error) {
    EXPECT_EQ(error.parameter(), "points");
  }
  // Named explicitly, the law in the calibration is tabulated.
  EXPECT_EQ(restitution_table(*calibration, *runs, std::string("hunt-crossley-thornton"), 3).law.key,
            "hunt-crossley-thornton");
}

} // namespace
