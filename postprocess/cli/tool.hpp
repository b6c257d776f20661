#pragma once
// What impact-calibrate, impact-export and impact-report share: they take run files or a
// campaign directory and an output, parse their options with the project's command-line
// framework (command_line.hpp: ranges checked, unknown options refused), and report usage
// errors and failures in the same words and with the same exit codes.

#include "command_line.hpp"

#include "impact_postprocess/problem.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess::tool {

using impact::cli::CommandLine;
using impact::cli::Option;
using impact::cli::Range;
using impact::cli::UsageError;

/// The options every tool takes.
struct RunArguments {
  std::vector<std::filesystem::path> runs;
  std::optional<std::filesystem::path> campaign;
  std::filesystem::path output;
  bool quiet = false;
};

/// What a tool's --help prints: `synopsis` (the usage lines and what the tool does), then the
/// options from their declarations (those that parse the command line), then `epilogue`.
struct Usage {
  std::string synopsis;
  std::vector<Option> options;
  std::string epilogue;
};

inline std::string usage_text(const Usage& usage) {
  return usage.synopsis + "\n" + impact::cli::usage_of_options(usage.options) +
         "  --help, -h            this text\n\n" + usage.epilogue;
}

/// The declarations of the options of run_arguments: --campaign, --output (`output_help`,
/// its value named `output_name`, "FILE" or "DIR") and --quiet.
inline std::vector<Option> run_options(const std::string& output_name,
                                       const std::string& output_help) {
  return {impact::cli::text_option("campaign", "DIR",
                                   "all runs of a campaign: those listed in DIR/index.json, "
                                   "else every subdirectory holding history.h5 (instead of "
                                   "RUN...)"),
          impact::cli::text_option("output", output_name, output_help + "; required"),
          impact::cli::flag_option("quiet", "no progress messages on stderr")};
}

/// The command line of a tool: the flag --quiet, run operands, the declared options.
inline CommandLine command_line(const std::string& program, int argc, char** argv,
                                const std::vector<Option>& options) {
  return CommandLine(program, std::vector<std::string>(argv + 1, argv + argc), options, true);
}

/// Takes --quiet, --output, --campaign and the run operands; requires an output (named
/// `output_name` in the message, "FILE" or "DIR") and either runs or a campaign.
inline RunArguments run_arguments(CommandLine& line, const std::string& output_name) {
  RunArguments arguments;
  arguments.quiet = line.flag("quiet");
  const auto output = line.text("output");
  if (!output) throw UsageError("--output " + output_name + " is required");
  arguments.output = *output;
  if (const auto campaign = line.text("campaign")) arguments.campaign = *campaign;
  for (const auto& run : line.operands()) arguments.runs.emplace_back(run);
  if (arguments.campaign && !arguments.runs.empty())
    throw UsageError("give either run files or --campaign DIR, not both");
  if (!arguments.campaign && arguments.runs.empty())
    throw UsageError("no input: give run files or --campaign DIR");
  return arguments;
}

/// The directory in which --output is to be written must exist.
inline void require_output_directory(const std::filesystem::path& output) {
  if (!std::filesystem::is_directory(std::filesystem::absolute(output).parent_path()))
    throw UsageError("the directory of --output '" + output.string() + "' does not exist");
}

/// Prints a problem as "program: error|warning: source: message".
inline void print_problem(const std::string& program, const Problem& problem) {
  std::cerr << program << ": " << (problem.kind == ProblemKind::input ? "error" : "warning") << ": "
            << (problem.source.empty() ? "" : problem.source + ": ") << problem.message << '\n';
}

/// The frame of a tool's main: its usage for --help or -h (wherever they stand); else `parse`
/// reads the command line (then every option must have been used) and `execute` returns the
/// exit code. Exit code 2 for a usage error or invalid input, 1 for any other failure.
template <class Arguments>
int run(const std::string& program, const Usage& usage, int argc, char** argv,
        Arguments (*parse)(CommandLine&), int (*execute)(const Arguments&)) {
  if (impact::cli::asks_for_help(std::vector<std::string>(argv + 1, argv + argc))) {
    std::cout << usage_text(usage);
    return 0;
  }
  Arguments arguments;
  try {
    CommandLine line = command_line(program, argc, argv, usage.options);
    arguments = parse(line);
    line.finish();
  } catch (const UsageError& error) {
    std::cerr << program << ": error: " << error.what() << "\n(" << program
              << " --help for the usage)\n";
    return 2;
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

} // namespace impact::postprocess::tool
