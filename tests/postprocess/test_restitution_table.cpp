// The restitution table of impact-export (restitution_table.hpp) on a campaign made by
// Hunt–Crossley damping on Thornton's spring with b(V) from the sphere's retardation time, and
// a calibration that holds that law from the material (ranked first) and a fit of the same
// damping on Jackson–Green's spring (ranked second, with out-of-sample predictions): the
// first-ranked law is tabulated, or the one named; its e, t_c, F_max equal the reduced
// library's called directly (within 1e-12) on either spring; the CSV and the JSON carry every
// column with its unit; rows at the FEM's velocities carry the FEM's values, its uncertainty
// (the GCI of a verification where the run has one) and the law's error in and out of sample,
// rows between say the error is not known; a law the calibration does not have is refused.

#include "plastic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/export/restitution_table.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hunt_crossley_elastic_plastic.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/kuwabara_kono_elastic_plastic.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>
#include <impact_reduced/thornton.hpp>

#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h> // getpid

namespace {

using namespace impact::postprocess;
namespace reduced = impact::reduced;
namespace fs = std::filesystem;
using impact::testing::Truth;

// A run of Hunt–Crossley on Thornton's spring of `truth` with b(V) from the retardation time
// tau (A = tau for a sphere on a rigid flat), from the library's closed-form history, recorded
// as impact-fem records an elastic-plastic sphere.
FemRun damped_thornton_run(const Truth& truth, double retardation_time, double velocity) {
  const double damping = matched_hunt_crossley_damping(retardation_time, velocity,
                                                       {truth.mass, truth.stiffness(), 1.5});
  const auto spring =
      std::make_shared<reduced::ThorntonContact>(truth.radius, truth.contact_modulus,
                                                 truth.yield_pressure);
  const reduced::HuntCrossleyElasticPlasticImpact impact(truth.mass, spring, damping, velocity);
  const auto response = impact.response();
  std::vector<reduced::ImpactSample> history;
  // 41 samples: the table reads the run's figures, and its history only for the uncertainty
  // without a verification (the time step); each instant costs a quadrature inversion.
  for (const auto& state : impact.history(41))
    history.push_back({state.time, state.approach, state.approach_rate, state.force});
  FemRun run = impact::testing::sampled_run(truth.mass, velocity, response.restitution,
                                            response.contact_time, response.force_max,
                                            response.time_force_max, response.approach_max,
                                            response.separation_approach, response.rebound_velocity,
                                            history);
  impact::testing::record_elastic_plastic_sphere(run, truth.contact_modulus * (1 - 0.09), 0.3,
                                                 truth.yield_pressure / 1.6, truth.radius);
  run.text_attributes["Sphere/Elastic-plastic/Retardation time"] =
      impact::testing::exact_text(retardation_time);
  return run;
}

ImpactPrediction figures_of(const reduced::HuntCrossleyElasticPlasticResponse& response,
                            double damping) {
  ImpactPrediction prediction;
  static_cast<ImpactFigures&>(prediction) = response.figures();
  prediction.damping = damping;
  return prediction;
}

// The campaign (written as impact-fem writes runs, one with a verification) and a calibration
// made here: the table reads the calibration, it does not make it.
class RestitutionTableTest : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    // One folder per process: ctest runs each test of the suite as its own process, in
    // parallel, and one's TearDownTestSuite must not remove another's campaign.
    directory = new fs::path(fs::temp_directory_path() /
                             ("impact_restitution_table_test_" + std::to_string(::getpid())));
    fs::remove_all(*directory);
    const Truth truth;
    const double v_y =
        thornton_yield_velocity(truth.yield_approach(), truth.mass, truth.stiffness());
    runs = new std::vector<FemRun>;
    calibration = new Calibration;
    ReferenceModel material;
    material.key = "hunt-crossley-thornton-material";
    material.model = "hunt-crossley-thornton-from-a";
    material.label = "Hunt-Crossley on Thornton from the material";
    material.stiffness = truth.stiffness();
    material.exponent = 1.5;
    material.dissipation = {truth.yield_approach(), tau};
    CampaignModelFit fit;
    fit.key = fit.fit.model = "hunt-crossley-jackson-green";
    fit.fit.converged = true;
    fit.fit.stiffness = {truth.stiffness(), nan, nan, nan};
    fit.fit.parameter = {jackson_green_yield, nan, nan, nan};
    fit.fit.extra = {{"b", "s/m", {fitted_b, nan, nan, nan}}};
    const auto spring = jackson_green_spring(truth);
    int index = 0;
    for (double ratio : {0.5, 4.0, 20.0}) {
      const double velocity = ratio * v_y;
      const FemRun made = damped_thornton_run(truth, tau, velocity);
      const fs::path run_directory = *directory / ("run" + std::to_string(index++));
      write_fem_run(made, run_directory);
      if (index == 2) impact::testing::write_verification(run_directory, made, 0.004);
      runs->push_back(read_fem_run(run_directory));
      const FemRun& run = runs->back();
      calibration->runs.push_back({run.source, run.impact_velocity, run.mass,
                                   measured_quantities(run), nan, nan, std::nullopt, std::nullopt,
                                   std::nullopt});
      RunResidual residual{run.source, run.impact_velocity, {nan, nan, 0}, {}, std::nullopt};
      static_cast<ImpactFigures&>(residual.prediction) = measured_quantities(run);
      material.runs.push_back(residual);
      // The Jackson-Green fit's predictions: in sample its own, out of sample 1 % off.
      const auto own =
          reduced::HuntCrossleyElasticPlasticImpact(truth.mass, spring, fitted_b, velocity)
              .response();
      residual.prediction = figures_of(own, fitted_b);
      ImpactPrediction held_out = residual.prediction;
      held_out.restitution *= 1.01;
      residual.out_of_sample = held_out;
      fit.runs.push_back(residual);
    }
    calibration->campaign.fitted = true;
    calibration->campaign.reference_models.push_back(material);
    // Kuwabara–Kono damping on the same spring with the same A (not ranked: a table of it is
    // asked for by name).
    ReferenceModel kuwabara_kono = material;
    kuwabara_kono.key = "kuwabara-kono-thornton-material";
    kuwabara_kono.model = "kuwabara-kono-thornton";
    kuwabara_kono.label = "Kuwabara-Kono on Thornton from the material";
    const double c = truth.stiffness(), x_y = truth.yield_approach();
    const reduced::ThorntonContact thornton(1.0, 0.75 * c,
                                            3 * c * std::sqrt(x_y) / (2 * 3.14159265358979323846));
    for (auto& residual : kuwabara_kono.runs)
      static_cast<ImpactFigures&>(residual.prediction) =
          reduced::kuwabara_kono_elastic_plastic_impact(truth.mass, residual.velocity, thornton,
                                                        tau)
              .figures();
    calibration->campaign.reference_models.push_back(kuwabara_kono);
    calibration->campaign.comparison_laws.push_back(fit);
    calibration->campaign.ranking = {{"kuwabara-kono", 2, 0.005, true, 0.01, 0.005, 0.01, true, {}},
                                     {material.key, 0, 0.01, true, 0.02, 0.01, 0.01, true, {}},
                                     {fit.key, 2, 0.02, true, 0.03, 0.02, 0.01, true, {}}};
  }
  static void TearDownTestSuite() {
    fs::remove_all(*directory);
    delete directory;
    delete runs;
    delete calibration;
  }

  // Jackson-Green's spring of the fixture's fit, as the reduced library builds it.
  static std::shared_ptr<const reduced::ElasticPlasticContact> jackson_green_spring(
      const Truth& truth) {
    return std::make_shared<reduced::JacksonGreenContact>(
        reduced::SphereFlatContact{truth.radius, 0.75 * truth.stiffness() / std::sqrt(truth.radius),
                                   jackson_green_yield, 0.3});
  }

  static constexpr double tau = 1.2e-6;                // s
  static constexpr double jackson_green_yield = 1.1e9; // Pa
  static constexpr double fitted_b = 0.07;             // s/m
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
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
  EXPECT_EQ(table.law.key, "hunt-crossley-thornton-material");
  EXPECT_EQ(table.law.model, "hunt-crossley-thornton-from-a");
  EXPECT_EQ(table.law.spring, "thornton");
  EXPECT_EQ(table.law.damping, TableDamping::hunt_crossley_of_velocity);
  EXPECT_GE(table.law.rank, 1u);
  // The material's c, x_y and A: those of the truth.
  const double c = table.law.stiffness, x_y = table.law.yield_parameter;
  EXPECT_NEAR(c / truth.stiffness(), 1, 1e-12);
  EXPECT_NEAR(x_y / truth.yield_approach(), 1, 1e-12);
  EXPECT_NEAR(table.law.damping_parameter / tau, 1, 1e-12);

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
    // b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5).
    const double b = 1.5 * reduced::brilliantov_gamma1() * table.law.damping_parameter *
                     std::pow(c / truth.mass, 0.4) * std::pow(row.velocity, -0.8);
    EXPECT_NEAR(row.damping / b, 1, 1e-15);
    const auto direct =
        reduced::HuntCrossleyElasticPlasticImpact(truth.mass, spring, b, row.velocity).response();
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
    // The campaign is the law's own: the law from the material is its truth.
    for (double error : row.fem->error) EXPECT_LT(std::abs(error), 1e-9);
    // A reference model fits nothing: out of sample, its error is the same.
    for (std::size_t q = 0; q < 3; ++q)
      EXPECT_NEAR(row.fem->out_of_sample_error[q], row.fem->error[q], 1e-15);
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
  EXPECT_NE(comments.find("hunt-crossley-thornton-material"), std::string::npos);
  EXPECT_NE(comments.find("x_y = "), std::string::npos);
  EXPECT_NE(comments.find("A = "), std::string::npos);
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
  EXPECT_EQ(law.at("damping").at("A").at("unit"), "s");
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

