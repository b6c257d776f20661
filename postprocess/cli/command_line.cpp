#include "command_line.hpp"

namespace impact::postprocess::cli {

void parse_run_arguments(int argc, char** argv, RunArguments& arguments,
                         const std::string& output_name, const OptionHandler& option) {
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const std::function<std::string()> value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError("the option " + argument + " needs a value");
      return argv[++i];
    };
    if (argument == "--help" || argument == "-h") arguments.help = true;
    else if (argument == "--quiet") arguments.quiet = true;
    else if (argument == "--output") arguments.output = value();
    else if (argument == "--campaign") {
      if (arguments.campaign) throw UsageError("--campaign is given twice");
      arguments.campaign = value();
    }
    else if (option(argument, value)) continue;
    else if (argument.rfind("--", 0) == 0) throw UsageError("unknown option '" + argument + "'");
    else arguments.runs.emplace_back(argument);
  }
  if (arguments.help) return;
  if (!arguments.output) throw UsageError("--output " + output_name + " is required");
  if (arguments.campaign && !arguments.runs.empty())
    throw UsageError("give either run files or --campaign DIR, not both");
  if (!arguments.campaign && arguments.runs.empty())
    throw UsageError("no input: give run files or --campaign DIR");
}

Campaign read_input(const RunArguments& arguments) {
  if (!arguments.campaign) return read_runs(arguments.runs);
  Campaign input;
  try {
    input = read_campaign(*arguments.campaign);
  } catch (const RunInputError& error) {
    input.problems.push_back({arguments.campaign->string(), error.what()});
  }
  return input;
}

} // namespace impact::postprocess::cli
