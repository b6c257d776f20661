// impact-export on a campaign made by the reduced library (Hunt–Crossley truth, the sphere
// radius recorded as impact-fem does): the exported numbers follow the documented mappings
// from the calibration JSON, the MuJoCo spring-damper reproduces the FEM restitution and
// contact time at the reference velocity, and bad input stops the tool with a message naming
// the problem, exit code 2 and no output. (That the tools themselves reproduce the laws is
// tests/consumers.)

#include "report_cli_testing.hpp"
#include "synthetic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/export/simulator_export.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace {

using namespace impact::postprocess;
using json = nlohmann::json;
namespace fs = std::filesystem;

const double radius = 0.01452;

using impact::testing::CliRun;
using impact::testing::contains;
using impact::testing::read_text;

CliRun run_export(const std::vector<std::string>& arguments, const fs::path& scratch) {
  return impact::testing::run_tool(IMPACT_EXPORT_CLI, arguments, scratch);
}

// A campaign at 0.5, 1, 2 m/s, calibrated with `laws`; the radius is recorded unless not.
class ExportCli : public ::testing::Test {
protected:
  void make(const std::vector<std::string>& laws, bool record_radius = true) {
    scratch = impact::testing::scratch_directory(
        std::string("export_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    campaign = scratch / "campaign";
    std::vector<FemRun> runs;
    for (double velocity : {0.5, 1.0, 2.0}) {
      FemRun run = impact::testing::synthetic_run({0.1, 1.75e10, 1.5, 0.05}, velocity);
      if (record_radius) run.text_attributes["Scenario/Sphere radius"] = "0.01452";
      write_fem_run(run, campaign / ("v" + std::to_string(velocity)));
    }
    const Campaign read = read_campaign(campaign);
    ASSERT_TRUE(read.problems.empty());
    CalibrationOptions options;
    options.laws = laws;
    calibration = to_json(calibrate(read.runs, options));
    std::ofstream(scratch / "calibration.json") << calibration.dump(2);
  }
  std::vector<std::string> arguments(const fs::path& output) const {
    return {"--campaign",    campaign.string(),
            "--calibration", (scratch / "calibration.json").string(),
            "--output",      output.string(),
            "--quiet"};
  }
  void TearDown() override { fs::remove_all(scratch); }

  fs::path scratch, campaign;
  json calibration;
};

TEST_F(ExportCli, WritesTheMappingsOfTheCalibration) {
  make({"kuwabara-kono", "tsuji"});
  const fs::path output = scratch / "export";
  const CliRun run = run_export(arguments(output), scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* file : {"export.json", "simbody/impact_contact.hpp", "mujoco/impact_contact.xml",
                           "lammps/kuwabara_kono.in", "lammps/tsuji.in"})
    EXPECT_TRUE(fs::is_regular_file(output / file)) << file;
  EXPECT_FALSE(fs::exists(scratch / "export.partial"));
  std::ifstream in(output / "export.json");
  const json manifest = json::parse(in);
  EXPECT_EQ(manifest.at("format"), "impact-export");
  EXPECT_DOUBLE_EQ(manifest.at("sphere").at("radius").get<double>(), radius);
  // The median of three runs is the middle one.
  EXPECT_DOUBLE_EQ(manifest.at("reference_velocity").get<double>(), 1.0);

  const json& hc = calibration.at("campaign").at("hunt_crossley_hertz_exponent").at("parameters");
  const double c = hc.at("c").at("value"), b = hc.at("b").at("value");
  const json& law = [&]() -> const json& {
    for (const auto& l : calibration.at("campaign").at("comparison_laws"))
      if (l.at("model") == "kuwabara-kono") return l;
    throw std::runtime_error("no kuwabara-kono fit");
  }();
  const double c_kk = law.at("parameters").at("c").at("value");
  const double a_kk = law.at("parameters").at("A").at("value");
  for (const auto& entry : manifest.at("exports")) {
    const json& p = entry.at("parameters");
    if (entry.at("tool") == "simbody") {
      EXPECT_NEAR(p.at("stiffness").at("value").get<double>() / (3 * c / std::sqrt(2 * radius)), 1,
                  1e-14);
      EXPECT_NEAR(p.at("dissipation").at("value").get<double>() / (2 * b / 3), 1, 1e-14);
      const std::string header = read_text(output / "simbody/impact_contact.hpp");
      EXPECT_TRUE(contains(header, "setBodyParameters(sphere, stiffness, dissipation"));
      EXPECT_TRUE(contains(header, "n = 3/2"));
    } else if (entry.at("tool") == "mujoco") {
      const double k = -p.at("solref")[0].get<double>(), damping = -p.at("solref")[1].get<double>();
      const json& fem = calibration.at("runs")[1].at("measured");
      const ImpactFigures linear = linear_contact_impact(k, damping, 0.1, 1.0);
      EXPECT_NEAR(linear.restitution / fem.at("restitution").get<double>(), 1, 1e-12);
      EXPECT_NEAR(linear.contact_time / fem.at("contact_time").get<double>(), 1, 1e-12);
      EXPECT_EQ(p.at("solimp")[0], p.at("solimp")[1]); // flat impedance: a linear contact
      EXPECT_LE(p.at("timestep").at("value").get<double>(), linear.contact_time / 1000);
    } else if (entry.at("model") == "kuwabara-kono") {
      EXPECT_NEAR(p.at("k_n").at("value").get<double>() / (c_kk / std::sqrt(radius)), 1, 1e-14);
      EXPECT_NEAR(p.at("eta_n0").at("value").get<double>() /
                      (1.5 * a_kk * c_kk / (0.1 * std::sqrt(radius))),
                  1, 1e-14);
    }
  }
}

// The clamped spring-damper in closed form against the reduced library's integration of the
// same law, and the inverse of LAMMPS's Tsuji polynomial.
TEST(SimulatorExport, ClosedFormsAgreeWithTheIntegrationAndInvert) {
  for (double zeta : {0.01, 0.1, 0.3, 0.6, 0.9}) {
    const double omega = 6e4, k = omega * omega, damping = 2 * zeta * omega, mass = 0.1, v = 2;
    const ImpactFigures closed = linear_contact_impact(k, damping, mass, v);
    const auto integrated = impact::reduced::integrate_impact(
        mass, v,
        [=](double x, double rate) { return std::max(0.0, mass * (k * x + damping * rate)); },
        1e-13);
    EXPECT_NEAR(closed.restitution / integrated.restitution, 1, 1e-9) << zeta;
    EXPECT_NEAR(closed.force_max / integrated.force_max, 1, 1e-9) << zeta;
    const MujocoContact contact = mujoco_contact(closed.restitution, closed.contact_time, v);
    EXPECT_NEAR(contact.stiffness / k, 1, 1e-9) << zeta;
    EXPECT_NEAR(contact.damping / damping, 1, 1e-9) << zeta;
  }
  for (double e : {0.05, 0.3, 0.7, 0.93, 0.999})
    EXPECT_NEAR(lammps_tsuji_restitution_input(lammps_tsuji_alpha(e)), e, 1e-12);
  EXPECT_THROW(lammps_tsuji_restitution_input(2.0), ExportInputError);
  EXPECT_THROW(mujoco_contact(0.1, 1e-4, 1), ExportInputError);
}

TEST_F(ExportCli, CalibrationWithoutALammpsLawIsAnErrorAndWritesNothing) {
  make({});
  const CliRun run = run_export(arguments(scratch / "export"), scratch);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "kuwabara-kono or tsuji")) << run.err;
  EXPECT_FALSE(fs::exists(scratch / "export"));
  EXPECT_FALSE(fs::exists(scratch / "export.partial"));
}