// Named, the fitted law on Jackson-Green's spring: the reduced library's numbers, and the
// error of the fit without each velocity beside that of the fit to all.
// Kuwabara–Kono damping: the rows are the library's integration of F = F_s + A k_t x' (no b
// column), and the JSON says which damping the simulator must apply.
TEST_F(RestitutionTableTest, TabulatesAKuwabaraKonoLawAsTheReducedLibraryIntegratesIt) {
  const RestitutionTable table =
      restitution_table(*calibration, *runs, std::string("kuwabara-kono-thornton-material"), 5);
  EXPECT_EQ(table.law.model, "kuwabara-kono-thornton");
  EXPECT_EQ(table.law.damping, TableDamping::kuwabara_kono);
  EXPECT_EQ(table.law.damping_parameter, tau);
  EXPECT_EQ(table.law.rank, 0u);
  const double c = table.law.stiffness, x_y = table.law.yield_parameter;
  const double pi = 3.14159265358979323846;
  const reduced::ThorntonContact spring(1.0, 0.75 * c, 3 * c * std::sqrt(x_y) / (2 * pi));
  ASSERT_EQ(table.rows.size(), 6u); // 5 log-spaced, both ends at runs, and the run between
  for (const auto& row : table.rows) {
    EXPECT_TRUE(std::isnan(row.damping));
    const auto direct =
        reduced::kuwabara_kono_elastic_plastic_impact(truth.mass, row.velocity, spring, tau);
    EXPECT_EQ(row.law.restitution, direct.restitution) << row.velocity;
    EXPECT_EQ(row.law.contact_time, direct.contact_time) << row.velocity;
    EXPECT_EQ(row.law.force_max, direct.force_max) << row.velocity;
    EXPECT_EQ(row.law.approach_max, direct.approach_max) << row.velocity;
    EXPECT_EQ(row.law.separation_approach, direct.approach_at_separation) << row.velocity;
    EXPECT_GT(row.law.separation_approach, 0); // it yields at every velocity of the fixture
    if (!row.fem) continue;
    for (std::size_t q = 0; q < 3; ++q) {
      EXPECT_TRUE(std::isfinite(row.fem->error[q]));
      EXPECT_NEAR(row.fem->out_of_sample_error[q], row.fem->error[q], 1e-15); // fits nothing
    }
  }
  const nlohmann::json json = restitution_table_json(table);
  const nlohmann::json& damping = json.at("law").at("damping");
  EXPECT_EQ(damping.at("kind"), "kuwabara-kono");
  EXPECT_EQ(damping.at("A").at("value").get<double>(), tau);
  EXPECT_FALSE(damping.contains("b"));
  EXPECT_NE(json.at("law").at("force_law").get<std::string>().find("A k_t(x) x'"),
            std::string::npos);
  for (const auto& row : json.at("rows")) EXPECT_TRUE(row.at("damping").is_null());
  const std::string csv = restitution_table_csv(table);
  EXPECT_NE(csv.find("Kuwabara-Kono: F = F_s + A k_t x'"), std::string::npos);
}

