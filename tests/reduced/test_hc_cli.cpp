// impact-reduced hc and damping: the JSON and CSV outputs, and exit code 2 with a message
// naming the parameter for every kind of bad input. hc from the materials of both bodies
// (c from the library's hertz_stiffness, m of a solid sphere), on an elastic or a rigid flat.

#include "cli_runner.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/hunt_crossley.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace {

using impact::testing::arguments_of;
using impact::testing::expect_rejected;
using impact::testing::run_cli;

const std::map<std::string, std::string> published = {{"mass", "0.1"},
                                                      {"stiffness", "1.7135e10"},
                                                      {"exponent", "1.5"},
                                                      {"damping", "0.1"},
                                                      {"velocity", "1"}};

TEST(HcCli, PrintsEveryKeyOfThePublishedExample) {
  const auto run = run_cli("hc", arguments_of(published));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  for (const char* key : {"mass", "stiffness", "exponent", "damping", "velocity", "x_max",
                          "force_max", "time_force_max", "compression_time", "contact_time",
                          "rebound_velocity", "restitution", "energy_loss"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_NEAR(json["x_max"].get<double>(), 3.42046253e-5, 0.5e-13);
  EXPECT_NEAR(json["restitution"].get<double>(), 0.937475580, 0.5e-9);
  EXPECT_LT(json["rebound_velocity"].get<double>(), 0.0);
}

TEST(HcCli, HistoryIsACsvTable) {
  auto options = published;
  options["history"] = "11";
  const auto run = run_cli("hc", arguments_of(options));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::stringstream lines(run.out);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "time,approach,velocity,force");
  int rows = 0;
  while (std::getline(lines, line)) ++rows;
  EXPECT_EQ(rows, 11);
}

TEST(HcCli, BadInputExitsWithTwoAndNamesTheParameter) {
  for (const auto& [name, valid] : published) {
    auto without = published;
    without.erase(name);
    if (name != "exponent") // optional: 1.5 by default
      expect_rejected("hc", without, name, "missing --" + name);
    std::vector<std::string> bad_values = {"-1", "abc", "nan", "inf", "1e999", ""};
    if (name != "damping") bad_values.push_back("0");
    for (const auto& bad : bad_values) {
      auto options = published;
      options[name] = bad;
      expect_rejected("hc", options, name, "--" + name + " " + bad);
    }
  }
  auto options = published;
  options["history"] = "1";
  expect_rejected("hc", options, "history", "--history 1");
  options.erase("history");
  options["colour"] = "red";
  expect_rejected("hc", options, "colour", "unknown option");
}

TEST(DampingCli, PublishedValueAndBadInput) {
  const std::map<std::string, std::string> good = {{"restitution", "0.9"}, {"velocity", "1"}};
  const auto run = run_cli("damping", arguments_of(good));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_NEAR(json["damping"].get<double>(), 0.166481951, 0.5e-9);
  EXPECT_NEAR(json["beta"].get<double>(), 0.166481951, 0.5e-9);
  for (const auto& [name, valid] : good) {
    auto without = good;
    without.erase(name);
    expect_rejected("damping", without, name, "missing --" + name);
    for (const std::string bad : {"0", "-0.5", "abc", "nan", "inf"}) {
      auto options = good;
      options[name] = bad;
      expect_rejected("damping", options, name, "--" + name + " " + bad);
    }
  }
  expect_rejected("damping", {{"restitution", "1.5"}, {"velocity", "1"}}, "restitution", "e > 1");
}

// The steel ball of the published example (E = 200 GPa, nu = 0.25, R = 14.52 mm,
// rho = 7800 kg/m^3) on a steel flat, given by its materials.
const std::map<std::string, std::string> materials = {
    {"sphere-modulus", "2e11"}, {"sphere-poisson", "0.25"}, {"radius", "0.01452"},
    {"sphere-density", "7800"}, {"flat-modulus", "2e11"},   {"flat-poisson", "0.25"},
    {"damping", "0.1"},         {"velocity", "1"}};

TEST(HcCli, MaterialsGiveTheHertzStiffnessAndTheSphereMass) {
  using namespace impact::reduced;
  const auto run = run_cli("hc", arguments_of(materials));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  const double c = hertz_stiffness({2e11, 0.25, 0.01452}, {2e11, 0.25});
  const double m = solid_sphere_mass(0.01452, 7800);
  EXPECT_EQ(json["stiffness"].get<double>(), c);
  EXPECT_EQ(json["mass"].get<double>(), m);
  EXPECT_EQ(json["exponent"].get<double>(), 1.5);
  const auto expected = HuntCrossleyImpact(m, c, 1.5, 0.1, 1).response();
  EXPECT_EQ(json["x_max"].get<double>(), expected.approach_max);
  EXPECT_EQ(json["restitution"].get<double>(), expected.restitution);
  EXPECT_NE(json["contact"].get<std::string>().find("Hertz"), std::string::npos);
}

TEST(HcCli, RigidFlatByName) {
  using namespace impact::reduced;
  auto options = materials;
  options.erase("flat-modulus");
  options.erase("flat-poisson");
  options["flat"] = "rigid";
  const auto run = run_cli("hc", arguments_of(options));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["stiffness"].get<double>(), hertz_stiffness({2e11, 0.25, 0.01452}, rigid_body()));
  EXPECT_NE(json["contact"].get<std::string>().find("rigid flat"), std::string::npos);
  options["flat"] = "steel";
  impact::testing::expect_rejected("hc", options, "flat", "--flat steel");
}

