#pragma once
// Runs the impact-reduced tool as a user would, for the CLI tests: separate stdout and
// stderr, and the exit code. IMPACT_REDUCED_CLI is the tool's path (set by CMake).

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

namespace impact::testing {

struct CliRun {
  int exit_code;
  std::string out;
  std::string err;
};

inline std::string read_file(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// `impact-reduced COMMAND ARGUMENTS...`, each argument passed as one shell word.
inline CliRun run_cli(const std::string& command_name, const std::vector<std::string>& arguments) {
  const std::string base = "/tmp/impact_reduced_cli_" + std::to_string(::getpid());
  std::string command = std::string("'") + IMPACT_REDUCED_CLI + "' " + command_name;
  for (const auto& argument : arguments) command += " '" + argument + "'";
  command += " >" + base + ".out 2>" + base + ".err";
  const int status = std::system(command.c_str());
  CliRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(base + ".out"),
             read_file(base + ".err")};
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return run;
}

/// `--name value` pairs of an option map, in the map's order.
inline std::vector<std::string> arguments_of(const std::map<std::string, std::string>& options) {
  std::vector<std::string> arguments;
  for (const auto& [name, value] : options) {
    arguments.push_back("--" + name);
    arguments.push_back(value);
  }
  return arguments;
}

/// Expects `impact-reduced COMMAND` with these options refused as a user error: exit code 2,
/// the option `--parameter` named on stderr, nothing on stdout. `what` labels the failure.
inline void expect_rejected(const std::string& command,
                            const std::map<std::string, std::string>& options,
                            const std::string& parameter, const std::string& what) {
  const auto run = run_cli(command, arguments_of(options));
  EXPECT_EQ(run.exit_code, 2) << what << ": " << run.out << run.err;
  EXPECT_NE(run.err.find("--" + parameter), std::string::npos) << what << ": " << run.err;
  EXPECT_TRUE(run.out.empty()) << what << ": partial output " << run.out;
}

} // namespace impact::testing
