#pragma once
// The subcommands of impact-reduced. Each reads its options from the command line,
// prints its result to `out` and returns the exit code.

#include "command_line.hpp"

#include <ostream>

namespace impact::cli {

int run_hc_command(CommandLine& options, std::ostream& out);
int run_damping_command(CommandLine& options, std::ostream& out);
int run_law_command(CommandLine& options, std::ostream& out);
int run_oscillator_command(CommandLine& options, std::ostream& out);
int run_thin_plate_command(CommandLine& options, std::ostream& out);
int run_plastic_command(CommandLine& options, std::ostream& out);

} // namespace impact::cli
