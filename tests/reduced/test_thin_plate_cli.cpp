// impact-reduced thin-plate: JSON and CSV outputs equal to the library's, both ways of
// giving the contact and the mass, and exit code 2 with a message naming the option for
// every kind of bad input (nothing on stdout).

#include "cli_runner.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/thin_plate.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace {

using impact::testing::arguments_of;
using impact::testing::run_cli;

constexpr double pi = 3.14159265358979323846;

// The study's steel ball on a 5 mm steel plate, from the materials.
const std::map<std::string, std::string> materials = {
    {"plate-modulus", "2e11"}, {"plate-poisson", "0.25"},  {"plate-density", "7800"},
    {"thickness", "0.005"},    {"sphere-modulus", "2e11"}, {"sphere-poisson", "0.25"},
    {"radius", "0.01452"},     {"sphere-density", "7800"}, {"velocity", "1"}};

// The same plate, the contact and the mass given directly, Hunt-Crossley damping.
const std::map<std::string, std::string> direct = {
    {"plate-modulus", "2e11"}, {"plate-poisson", "0.25"},  {"plate-density", "7800"},
    {"thickness", "0.005"},    {"stiffness", "1.7135e10"}, {"exponent", "1.5"},
    {"mass", "0.1"},           {"damping", "0.1"},         {"velocity", "0.5,1,5"}};

TEST(ThinPlateCli, MaterialsGiveTheLibrarysImpact) {
  const auto run = run_cli("thin-plate", arguments_of(materials));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  const impact::reduced::KirchhoffPlate plate{2e11, 0.25, 7800, 0.005};
  const double mass = 4.0 / 3.0 * pi * std::pow(0.01452, 3) * 7800;
  const double c = impact::reduced::hertz_stiffness({2e11, 0.25, 0.01452}, {2e11, 0.25});
  const double Z = impact::reduced::plate_point_impedance(plate);
  const auto expected = impact::reduced::ThinPlateImpact(c, 1.5, 0, mass, Z).impact(1.0);
  EXPECT_DOUBLE_EQ(json["mass"].get<double>(), mass);
  EXPECT_DOUBLE_EQ(json["stiffness"].get<double>(), c);
  EXPECT_DOUBLE_EQ(json["impedance"].get<double>(), Z);
  ASSERT_EQ(json["impacts"].size(), 1u);
  const auto& impact = json["impacts"][0];
  for (const char* key :
       {"velocity", "zener_lambda", "restitution", "contact_time", "force_max", "time_force_max",
        "approach_max", "time_approach_max", "plate_energy_fraction", "damping_energy_fraction",
        "plate_deflection", "number_of_contacts"})
    EXPECT_TRUE(impact.contains(key)) << key;
  EXPECT_EQ(impact["restitution"].get<double>(), expected.restitution);
  EXPECT_EQ(impact["contact_time"].get<double>(), expected.contact_time);
  EXPECT_EQ(impact["force_max"].get<double>(), expected.force_max);
  EXPECT_EQ(impact["approach_max"].get<double>(), expected.approach_max);
  EXPECT_EQ(impact["zener_lambda"].get<double>(),
            impact::reduced::zener_lambda(0.01452, 7800, 2e11, 0.25, plate, 1.0));
  EXPECT_EQ(impact["number_of_contacts"].get<int>(), 1);
}

TEST(ThinPlateCli, SeveralVelocitiesAsJsonAndCsv) {
  const auto run = run_cli("thin-plate", arguments_of(direct));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  ASSERT_EQ(json["impacts"].size(), 3u);
  const impact::reduced::ThinPlateImpact model(1.7135e10, 1.5, 0.1, 0.1,
                                               impact::reduced::plate_point_impedance(
                                                   {2e11, 0.25, 7800, 0.005}));
  const double velocities[] = {0.5, 1, 5};
  for (int i = 0; i < 3; ++i) {
    const auto expected = model.impact(velocities[i]);
    EXPECT_EQ(json["impacts"][i]["velocity"].get<double>(), velocities[i]);
    EXPECT_EQ(json["impacts"][i]["restitution"].get<double>(), expected.restitution);
    EXPECT_EQ(json["impacts"][i]["damping_energy_fraction"].get<double>(),
              expected.damping_energy_fraction);
  }
  auto options = direct;
  options["format"] = "csv";
  const auto csv = run_cli("thin-plate", arguments_of(options));
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  std::stringstream lines(csv.out);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "velocity,zener_lambda,restitution,contact_time,force_max,time_force_max,"
            "approach_max,time_approach_max,plate_energy_fraction,"
            "damping_energy_fraction,plate_deflection,number_of_contacts");
  int rows = 0;
  while (std::getline(lines, line)) ++rows;
  EXPECT_EQ(rows, 3);
}

void expect_rejected(const std::map<std::string, std::string>& options,
                     const std::string& parameter, const std::string& what) {
  impact::testing::expect_rejected("thin-plate", options, parameter, what);
}

TEST(ThinPlateCli, BadInputExitsWithTwoAndNamesTheOption) {
  for (const auto* good : {&materials, &direct}) {
    for (const auto& [name, valid] : *good) {
      std::vector<std::string> bad_values = {"-1", "abc", "nan", "inf", ""};
      if (name != "damping") bad_values.push_back("0");
      if (name == "plate-poisson" || name == "sphere-poisson") bad_values = {"0.5", "-1", "x"};
      for (const auto& bad : bad_values) {
        auto options = *good;
        options[name] = bad;
        expect_rejected(options, name, "--" + name + " " + bad);
      }
      if (name == "damping" || name == "exponent") continue; // optional
      auto without = *good;
      without.erase(name);
      expect_rejected(without, name, "missing --" + name);
    }
  }
  auto both = direct;
  both["sphere-modulus"] = "2e11";
  expect_rejected(both, "sphere-modulus", "--stiffness and --sphere-modulus");
  both = direct;
  both["sphere-density"] = "7800";
  expect_rejected(both, "sphere-density", "--mass and --sphere-density");
  auto options = direct;
  options["tolerance"] = "1e-20";
  expect_rejected(options, "tolerance", "--tolerance 1e-20");
  options = direct;
  options["colour"] = "red";
  expect_rejected(options, "colour", "unknown option");
}

} // namespace
