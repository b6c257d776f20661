// The exports of impact-export run in the simulators themselves (run_in_simulators.sh) on the
// fixture campaign (make_export.cmake). Each test checks the tool against the reduced model
// its export came from, computed here from the calibration JSON with the reduced library
// (not from the export), and prints the tool's errors against the campaign's FEM values:
//   Simbody, LAMMPS: e, t_c, F_max within 0.5 % of the law at every campaign velocity;
//   MuJoCo: e, t_c within 1 % of the FEM at its reference velocity (the median run).

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;
namespace reduced = impact::reduced;

const fs::path work = IMPACT_CONSUMER_WORK_DIR;

json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  return json::parse(in);
}

// Runs the tool on the fixture's export; returns its result files.
json run_tool(const std::string& tool, const std::string& result) {
  const fs::path output = work / ("in_simulator_" + tool);
  fs::remove_all(output);
  const std::string command = "IMPACT_BUILD_DIR='" + std::string(IMPACT_BUILD_DIR) + "' bash '" +
                              IMPACT_RUN_IN_SIMULATORS + "' '" + (work / "export").string() +
                              "' '" + output.string() + "' " + tool;
  const int status = std::system(command.c_str());
  if (status != 0) throw std::runtime_error(command + " failed (status " + std::to_string(status) + ")");
  return read_json(output / result);
}

struct Figures {
  double restitution, contact_time, force_max;
};

Figures tool_figures(const json& run) {
  const json& tool = run.at("tool");
  return {tool.at("restitution"), tool.at("contact_time"), tool.at("force_max")};
}

const json& campaign_fit(const json& calibration, const std::string& model) {
  if (model == "hunt-crossley") return calibration.at("campaign").at("hunt_crossley_hertz_exponent");
  for (const auto& law : calibration.at("campaign").at("comparison_laws"))
    if (law.at("model") == model) return law;
  throw std::runtime_error("the calibration has no " + model + " fit");
}

double parameter(const json& fit, const std::string& name) {
  return fit.at("parameters").at(name).at("value");
}

// The run of the calibration at velocity V.
const json& calibration_run(const json& calibration, double velocity) {
  for (const auto& run : calibration.at("runs"))
    if (std::abs(run.at("impact_velocity").get<double>() / velocity - 1) < 1e-9) return run;
  throw std::runtime_error("no calibration run at V = " + std::to_string(velocity));
}

void print_against_fem(const std::string& label, const json& calibration, const json& result) {
  std::printf("%s against the FEM of the campaign (tool / FEM - 1):\n", label.c_str());
  std::printf("  V [m/s]  e         1-e^2      t_c [s]      F_max [N]   | de/e     d(1-e^2)  dt/t     dF/F\n");
  for (const auto& run : result.at("runs")) {
    const double velocity = run.at("impact_velocity");
    const Figures tool = tool_figures(run);
    const json& fem = calibration_run(calibration, velocity).at("measured");
    const double e = fem.at("restitution");
    std::printf("  %-7.3g  %-8.6f  %-9.5f  %-11.5g  %-10.5g  | %+6.2f%%  %+7.2f%%  %+6.2f%%  %+6.2f%%\n",
                velocity, tool.restitution, 1 - tool.restitution * tool.restitution,
                tool.contact_time, tool.force_max, 100 * (tool.restitution / e - 1),
                100 * ((1 - tool.restitution * tool.restitution) / (1 - e * e) - 1),
                100 * (tool.contact_time / fem.at("contact_time").get<double>() - 1),
                100 * (tool.force_max / fem.at("force_max").get<double>() - 1));
  }
}