TEST_F(ExportCli, ReferenceVelocityOutsideTheCampaignIsAnError) {
  make({"tsuji"});
  auto args = arguments(scratch / "export");
  args.insert(args.end(), {"--reference-velocity", "3"});
  const CliRun run = run_export(args, scratch);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(
      contains(run.err,
               "reference velocity 3 m/s is not a velocity of the campaign (0.5, 1, 2 m/s)"))
      << run.err;
  EXPECT_FALSE(fs::exists(scratch / "export"));
  args.back() = "-1";
  EXPECT_EQ(run_export(args, scratch).exit_code, 2);
}

// The restitution table: none without a damped elastic-plastic law; a law the calibration
// does not have, or too few points, is refused by name and nothing is written.
TEST_F(ExportCli, RestitutionTableOfALawTheCalibrationLacksIsAnError) {
  make({"tsuji"});
  const CliRun plain = run_export(arguments(scratch / "export"), scratch);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_FALSE(fs::exists(scratch / "export" / "restitution"));
  fs::remove_all(scratch / "export");
  auto args = arguments(scratch / "export");
  args.insert(args.end(), {"--law", "hunt-crossley-thornton"});
  const CliRun run = run_export(args, scratch);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "the calibration has no law hunt-crossley-thornton")) << run.err;
  EXPECT_TRUE(contains(run.err, "nothing was written")) << run.err;
  EXPECT_FALSE(fs::exists(scratch / "export"));
  args.back() = "tsuji";
  const CliRun other = run_export(args, scratch);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_TRUE(contains(other.err, "--law tsuji: not a damped elastic-plastic law")) << other.err;
  args = arguments(scratch / "export");
  args.insert(args.end(), {"--table-points", "1"});
  const CliRun points = run_export(args, scratch);
  EXPECT_EQ(points.exit_code, 2);
  EXPECT_TRUE(contains(points.err, "--table-points")) << points.err;
  EXPECT_FALSE(fs::exists(scratch / "export"));
}

