// impact-calibrate as a user runs it: a good campaign gives exit 0 and a JSON with every key;
// each bad input gives exit 2, a message naming the problem, and a JSON that says what is
// missing; a fit that does not converge gives exit 3 and says so.

#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace {

using namespace impact::postprocess;
using json = nlohmann::json;
namespace fs = std::filesystem;

const impact::testing::HuntCrossleyTruth truth;
const std::string few_laws = "lankarani-nikravesh,kuwabara-kono";

struct CliRun {
  int exit_code;
  std::string out;
  std::string err;
};

std::string read_text(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

CliRun run_cli(const std::vector<std::string>& arguments, const fs::path& scratch) {
  std::string command = std::string("'") + IMPACT_CALIBRATE_CLI + "'";
  for (const auto& argument : arguments) command += " '" + argument + "'";
  command +=
      " >'" + (scratch / "out.txt").string() + "' 2>'" + (scratch / "err.txt").string() + "'";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(scratch / "out.txt"),
          read_text(scratch / "err.txt")};
}

json read_json(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class CalibrateCli : public ::testing::Test {
protected:
  void SetUp() override {
    directory = impact::testing::scratch_directory(
        std::string("cli_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    output = directory / "calibration.json";
  }
  void TearDown() override { fs::remove_all(directory); }

  fs::path add_run(const std::string& name, double velocity) {
    return write_fem_run(impact::testing::synthetic_run(truth, velocity), directory / name);
  }

  fs::path directory;
  fs::path output;
};

// The keys a consumer of the JSON may rely on (postprocess/README.md).
void expect_fit_keys(const json& fit, const std::string& where) {
  for (const char* key : {"model", "parameters", "correlation", "covariance", "reference_approach",
                          "force_at_reference_approach", "rms_residual", "r_squared", "samples",
                          "converged", "iterations", "solver_message"})
    EXPECT_TRUE(fit.contains(key)) << where << " has no '" << key << "'";
  ASSERT_TRUE(fit["parameters"].is_object()) << where;
  EXPECT_EQ(fit["parameters"].size(), 3u) << where;
  for (const auto& [name, parameter] : fit["parameters"].items())
    for (const char* key : {"value", "standard_error", "interval", "unit", "fixed"})
      EXPECT_TRUE(parameter.contains(key)) << where << " parameter " << name << " has no " << key;
  EXPECT_EQ(fit["correlation"].size(), 3u) << where;
}

void expect_prediction_keys(const json& prediction, const std::string& where) {
  for (const char* key :
       {"damping", "restitution", "contact_time", "force_max", "time_force_max", "approach_max"})
    EXPECT_TRUE(prediction.contains(key)) << where << " has no '" << key << "'";
}

TEST_F(CalibrateCli, CampaignGivesEveryKey) {
  for (double velocity : {0.5, 1.0, 2.0}) add_run("v" + std::to_string(velocity), velocity);
  const CliRun run =
      run_cli({"--campaign", directory.string(), "--output", output.string(), "--laws", few_laws},
              directory);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(contains(run.err, "run 1/3")) << run.err; // progress on stderr
  EXPECT_TRUE(contains(run.out, "calibration written to")) << run.out;
  const json calibration = read_json(output);

  for (const char* key : {"format", "format_version", "generated_by", "status", "problems",
                          "confidence_level", "units", "multibody", "runs", "campaign"})
    EXPECT_TRUE(calibration.contains(key)) << "no '" << key << "'";
  EXPECT_EQ(calibration["status"], "complete");
  EXPECT_TRUE(calibration["problems"].empty());
  for (const char* key : {"c", "n", "b", "e", "impact_velocity", "rms_residual", "r_squared"})
    EXPECT_TRUE(calibration["units"].contains(key)) << "units has no '" << key << "'";

  const json& multibody = calibration["multibody"];
  for (const char* key : {"model", "force_law", "c", "n", "b", "units", "basis", "converged"})
    EXPECT_TRUE(multibody.contains(key)) << "multibody has no '" << key << "'";
  EXPECT_NEAR(multibody["c"].get<double>() / truth.stiffness, 1, 1e-6);
  EXPECT_NEAR(multibody["n"].get<double>(), truth.exponent, 1e-6);
  EXPECT_NEAR(multibody["b"].get<double>(), truth.damping, 1e-7);
  // b(V) for a multibody code: the data have a constant b, so q = 0 and b_1 = b.
  const json& velocity_damping = calibration["multibody_velocity_damping"];
  for (const char* key :
       {"model", "force_law", "c", "n", "b_1", "q", "units", "basis", "converged"})
    EXPECT_TRUE(velocity_damping.contains(key))
        << "multibody_velocity_damping has no '" << key << "'";
  EXPECT_NEAR(velocity_damping["q"].get<double>(), 0, 1e-6);
  EXPECT_NEAR(velocity_damping["b_1"].get<double>(), truth.damping, 1e-7);

  ASSERT_EQ(calibration["runs"].size(), 3u);
  for (const auto& entry : calibration["runs"]) {
    for (const char* key : {"source", "impact_velocity", "mass", "measured", "restitution_fit",
                            "loading_fit", "history_fit", "history_prediction"})
      EXPECT_TRUE(entry.contains(key)) << "run has no '" << key << "'";
    for (const char* key :
         {"restitution", "contact_time", "force_max", "time_force_max", "approach_max"})
      EXPECT_TRUE(entry["measured"].contains(key)) << "measured has no '" << key << "'";
    EXPECT_NEAR(entry["restitution_fit"]["b"]["value"].get<double>(), truth.damping, 1e-12);
    expect_fit_keys(entry["loading_fit"], "loading_fit");
    expect_fit_keys(entry["history_fit"], "history_fit");
    expect_prediction_keys(entry["history_prediction"], "history_prediction");
  }

  const json& campaign = calibration["campaign"];
  for (const char* key : {"fitted", "reason", "velocities", "hunt_crossley",
                          "hunt_crossley_hertz_exponent", "comparison_laws", "ranking"})
    EXPECT_TRUE(campaign.contains(key)) << "campaign has no '" << key << "'";
  EXPECT_TRUE(campaign["fitted"].get<bool>());
  EXPECT_EQ(campaign["velocities"].size(), 3u);
  std::vector<json> fits = {campaign["hunt_crossley"], campaign["hunt_crossley_hertz_exponent"]};
  for (const auto& law : campaign["comparison_laws"]) fits.push_back(law);
  ASSERT_EQ(fits.size(), 4u);
  const json& fixed_n = campaign["hunt_crossley_hertz_exponent"]["parameters"]["n"];
  EXPECT_EQ(fixed_n["value"].get<double>(), 1.5);
  EXPECT_TRUE(fixed_n["fixed"].get<bool>());
  EXPECT_TRUE(fixed_n["interval"][0].is_null());
  EXPECT_TRUE(contains(run.out, "Hunt-Crossley with n = 1.5 fixed: c = ")) << run.out;
  for (const auto& fit : fits) {
    expect_fit_keys(fit, fit["model"].get<std::string>());
    for (const char* key : {"formula", "reference", "damping", "runs"})
      EXPECT_TRUE(fit.contains(key)) << fit["model"] << " has no '" << key << "'";
    ASSERT_EQ(fit["runs"].size(), 3u);
    for (const auto& entry : fit["runs"]) {
      for (const char* key :
           {"source", "impact_velocity", "rms_residual", "r_squared", "samples", "prediction"})
        EXPECT_TRUE(entry.contains(key)) << fit["model"] << " run has no '" << key << "'";
      expect_prediction_keys(entry["prediction"], fit["model"].get<std::string>());
    }
  }
  EXPECT_EQ(campaign["comparison_laws"][1]["parameters"].count("A"), 1u); // Kuwabara–Kono
  EXPECT_EQ(campaign["comparison_laws"][0]["parameters"].count("e"), 1u); // Lankarani–Nikravesh
  // The ranking holds every campaign fit (Hunt–Crossley on the histories, with the energy
  // loss, with n = 3/2, with b(V), the two laws) and the reference models that fit nothing
  // (Hertz, the published b; no material A: the runs record no retardation times).
  ASSERT_EQ(campaign["ranking"].size(), 8u);
  EXPECT_EQ(campaign["ranking"][0]["model"], "hunt-crossley"); // the law that made the data
  for (const auto& entry : campaign["ranking"])
    for (const char* key : {"model", "free_parameters", "score", "out_of_sample", "worst_error",
                            "in_sample_score", "rms_residual", "converged", "family", "parameter"})
      EXPECT_TRUE(entry.contains(key)) << entry["model"] << " has no '" << key << "'";
  // Three velocities: every campaign fit is repeated without each, for out-of-sample
  // predictions and jackknife intervals.
  for (const char* key :
       {"hunt_crossley", "hunt_crossley_energy", "hunt_crossley_velocity_damping"}) {
    const json& fit = campaign[key];
    ASSERT_TRUE(fit.is_object()) << key;
    EXPECT_EQ(fit["held_out"].size(), 3u) << key;
    EXPECT_TRUE(fit["jackknife"].is_object()) << key;
    for (const auto& entry : fit["runs"]) EXPECT_TRUE(entry["out_of_sample"].is_object()) << key;
  }
  EXPECT_EQ(campaign["hunt_crossley_velocity_damping"]["parameters"].size(), 4u); // c, n, b_1, q
  EXPECT_EQ(campaign["energy_weight"], 1.0);
  EXPECT_EQ(campaign["published_damping"], 0.1);
  EXPECT_EQ(campaign["restitution_maps"].size(), 5u);
}

TEST_F(CalibrateCli, SingleVelocityCampaign) {
  add_run("v1", 1.0);
  const CliRun run =
      run_cli({"--campaign", directory.string(), "--output", output.string(), "--laws", "none"},
              directory);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "single impact velocity")) << run.err;
  const json calibration = read_json(output);
  EXPECT_EQ(calibration["status"], "incomplete");
  EXPECT_FALSE(calibration["campaign"]["fitted"].get<bool>());
  EXPECT_TRUE(contains(calibration["campaign"]["reason"].get<std::string>(), "single"));
  EXPECT_TRUE(calibration["campaign"]["hunt_crossley"].is_null());
  ASSERT_EQ(calibration["runs"].size(), 1u); // the run itself is still calibrated
  EXPECT_TRUE(calibration["runs"][0]["history_fit"].is_object());
}

TEST_F(CalibrateCli, OneRunGivenExplicitlyIsAPerRunCalibration) {
  const fs::path file = add_run("v1", 1.0);
  const CliRun run = run_cli({file.string(), "--output", output.string(), "--quiet"}, directory);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  const json calibration = read_json(output);
  EXPECT_EQ(calibration["status"], "complete");
  EXPECT_TRUE(contains(calibration["multibody"]["basis"].get<std::string>(), "single run"));
  EXPECT_NEAR(calibration["multibody"]["b"].get<double>(), truth.damping, 1e-7);
}

TEST_F(CalibrateCli, CampaignWithBadRunsCalibratesTheOthersAndListsTheProblems) {
  add_run("v1", 1.0);
  add_run("v2", 2.0);
  write_fem_run(impact::testing::synthetic_run(truth, 3.0), directory / "v3", false);
  FemRun no_contact = impact::testing::synthetic_run(truth, 4.0);
  std::fill(no_contact.contact_force.begin(), no_contact.contact_force.end(), 0.0);
  write_fem_run(no_contact, directory / "v4");
  std::ofstream(directory / fem_format::campaign_index_json)
      << R"({"runs": [{"velocity": 1, "path": "v1"}, {"velocity": 2, "path": "v2"},
                      {"velocity": 3, "path": "v3"}, {"velocity": 4, "path": "v4"},
                      {"velocity": 5, "path": "v5"}]})";
  const CliRun run =
      run_cli({"--campaign", directory.string(), "--output", output.string(), "--laws", "none"},
              directory);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "did not finish")) << run.err;
  EXPECT_TRUE(contains(run.err, "no contact")) << run.err;
  EXPECT_TRUE(contains(run.err, "v5")) << run.err;
  const json calibration = read_json(output);
  EXPECT_EQ(calibration["status"], "incomplete");
  EXPECT_EQ(calibration["problems"].size(), 3u);
  EXPECT_EQ(calibration["runs"].size(), 2u);
  EXPECT_TRUE(calibration["campaign"]["fitted"].get<bool>());
}

