#pragma once
// The subcommands of impact-reduced. Each declares its options (command_line.hpp), from
// which both its parsing and its usage (--help) come; `run` reads them from the command
// line, prints the result to `out` and returns the exit code.

#include "command_line.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace impact::cli {

struct Command {
  std::string name;
  std::string summary;     ///< one line in the list of commands
  std::string description; ///< the paragraph at the top of its usage
  std::vector<Option> options;
  std::string notes; ///< after the options: which options go together, the output
  int (*run)(CommandLine& options, std::ostream& out);
};

/// The usage of one command (impact-reduced COMMAND --help).
std::string usage_of(const Command& command);

Command hc_command();
Command damping_command();
Command law_command();
Command oscillator_command();
Command thin_plate_command();
Command plastic_command();

} // namespace impact::cli