TEST(HcCli, MaterialsConflictOrIncompleteExitTwoNamingTheOption) {
  using impact::testing::expect_rejected;
  auto options = materials;
  options["stiffness"] = "1e10";
  expect_rejected("hc", options, "stiffness", "--stiffness with the materials");
  options = materials;
  options["mass"] = "0.1";
  expect_rejected("hc", options, "sphere-density", "--mass with --sphere-density");
  options = materials;
  options["exponent"] = "1.4";
  expect_rejected("hc", options, "exponent", "--exponent with the materials");
  options = materials;
  options["flat"] = "rigid";
  expect_rejected("hc", options, "flat-modulus", "--flat rigid with --flat-modulus");
  for (const char* missing : {"sphere-poisson", "radius"}) {
    options = materials;
    options.erase(missing);
    expect_rejected("hc", options, missing, std::string("without --") + missing);
  }
  options = materials;
  options.erase("flat-modulus");
  options.erase("flat-poisson");
  expect_rejected("hc", options, "flat-modulus", "no flat");
  options = published;
  options["flat-poisson"] = "0.3";
  expect_rejected("hc", options, "flat-poisson", "--flat-poisson with --stiffness");
  // A mass outside --mass's range, from the radius and density.
  options = materials;
  options["radius"] = "1e3";
  options["sphere-density"] = "1e5";
  expect_rejected("hc", options, "mass", "a mass of 4e14 kg");
}

// The cases of "internal error" on finite values: each refused, naming the option and
// its range, or answered.
TEST(HcCli, ExtremeValuesAreRefusedWithTheirRange) {
  auto options = published;
  options["exponent"] = "1e300";
  expect_rejected("hc", options, "exponent", "--exponent 1e300");
  options = published;
  options["mass"] = "1e308";
  expect_rejected("hc", options, "mass", "--mass 1e308");
  const auto run = run_cli("hc", arguments_of(options));
  EXPECT_NE(run.err.find("a number in ["), std::string::npos) << run.err;
  options = published;
  options["damping"] = "2e3";
  expect_rejected("hc", options, "damping", "b V = 2e3");
}

TEST(Cli, UnknownCommandExitsWithTwo) {
  const auto run = run_cli("bounce", {});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown command"), std::string::npos);
}

} // namespace