TEST_F(RestitutionTableTest, TabulatesAFittedLawOnJacksonGreensSpring) {
  const RestitutionTable table =
      restitution_table(*calibration, *runs, std::string("hunt-crossley-jackson-green"), 4);
  EXPECT_EQ(table.law.spring, "jackson-green");
  EXPECT_EQ(table.law.rank, 3u);
  EXPECT_EQ(table.law.damping, TableDamping::hunt_crossley);
  EXPECT_EQ(table.law.poisson_ratio, 0.3);
  EXPECT_NEAR(table.law.radius / truth.radius, 1, 1e-15);
  const auto spring = jackson_green_spring(truth);
  ASSERT_EQ(table.rows.size(), 5u); // 4 log-spaced with both ends at runs, and the middle run
  for (const auto& row : table.rows) {
    EXPECT_EQ(row.damping, fitted_b);
    const auto direct =
        reduced::HuntCrossleyElasticPlasticImpact(truth.mass, spring, fitted_b, row.velocity)
            .response();
    EXPECT_NEAR(row.law.restitution / direct.restitution, 1, 1e-12) << row.velocity;
    EXPECT_NEAR(row.law.contact_time / direct.contact_time, 1, 1e-12) << row.velocity;
    EXPECT_NEAR(row.law.force_max / direct.force_max, 1, 1e-12) << row.velocity;
    if (!row.fem) continue;
    const double e = row.fem->figures.restitution;
    EXPECT_NEAR(row.fem->error[0], row.law.restitution / e - 1, 1e-15);
    EXPECT_NEAR(row.fem->out_of_sample_error[0], 1.01 * row.law.restitution / e - 1, 1e-12);
    EXPECT_NEAR(row.fem->out_of_sample_error[2], row.fem->error[2], 1e-12);
  }
}

TEST_F(RestitutionTableTest, RefusesALawTheCalibrationDoesNotHave) {
  for (const std::string name :
       {"hunt-crossley-thornton", "hunt-crossley-jackson-green-material", "kuwabara-kono"})
    EXPECT_THROW(restitution_table(*calibration, *runs, name, 5), RestitutionTableError) << name;
  try {
    restitution_table(*calibration, *runs, std::nullopt, 1);
    ADD_FAILURE() << "one point accepted";
  } catch (const reduced::InvalidInput& error) {
    EXPECT_EQ(error.parameter(), "points");
  }
  Calibration without = *calibration;
  without.campaign.reference_models.clear();
  without.campaign.comparison_laws.clear();
  EXPECT_TRUE(restitution_table_laws(without).empty());
  EXPECT_THROW(restitution_table(without, *runs, std::nullopt, 5), RestitutionTableError);
}

} // namespace
