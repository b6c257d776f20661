// impact-export: the calibrated contact of a campaign in the terms of Simbody, MuJoCo and
// LAMMPS. Exit codes: 0 success; 2 bad input (the message names it; nothing is written);
// 1 internal error.

#include "command_line.hpp"

#include "impact_postprocess/fem_run.hpp"
#include "impact_postprocess/simulator_export.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace impact::postprocess;

const std::string program = "impact-export";

const char* usage = R"(usage: impact-export --campaign DIR --calibration FILE --output DIR [options]
       impact-export RUN... --calibration FILE --output DIR [options]

Writes the calibrated contact of a campaign for three simulators, each file with a header
saying which model it carries and that model's errors against the FEM:
  simbody/impact_contact.hpp   Simbody 3.7 HuntCrossleyForce parameters (C++ header)
  mujoco/impact_contact.xml    MuJoCo 2.2.2 MJCF drop model (solref, solimp, timestep)
  lammps/kuwabara_kono.in      LAMMPS fix wall/gran granular input decks
  lammps/tsuji.in
  export.json                  the manifest: parameters, mappings, model predictions

  --campaign DIR / RUN...      the FEM runs of the calibration (for the sphere radius,
                               impact-fem's parameter 'Scenario/Sphere radius')
  --calibration FILE           the JSON of impact-calibrate for these runs (required)
  --output DIR                 the export directory (replaced as a whole; required)
  --reference-velocity V       MuJoCo's reference velocity, one of the campaign's [m/s]
                               (default: the median run, the lower middle one for an even
                               number of runs)
  --quiet                      no progress messages on stderr
  --help                       this text

Exit codes: 0 success, 2 bad input (message names the problem; nothing is written),
1 internal error.
)";

struct Arguments : cli::RunArguments {
  std::optional<fs::path> calibration;
  std::optional<double> reference_velocity;
};

Arguments parse(int argc, char** argv) {
  using cli::UsageError;
  Arguments arguments;
  const auto option = [&](const std::string& argument,
                          const std::function<std::string()>& value) {
    if (argument == "--calibration") {
      arguments.calibration = value();
    } else if (argument == "--reference-velocity") {
      const std::string text = value();
      std::size_t end = 0;
      double velocity = NAN;
      try {
        velocity = std::stod(text, &end);
      } catch (const std::exception&) {
      }
      if (end != text.size() || !(std::isfinite(velocity) && velocity > 0))
        throw UsageError("--reference-velocity must be a positive velocity in m/s (got '" +
                         text + "')");
      arguments.reference_velocity = velocity;
    } else {
      return false;
    }
    return true;
  };
  cli::parse_run_arguments(argc, argv, arguments, "DIR", option);
  if (arguments.help) return arguments;
  if (!arguments.calibration) throw UsageError("--calibration FILE is required");
  const fs::path parent = fs::absolute(*arguments.output).parent_path();
  if (!fs::is_directory(parent))
    throw UsageError("the directory of --output '" + arguments.output->string() +
                     "' does not exist");
  if (fs::exists(*arguments.output) && !fs::is_directory(*arguments.output))
    throw UsageError("--output '" + arguments.output->string() + "' is not a directory");
  return arguments;
}

// The sphere radius that every run records (impact-fem's text parameter).
double sphere_radius(const Campaign& input) {
  const std::string key = "Scenario/Sphere radius";
  std::optional<double> radius;
  for (const auto& run : input.runs) {
    const auto found = run.text_attributes.find(key);
    if (found == run.text_attributes.end())
      throw ExportInputError(run.source + ": the run does not record the sphere radius "
                             "(text attribute '" + key + "')");
    double value = NAN;
    try {
      value = std::stod(found->second);
    } catch (const std::exception&) {
    }
    if (!(std::isfinite(value) && value > 0))
      throw ExportInputError(run.source + ": '" + key + "' = '" + found->second +
                             "' is not a positive length in m");
    if (radius && std::abs(value / *radius - 1) > 1e-12)
      throw ExportInputError(run.source + ": sphere radius " + found->second +
                             " m differs from the other runs' " + std::to_string(*radius) +
                             " m: one sphere per export");
    radius = value;
  }
  return *radius;
}

int execute(const Arguments& arguments) {
  const Campaign input = cli::read_input(arguments);
  for (const auto& problem : input.problems)
    std::cerr << program << ": error: " << problem.message << '\n';
  if (!input.problems.empty() || input.runs.empty()) {
    std::cerr << program << ": error: every run of the calibration must be readable; "
                            "nothing was written\n";
    return 2;
  }
  try {
    std::ifstream file(*arguments.calibration);
    if (!file)
      throw ExportInputError(arguments.calibration->string() + ": cannot open the calibration");
    nlohmann::json calibration;
    try {
      calibration = nlohmann::json::parse(file);
    } catch (const nlohmann::json::exception& error) {
      throw ExportInputError(arguments.calibration->string() + ": not valid JSON (" +
                             error.what() + ")");
    }
    const ExportCampaign campaign = read_export_campaign(
        calibration, arguments.calibration->string(), sphere_radius(input));
    if (campaign.runs.size() != input.runs.size())
      throw ExportInputError(arguments.calibration->string() + ": the calibration has " +
                             std::to_string(campaign.runs.size()) + " runs, the input " +
                             std::to_string(input.runs.size()) + ": not the same campaign");
    const auto manifest =
        write_exports(campaign, arguments.reference_velocity, *arguments.output);
    if (!arguments.quiet)
      for (const auto& entry : manifest.at("exports"))
        std::cerr << program << ": " << entry.at("tool").get<std::string>() << " ("
                  << entry.at("model").get<std::string>() << "): "
                  << (*arguments.output / entry.at("file").get<std::string>()).string() << '\n';
    std::cout << "export written to " << arguments.output->string() << '\n';
  } catch (const ExportInputError& error) {
    std::cerr << program << ": error: " << error.what() << "; nothing was written\n";
    return 2;
  }
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  return cli::run_command(program, usage, argc, argv, parse, execute);
}