// Every run of `result` within `tolerance` of the law `model` of the calibration.
void expect_reproduces_law(const json& calibration, const json& result, const std::string& model,
                           double tolerance) {
  const json& fit = campaign_fit(calibration, model);
  const double c = parameter(fit, "c");
  ASSERT_EQ(result.at("runs").size(), calibration.at("runs").size());
  std::printf("%s against the calibrated %s law (tool / law - 1):\n",
              result.at("file").get<std::string>().c_str(), model.c_str());
  for (const auto& run : result.at("runs")) {
    const double velocity = run.at("impact_velocity");
    const double mass = calibration_run(calibration, velocity).at("mass");
    Figures law;
    if (model == "hunt-crossley") {
      const auto response =
          reduced::HuntCrossleyImpact(mass, c, 1.5, parameter(fit, "b"), velocity).response();
      law = {response.restitution, response.contact_time, response.force_max};
    } else {
      const reduced::ContactSetup setup{mass, c, 1.5};
      const double damping = parameter(fit, model == "tsuji" ? "eta" : "A");
      const auto impact = reduced::integrate_impact(
          mass, velocity, reduced::comparison_law(model).force_law(damping, setup), 1e-12);
      law = {impact.restitution, impact.contact_time, impact.force_max};
    }
    const Figures tool = tool_figures(run);
    std::printf("  V = %-5.3g m/s: e %+.2e, t_c %+.2e, F_max %+.2e\n", velocity,
                tool.restitution / law.restitution - 1, tool.contact_time / law.contact_time - 1,
                tool.force_max / law.force_max - 1);
    EXPECT_NEAR(tool.restitution / law.restitution, 1, tolerance) << "V = " << velocity;
    EXPECT_NEAR(tool.contact_time / law.contact_time, 1, tolerance) << "V = " << velocity;
    EXPECT_NEAR(tool.force_max / law.force_max, 1, tolerance) << "V = " << velocity;
  }
}

TEST(Simbody, ReproducesTheHuntCrossleyLawOfTheCalibration) {
  const json calibration = read_json(work / "calibration.json");
  const json result = run_tool("simbody", "simbody.json");
  EXPECT_EQ(result.at("tool_version"), "3.7");
  expect_reproduces_law(calibration, result, "hunt-crossley", 0.005);
  print_against_fem("Simbody", calibration, result);
}

TEST(Lammps, ReproducesTheKuwabaraKonoAndTsujiLawsOfTheCalibration) {
  const json calibration = read_json(work / "calibration.json");
  const json kuwabara_kono = run_tool("lammps", "lammps-kuwabara-kono.json");
  expect_reproduces_law(calibration, kuwabara_kono, "kuwabara-kono", 0.005);
  print_against_fem("LAMMPS, Kuwabara-Kono (viscoelastic)", calibration, kuwabara_kono);
  const json tsuji = read_json(work / "in_simulator_lammps" / "lammps-tsuji.json");
  expect_reproduces_law(calibration, tsuji, "tsuji", 0.005);
  print_against_fem("LAMMPS, Tsuji", calibration, tsuji);
}

TEST(Mujoco, ReproducesTheFemRestitutionAndContactTimeAtItsReferenceVelocity) {
  const json calibration = read_json(work / "calibration.json");
  const json result = run_tool("mujoco", "mujoco.json");
  // The median run of the campaign (the lower middle one for an even count).
  const json& runs = calibration.at("runs");
  const json& median = runs[(runs.size() - 1) / 2];
  const double reference = median.at("impact_velocity");
  EXPECT_DOUBLE_EQ(result.at("reference_velocity").get<double>(), reference);
  bool found = false;
  for (const auto& run : result.at("runs")) {
    if (run.at("impact_velocity").get<double>() != reference) continue;
    found = true;
    const Figures tool = tool_figures(run);
    const json& fem = median.at("measured");
    std::printf("MuJoCo at its reference velocity %g m/s: e %+.2e, t_c %+.2e against the FEM\n",
                reference, tool.restitution / fem.at("restitution").get<double>() - 1,
                tool.contact_time / fem.at("contact_time").get<double>() - 1);
    EXPECT_NEAR(tool.restitution / fem.at("restitution").get<double>(), 1, 0.01);
    EXPECT_NEAR(tool.contact_time / fem.at("contact_time").get<double>(), 1, 0.01);
  }
  EXPECT_TRUE(found) << "no MuJoCo run at the reference velocity";
  print_against_fem("MuJoCo", calibration, result);
}

} // namespace
