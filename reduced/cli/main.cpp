// impact-reduced: command-line front end of the reduced impact library.
// Exit codes: 0 success, 2 bad input (message on stderr names the parameter), 1 internal error.

#include "commands.hpp"
#include "impact_reduced/invalid_input.hpp"

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace impact::cli {

namespace {

const char* units_and_exit_codes =
    "Units are SI. Output is JSON, or CSV where it is a table (--format csv).\n"
    "Exit codes: 0 success, 2 bad input (the message names the option and its allowed "
    "values), 1 internal error.\n";

std::vector<Command> all_commands() {
  return {hc_command(),         damping_command(),    law_command(),
          oscillator_command(), thin_plate_command(), plastic_command()};
}

std::string usage_of_tool(const std::vector<Command>& commands) {
  std::string usage =
      "usage: impact-reduced COMMAND [--option value ...]\n"
      "       impact-reduced COMMAND --help   (the options of COMMAND)\n\n"
      "commands:\n";
  for (const auto& command : commands) {
    const std::string name = "  " + command.name;
    usage += name + wrapped_text(command.summary, 14).substr(name.size());
  }
  return usage + '\n' + units_and_exit_codes;
}

} // namespace

std::string usage_of(const Command& command) {
  std::string usage = "usage: impact-reduced " + command.name + " [--option value ...]\n\n";
  usage += wrapped_text(command.description) + "\noptions:\n" + usage_of_options(command.options);
  if (!command.notes.empty()) usage += '\n' + wrapped_text(command.notes);
  return usage + '\n' + units_and_exit_codes;
}

} // namespace impact::cli

int main(int argc, char** argv) {
  using namespace impact::cli;
  const std::vector<Command> commands = all_commands();
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.empty() || arguments[0] == "--help" || arguments[0] == "-h") {
    (arguments.empty() ? std::cerr : std::cout) << usage_of_tool(commands);
    return arguments.empty() ? 2 : 0;
  }
  const std::string& name = arguments[0];
  const Command* command = nullptr;
  for (const auto& candidate : commands)
    if (candidate.name == name) command = &candidate;
  if (!command) {
    std::cerr << "impact-reduced: unknown command '" << name << "'\n\n" << usage_of_tool(commands);
    return 2;
  }
  const std::vector<std::string> options(arguments.begin() + 1, arguments.end());
  if (asks_for_help(options)) {
    std::cout << usage_of(*command);
    return 0;
  }
  try {
    CommandLine line(name, options, command->options);
    return command->run(line, std::cout);
  } catch (const UsageError& error) {
    std::cerr << "impact-reduced " << name << ": error: " << error.what() << '\n';
    return 2;
  } catch (const impact::reduced::InvalidInput& error) {
    // The library names its parameter as the options do (mass, velocity, a0, ...).
    const std::string option = "--" + error.parameter();
    const bool named =
        command->options.end() != std::find_if(command->options.begin(), command->options.end(),
                                               [&](const Option& declared) {
                                                 return declared.kind != Option::Kind::heading &&
                                                        declared.name == error.parameter();
                                               }) &&
        std::string(error.what()).find(option) == std::string::npos;
    std::cerr << "impact-reduced " << name << ": error: " << (named ? option + ": " : "")
              << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "impact-reduced " << name << ": internal error: " << error.what() << '\n';
    return 1;
  }
}
