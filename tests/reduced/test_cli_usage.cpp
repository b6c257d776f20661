// impact-reduced --help and COMMAND --help: the usage on stdout and exit 0, whatever else is on
// the command line (missing or bad options included); every option the usage lists is one the
// command parses (none is refused as unknown).

#include "cli_runner.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

namespace {

using impact::testing::run_cli;

const std::vector<std::string> commands = {"hc",         "damping",    "law",
                                           "oscillator", "thin-plate", "plastic"};

std::vector<std::string> options_in(const std::string& usage) {
  std::vector<std::string> names;
  const std::regex option(R"(\n  --([a-z0-9-]+))");
  for (std::sregex_iterator match(usage.begin(), usage.end(), option), end; match != end; ++match)
    names.push_back((*match)[1]);
  return names;
}

TEST(CliUsage, ToolUsageListsEveryCommand) {
  for (const std::string help : {"--help", "-h"}) {
    const auto run = run_cli(help, {});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    for (const auto& command : commands)
      EXPECT_NE(run.out.find("\n  " + command + " "), std::string::npos) << command;
  }
  const auto bare = run_cli("", {});
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("usage: impact-reduced"), std::string::npos);
}

TEST(CliUsage, EveryCommandPrintsItsUsageEvenWithoutItsOptions) {
  for (const auto& command : commands)
    for (const std::vector<std::string>& arguments :
         std::vector<std::vector<std::string>>{{"--help"},
                                               {"-h"},
                                               {"--mass", "-1", "--help"},
                                               {"--model", "nonsense", "-h", "--colour", "red"}}) {
      const auto run = run_cli(command, arguments);
      EXPECT_EQ(run.exit_code, 0) << command << ": " << run.err;
      EXPECT_TRUE(run.err.empty()) << command << ": " << run.err;
      EXPECT_EQ(run.out.rfind("usage: impact-reduced " + command + " ", 0), 0u) << run.out;
      EXPECT_NE(run.out.find("Exit codes:"), std::string::npos) << run.out;
    }
}

// The issue's case: plastic --help answered "error: --model is required".
TEST(CliUsage, PlasticHelpDescribesItsOptions) {
  const auto run = run_cli("plastic", {"--help"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* text : {"--model thornton|jackson-green", "--yield-strength Y", "--flat rigid",
                           "(default johnson)", "[Pa]", "--velocity V[,V...]"})
    EXPECT_NE(run.out.find(text), std::string::npos) << text;
}

TEST(CliUsage, EveryListedOptionIsParsed) {
  for (const auto& command : commands) {
    const auto usage = run_cli(command, {"--help"});
    const auto names = options_in(usage.out);
    EXPECT_GE(names.size(), 2u) << command;
    for (const auto& name : names) {
      const auto run = run_cli(command, {"--" + name, "@"});
      EXPECT_EQ(run.exit_code, 2) << command << " --" << name;
      EXPECT_EQ(run.err.find("unknown option"), std::string::npos)
          << command << " --" << name << ": " << run.err;
    }
  }
}

TEST(CliUsage, HelpStatesTheRangesThatAreEnforced) {
  // The range in the usage is the one in the message of a value outside it.
  const auto usage = run_cli("hc", {"--help"});
  const std::regex velocity(R"(--velocity V +impact velocity \[m/s\]\n +\((a number in [^;)]*))");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(usage.out, match, velocity)) << usage.out;
  const auto run = run_cli("hc", {"--mass", "0.1", "--stiffness", "1e10", "--damping", "0",
                                  "--velocity", "1e5"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--velocity must be " + match[1].str() + " (got '1e5')"),
            std::string::npos)
      << run.err << " / " << match[1];
}

} // namespace
