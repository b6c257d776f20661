// impact-reduced law: JSON output for valid input; exit code 2 and a message naming the
// parameter for every kind of bad input.

#include "cli_runner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace {

struct Run {
  int status;
  std::string output; // stderr, then stdout
};

// `arguments` is a shell-quoted argument string.
Run run_cli(const std::string& arguments) {
  const auto run = impact::testing::run_cli("law " + arguments, {});
  return {run.exit_code, run.err + run.out};
}

struct Option {
  std::string name;
  std::string valid;
};

const std::vector<Option> options = {
    {"model", "flores"}, {"restitution", "0.7"},     {"velocity", "1.5"},
    {"mass", "0.1"},     {"stiffness", "1.7135e10"}, {"exponent", "1.5"},
};

std::string arguments_with(const std::string& name, const std::string& value, bool omit = false) {
  std::string arguments;
  for (const auto& option : options) {
    if (option.name == name && omit) continue;
    arguments += " --" + option.name + " '" + (option.name == name ? value : option.valid) + "'";
  }
  return arguments;
}

TEST(LawCli, ValidCallPrintsTheJsonKeys) {
  const auto run = run_cli(arguments_with("", ""));
  ASSERT_EQ(run.status, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output);
  for (const char* key : {"model", "restitution", "velocity", "mass", "stiffness", "exponent",
                          "damping", "restitution_produced", "restitution_error",
                          "force_at_separation", "contact_time", "force_max", "approach_max"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["model"], "flores");
  EXPECT_NEAR(json["damping"].get<double>(), 8 * 0.3 / (5 * 0.7 * 1.5), 1e-15);
  EXPECT_NEAR(json["restitution_produced"].get<double>(), 0.683184, 1e-6);
  EXPECT_NEAR(json["restitution_error"].get<double>(), 0.683184 / 0.7 - 1, 2e-6);
}

TEST(LawCli, EveryModelRunsAndKelvinVoigtShowsTension) {
  for (const char* model : {"kelvin-voigt", "lankarani-nikravesh", "flores", "gonthier", "hu-guo",
                            "zhiying-qishao", "tsuji", "tsuji-clamped", "kuwabara-kono"}) {
    std::string arguments = " --model " + std::string(model) +
                            " --restitution 0.5 --velocity 1 --mass 0.1 --stiffness 1e9";
    const auto run = run_cli(arguments);
    ASSERT_EQ(run.status, 0) << model << ": " << run.output;
    const auto json = nlohmann::json::parse(run.output);
    if (std::string(model) == "kelvin-voigt") {
      EXPECT_EQ(json["exponent"].get<double>(), 1.0); // its default
      EXPECT_LT(json["force_at_separation"].get<double>(), 0.0);
    } else {
      EXPECT_EQ(json["exponent"].get<double>(), 1.5);
    }
  }
}

TEST(LawCli, BadInputExitsWithTwoAndNamesTheParameter) {
  const std::vector<std::string> bad_numbers = {"-1", "0", "abc", "nan", "inf", "1e400"};
  for (const auto& option : options) {
    std::vector<std::string> bad_values = bad_numbers;
    if (option.name == "model") bad_values = {"hertz-mindlin", "0", "FLORES"};
    if (option.name == "restitution") bad_values.push_back("1.5");
    // Missing: required for all but the exponent (which has a default).
    if (option.name != "exponent") {
      const auto run = run_cli(arguments_with(option.name, "", true));
      EXPECT_EQ(run.status, 2) << option.name << " missing: " << run.output;
      EXPECT_NE(run.output.find("--" + option.name), std::string::npos) << run.output;
    }
    for (const auto& value : bad_values) {
      const auto run = run_cli(arguments_with(option.name, value));
      EXPECT_EQ(run.status, 2) << option.name << " = " << value << ": " << run.output;
      EXPECT_NE(run.output.find(option.name), std::string::npos)
          << option.name << " = " << value << ": " << run.output;
      EXPECT_EQ(run.output.find("nan\n"), std::string::npos);
    }
  }
  // An exponent the law is not defined for, and an unknown option.
  auto run = run_cli(
      " --model kelvin-voigt --restitution 0.5 --velocity 1 --mass 0.1 "
      "--stiffness 1e9 --exponent 1.5");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("exponent"), std::string::npos) << run.output;
  run = run_cli(arguments_with("", "") + " --damping 3");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--damping"), std::string::npos) << run.output;
}

} // namespace
