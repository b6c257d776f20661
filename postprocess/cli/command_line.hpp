#pragma once
// The command-line handling shared by impact-calibrate, impact-export and impact-report: they take run
// files or a campaign directory and an output, report usage errors and failures in the
// same words and with the same exit codes.

#include "impact_postprocess/fem_run.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::postprocess::cli {

/// A command line that cannot be used; reported with a pointer to --help, exit code 2.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The arguments both executables take.
struct RunArguments {
  std::vector<std::filesystem::path> runs;
  std::optional<std::filesystem::path> campaign;
  std::optional<std::filesystem::path> output;
  bool quiet = false;
  bool help = false;
};

/// Handles an option of one executable: `value` gives the option's value (UsageError when
/// there is none). Returns false for an option it does not know.
using OptionHandler =
    std::function<bool(const std::string& option, const std::function<std::string()>& value)>;

/// Parses the command line into `arguments`: --help, -h, --quiet, --output, --campaign (once)
/// and the run operands here, every other option by `option`. Unless --help is given, requires an
/// output (named `output_name` in the message, "FILE" or "DIR") and either runs or a
/// campaign. Throws UsageError.
void parse_run_arguments(int argc, char** argv, RunArguments& arguments,
                         const std::string& output_name, const OptionHandler& option);

/// The runs named on the command line: those of the campaign, or the run files. A campaign
/// that cannot be read is an input problem, like a run that cannot be read.
Campaign read_input(const RunArguments& arguments);

/// Prints a problem (of a calibration or a report) as "program: error|warning: source: message".
template <class Problem>
void print_problem(const std::string& program, const Problem& problem) {
  std::cerr << program << ": " << (problem.kind == "input" ? "error" : "warning") << ": "
            << (problem.source.empty() ? "" : problem.source + ": ") << problem.message << '\n';
}

/// The frame of an executable's main: parses the command line with `parse`, prints `usage`
/// for --help, else returns what `execute` returns. Exit code 2 for a usage error or invalid
/// input, 1 for any other failure of `execute`.
template <class Arguments>
int run_command(const std::string& program, const char* usage, int argc, char** argv,
                Arguments (*parse)(int, char**), int (*execute)(const Arguments&)) {
  Arguments arguments;
  try {
    arguments = parse(argc, argv);
  } catch (const UsageError& error) {
    std::cerr << program << ": error: " << error.what() << "\n(" << program
              << " --help for the usage)\n";
    return 2;
  }
  if (arguments.help) {
    std::cout << usage;
    return 0;
  }
  try {
    return execute(arguments);
  } catch (const impact::reduced::InvalidInput& error) {
    std::cerr << program << ": error: " << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << program << ": internal error: " << error.what() << '\n';
    return 1;
  }
}

} // namespace impact::postprocess::cli
