// impact-export: the calibrated contact of a campaign in the terms of Simbody, MuJoCo,
// LAMMPS and (for an elastic-plastic campaign) LIGGGHTS. The options are parsed here; the export is made by export_run_set
// (impact_postprocess/export/export_run_set.hpp).
// Exit codes: 0 success; 2 bad input (the message names it; nothing is written);
// 1 internal error.

#include "tool.hpp"

#include "impact_postprocess/export/export_run_set.hpp"

#include <filesystem>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace impact::postprocess;

const std::string program = "impact-export";

tool::Usage usage() {
  using namespace impact::cli;
  std::vector<Option> options =
      tool::run_options("DIR", "the export directory (replaced as a whole)");
  options.insert(options.begin(),
                 text_option("calibration", "FILE",
                             "the JSON of impact-calibrate for these runs (required)"));
  options.push_back(real_option("reference-velocity", "V", Range::positive(),
                                "MuJoCo's reference velocity [m/s], one of the campaign's")
                        .with_default_note("the median run, the lower middle one for an even "
                                           "number of runs"));
  options.push_back(text_option("law", "KEY",
                                "the damped elastic-plastic law of the restitution table "
                                "(a key of the calibration's ranking, e.g. "
                                "hunt-crossley-jackson-green-from-a)")
                        .with_default_note("the first-ranked one; no table without one"));
  options.push_back(integer_option("table-points", "N", 2, 1000,
                                   "log-spaced velocities of the restitution table over the "
                                   "campaign's range, besides the FEM's own")
                        .with_default_note("25"));
  return {R"(usage: impact-export --campaign DIR --calibration FILE --output DIR [options]
       impact-export RUN... --calibration FILE --output DIR [options]

Writes the calibrated contact of a campaign for four simulators, each file with a header
saying which model it carries and that model's errors against the FEM:
  simbody/impact_contact.hpp   Simbody 3.7 HuntCrossleyForce parameters (C++ header)
  mujoco/impact_contact.xml    MuJoCo 2.2.2 MJCF drop model (solref, solimp, timestep)
  lammps/kuwabara_kono.in      LAMMPS fix wall/gran granular input decks
  lammps/tsuji.in
  liggghts/thornton_ning.in    LIGGGHTS 3.8.0 normal model thornton_ning on a wall
                               (Thornton's law, p_y from the calibration's Thornton
                               fit, else from the runs' yield strength; no file
                               when neither exists)
  restitution/LAW.csv, .json   e(V), t_c(V), F_max(V) of a damped elastic-plastic law
                               with the FEM's uncertainty and the law's error per row
                               (when the calibration has such a law)
  export.json                  the manifest: parameters, mappings, model predictions

  RUN                   the FEM runs of the calibration, instead of --campaign (for the
                        sphere radius, impact-fem's parameter 'Scenario/Sphere radius')
)",
          options,
          R"(Exit codes: 0 success, 2 bad input (message names the problem; nothing is written),
1 internal error.
)"};
}

struct Arguments {
  ExportRequest request;
  bool quiet = false;
};

Arguments parse(tool::CommandLine& line) {
  const tool::RunArguments common = tool::run_arguments(line, "DIR");
  Arguments arguments;
  ExportRequest& request = arguments.request;
  arguments.quiet = common.quiet;
  request.runs = common.runs;
  request.campaign = common.campaign;
  request.output = common.output;
  const auto calibration = line.text("calibration");
  if (line.has("reference-velocity")) request.reference_velocity = line.real("reference-velocity");
  if (const auto law = line.text("law")) request.table_law = *law;
  if (line.has("table-points")) request.table_points = std::size_t(line.integer("table-points"));
  if (!calibration) throw tool::UsageError("--calibration FILE is required");
  request.calibration = *calibration;
  tool::require_output_directory(request.output);
  if (fs::exists(request.output) && !fs::is_directory(request.output))
    throw tool::UsageError("--output '" + request.output.string() + "' is not a directory");
  return arguments;
}

int execute(const Arguments& arguments) {
  const ExportOutcome outcome = export_run_set(arguments.request);
  for (const auto& problem : outcome.problems) tool::print_problem(program, problem);
  if (!outcome.problems.empty()) return exit_code(outcome.problems);
  if (!arguments.quiet)
    for (const auto& entry : outcome.manifest.at("exports"))
      std::cerr << program << ": " << entry.at("tool").get<std::string>() << " ("
                << entry.at("model").get<std::string>() << "): "
                << (arguments.request.output / entry.at("file").get<std::string>()).string()
                << '\n';
  std::cout << "export written to " << arguments.request.output.string() << '\n';
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  return tool::run(program, usage(), argc, argv, parse, execute);
}
