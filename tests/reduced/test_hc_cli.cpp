// impact-reduced hc and damping: the JSON and CSV outputs, and exit code 2 with a message
// naming the parameter for every kind of bad input.

#include "cli_runner.hpp"

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

TEST(Cli, UnknownCommandExitsWithTwo) {
  const auto run = run_cli("bounce", {});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown command"), std::string::npos);
}

} // namespace