// Nothing written from nothing: without a usable run there is no calibration file, only the
// message why (a missing campaign directory, an empty one).
TEST_F(CalibrateCli, NoUsableRunWritesNothing) {
  fs::create_directories(directory / "empty");
  for (const auto& [campaign, why] :
       {std::pair<std::string, std::string>{"nowhere", "does not exist"},
        {"empty", "holds no run"}}) {
    const CliRun run =
        run_cli({"--campaign", (directory / campaign).string(), "--output", output.string()},
                directory);
    EXPECT_EQ(run.exit_code, 2) << campaign;
    EXPECT_TRUE(contains(run.err, why)) << run.err;
    EXPECT_TRUE(contains(run.err, "no usable run: nothing was calibrated")) << run.err;
    EXPECT_FALSE(fs::exists(output)) << campaign;
  }
}

TEST_F(CalibrateCli, MissingRunFile) {
  const CliRun run =
      run_cli({(directory / "absent.h5").string(), "--output", output.string()}, directory);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "absent.h5")) << run.err;
  EXPECT_TRUE(contains(run.err, "does not exist")) << run.err;
}

TEST_F(CalibrateCli, UsageErrorsNameTheProblem) {
  const fs::path file = add_run("v1", 1.0);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{file.string()}, "--output FILE is required"},
      {{"--output", output.string()}, "no input"},
      {{file.string(), "--campaign", directory.string(), "--output", output.string()}, "not both"},
      {{file.string(), "--output", output.string(), "--frobnicate"},
       "unknown option '--frobnicate'"},
      {{file.string(), "--output", output.string(), "--laws", "nonsense"},
       "unknown law 'nonsense'"},
      {{file.string(), "--output", output.string(), "--max-iterations", "0"}, "--max-iterations"},
      {{file.string(), "--output", output.string(), "--confidence", "1.5"}, "--confidence"},
      {{file.string(), "--output", output.string(), "--energy-weight", "-1"}, "--energy-weight"},
      {{file.string(), "--output", output.string(), "--published-damping", "fast"},
       "--published-damping"},
      {{file.string(), "--output", output.string(), "--damped-stiffness", "free"},
       "--damped-stiffness must be one of hertz|fitted (got 'free')"},
      {{file.string(), "--output", (directory / "no" / "c.json").string()}, "does not exist"},
      {{file.string(), "--output"}, "needs a value"}};
  for (const auto& [arguments, message] : cases) {
    const CliRun run = run_cli(arguments, directory);
    EXPECT_EQ(run.exit_code, 2) << message;
    EXPECT_TRUE(contains(run.err, message)) << "expected '" << message << "' in: " << run.err;
  }
  EXPECT_EQ(run_cli({"--help"}, directory).exit_code, 0);
}

TEST_F(CalibrateCli, FitThatDoesNotConvergeIsReported) {
  add_run("v1", 1.0);
  add_run("v2", 2.0);
  // Noisy data and a single iteration: no fit can converge.
  write_fem_run(impact::testing::synthetic_run(truth, 4.0, 0.01), directory / "v4");
  const CliRun run = run_cli({"--campaign", directory.string(), "--output", output.string(),
                              "--laws", "none", "--max-iterations", "1"},
                             directory);
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_TRUE(contains(run.err, "did not converge")) << run.err;
  const json calibration = read_json(output);
  EXPECT_EQ(calibration["status"], "incomplete");
  bool reported = false;
  for (const auto& problem : calibration["problems"])
    reported = reported || problem["kind"] == "convergence";
  EXPECT_TRUE(reported);
  EXPECT_FALSE(calibration["multibody"]["converged"].get<bool>());
}

} // namespace
