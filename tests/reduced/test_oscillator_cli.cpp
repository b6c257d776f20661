// Tests of `impact-reduced oscillator`: the CSV tables, and exit code 2 with a message naming
// the parameter for every kind of bad input.

#include "cli_runner.hpp"
#include "impact_reduced/oscillator.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace reduced = impact::reduced;

using impact::testing::arguments_of;
using impact::testing::CliRun;

CliRun run_cli(const std::vector<std::string>& arguments) {
  return impact::testing::run_cli("oscillator", arguments);
}

// The published quadratic case.
const std::map<std::string, std::string> good = {{"mass", "2"},   {"viscous", "8"},
                                                 {"c1", "800"},   {"c2", "4000"},
                                                 {"power", "1"},  {"a0", "0.05"},
                                                 {"count", "10"}, {"method", "numeric"}};

std::vector<std::vector<double>> parse_csv(const std::string& text, std::string& header) {
  std::stringstream lines(text);
  std::getline(lines, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(OscillatorCli, NumericTableMatchesLibrary) {
  const CliRun run = run_cli(arguments_of(good));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  std::string header;
  const auto rows = parse_csv(run.out, header);
  EXPECT_EQ(header, "i,time,amplitude");
  const auto extremes = reduced::free_decay_extremes({2, 8, 800, 4000, 1, 0.05}, 10);
  ASSERT_EQ(rows.size(), extremes.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 3u);
    EXPECT_EQ(rows[i][0], static_cast<double>(i + 1));
    EXPECT_EQ(rows[i][1], extremes[i].time); // 17 digits: exact round trip
    EXPECT_EQ(rows[i][2], extremes[i].amplitude);
  }
}

TEST(OscillatorCli, ApproximationTablesMatchLibrary) {
  for (const std::string method : {"implicit", "lambert", "lambert-approx"}) {
    auto options = good;
    options["method"] = method;
    options["format"] = "csv";
    const CliRun run = run_cli(arguments_of(options));
    ASSERT_EQ(run.exit_code, 0) << method << ": " << run.err;
    std::string header;
    const auto rows = parse_csv(run.out, header);
    EXPECT_EQ(header, "i,amplitude") << method;
    const auto amplitudes =
        reduced::free_decay_amplitudes({2, 8, 800, 4000, 1, 0.05}, 10,
                                       reduced::amplitude_method_from_name(method));
    ASSERT_EQ(rows.size(), amplitudes.size()) << method;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_EQ(rows[i].at(0), static_cast<double>(i + 1)) << method;
      EXPECT_EQ(rows[i].at(1), amplitudes[i]) << method;
    }
  }
}

// Every option: missing, and each bad value; exit code 2, the message names the option,
// nothing on stdout.
TEST(OscillatorCli, BadInputExitsWithTwoAndNamesTheParameter) {
  const std::vector<std::string> non_numbers = {"abc",  "nan",   "NaN", "inf",
                                                "-inf", "1e400", "",    "3x"};
  std::map<std::string, std::vector<std::string>> bad;
  for (const auto& [name, value] : good)
    if (name != "method") bad[name] = non_numbers;
  for (const std::string name : {"mass", "c1", "a0"}) { // > 0
    bad[name].push_back("0");
    bad[name].push_back("-1");
  }
  for (const std::string name : {"viscous", "power"}) bad[name].push_back("-1"); // >= 0
  bad["viscous"].push_back("80");  // critical damping 2 sqrt(c1 m) = 80
  bad["viscous"].push_back("1e3"); // overdamped
  bad["count"] = {"0", "-1", "10001", "1.5", "abc", "nan", "inf", ""};
  bad["method"] = {"exact", "", "NUMERIC"};

  int runs = 0;
  for (const auto& [name, values] : bad) {
    auto without = good;
    without.erase(name);
    CliRun run = run_cli(arguments_of(without));
    EXPECT_EQ(run.exit_code, 2) << "missing --" << name;
    EXPECT_NE(run.err.find("--" + name), std::string::npos)
        << "missing " << name << ": " << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    for (const auto& value : values) {
      auto options = good;
      options[name] = value;
      run = run_cli(arguments_of(options));
      ++runs;
      EXPECT_EQ(run.exit_code, 2) << "--" << name << " '" << value << "'";
      EXPECT_NE(run.err.find(name), std::string::npos)
          << "--" << name << " '" << value << "': " << run.err;
      EXPECT_TRUE(run.out.empty()) << "--" << name << " '" << value << "': " << run.out;
    }
  }
  EXPECT_GT(runs, 60);
}

// Inputs that every option accepts alone but that are invalid together, or invalid for one
// method only: the message names the parameter responsible.
TEST(OscillatorCli, InconsistentInputExitsWithTwo) {
  struct Case {
    std::map<std::string, std::string> changes;
    std::string named;
  };
  const std::vector<Case> cases = {
      {{{"c2", "-20000"}}, "a0"},                              // beyond the softening barrier
      {{{"power", "0"}, {"c2", "-800"}}, "c2"},                // linear stiffness c1 + c2 = 0
      {{{"c2", "1e6"}, {"method", "lambert"}}, "a0"},          // W0 argument below -1/e
      {{{"c2", "29000"}, {"method", "lambert-approx"}}, "a0"}, // outside [-0.2, 0.3]
      {{{"c2", "-15000"}, {"viscous", "56"}, {"method", "implicit"}}, "a0"},
      {{{"unknown", "1"}}, "--unknown"},
  };
  for (const auto& c : cases) {
    auto options = good;
    for (const auto& [name, value] : c.changes) options[name] = value;
    const CliRun run = run_cli(arguments_of(options));
    EXPECT_EQ(run.exit_code, 2) << c.named << ": " << run.err;
    EXPECT_NE(run.err.find(c.named), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

} // namespace