// Nothing written from nothing: a missing or an empty campaign directory.
TEST_F(ExportCli, NoUsableRunWritesNothing) {
  make({"tsuji"});
  fs::create_directories(scratch / "empty");
  for (const auto& [directory, why] :
       {std::pair<std::string, std::string>{"nowhere", "does not exist"},
        {"empty", "holds no run"}}) {
    auto args = arguments(scratch / "export");
    args[1] = (scratch / directory).string();
    const CliRun run = run_export(args, scratch);
    EXPECT_EQ(run.exit_code, 2) << directory;
    EXPECT_TRUE(contains(run.err, why)) << run.err;
    EXPECT_TRUE(contains(run.err, "nothing was written")) << run.err;
    EXPECT_FALSE(fs::exists(scratch / "export")) << directory;
  }
}

TEST_F(ExportCli, MissingRadiusOrCalibrationIsAnError) {
  make({"tsuji"}, false);
  CliRun run = run_export(arguments(scratch / "export"), scratch);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "'Scenario/Sphere radius'")) << run.err;
  EXPECT_FALSE(fs::exists(scratch / "export"));
  auto args = arguments(scratch / "export");
  args[3] = (scratch / "none.json").string();
  run = run_export(args, scratch);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "cannot open the calibration")) << run.err;
}

} // namespace

namespace {

// --help names the four simulators the exporters write (the issue: it said "three", without
// LIGGGHTS), and exits 0 wherever it stands, required options missing.
TEST(ExportCliUsage, NamesTheFourSimulators) {
  const fs::path scratch = impact::testing::scratch_directory("export_usage");
  for (const std::vector<std::string>& arguments :
       std::vector<std::vector<std::string>>{{"--help"}, {"--campaign", "x", "-h"}}) {
    const CliRun run = run_export(arguments, scratch);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    for (const char* text : {"four simulators", "simbody/", "mujoco/", "lammps/", "liggghts/",
                             "--reference-velocity V", "--calibration FILE", "restitution/",
                             "--law KEY", "--table-points N"})
      EXPECT_TRUE(contains(run.out, text)) << text << " not in " << run.out;
  }
  fs::remove_all(scratch);
}

} // namespace
