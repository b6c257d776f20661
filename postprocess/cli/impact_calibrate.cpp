// impact-calibrate: Hunt–Crossley (and comparison-law) parameters from FEM impact runs. The
// options are parsed here; the calibration is made by write_calibration
// (impact_postprocess/calibration/calibrate_run_set.hpp).
// Exit codes: 0 success; 2 bad input (the message names the problem; the JSON lists what is
// missing; with no usable run nothing is written); 3 a fit did not converge; 1 internal error.

#include "tool.hpp"

#include "impact_postprocess/calibration/calibrate_run_set.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace impact::postprocess;

const std::string program = "impact-calibrate";

const char* usage = R"(usage: impact-calibrate RUN... --output FILE [options]
       impact-calibrate --campaign DIR --output FILE [options]

Calibrates the Hunt-Crossley contact law F = c x^n (1 + b dx/dt) (and the comparison laws
of the reduced library) from impact-fem runs and writes the result as JSON.

  RUN                  a run directory of impact-fem (holding history.h5 and summary.json)
                       or its HDF5 file
  --campaign DIR       all runs of a campaign: those listed in DIR/index.json, else
                       every subdirectory holding history.h5
  --output FILE        the calibration JSON to write (required)
  --laws LIST          comparison laws fitted over the campaign: comma-separated names,
                       'all' (default) or 'none'
  --max-iterations N   iteration limit of each least-squares fit (default 100)
  --confidence LEVEL   level of the confidence intervals, in (0, 1) (default 0.95)
  --energy-weight W    weight of the energy-loss residuals of the combined fits, >= 0
                       (default 1: a 1 % error in 1 - e^2 costs as much as a 1 % RMS force
                       residual; 0 fits the force histories only)
  --published-damping B  b [s/m] of the published Hunt-Crossley reference model (c from
                       Hertz, n = 3/2), >= 0 (default 0.1, the published steel example)
  --damped-stiffness hertz|fitted
                       c of the damped elastic-plastic laws (hunt-crossley-thornton, ...):
                       held at the Hertz value of the runs' materials (default; fitted when
                       the runs do not record them) or fitted
  --quiet              no progress messages on stderr
  --help               this text

Exit codes: 0 success, 2 bad input (message names the problem; the JSON says what is
missing; with no usable run nothing is written), 3 a fit did not converge (see "problems"
in the JSON), 1 internal error.
)";

// The comparison laws of --laws: 'all', 'none' or comma-separated names of the library's.
std::vector<std::string> laws(tool::CommandLine& line) {
  const auto known = impact::postprocess::comparison_model_names();
  const std::string list = line.text("laws").value_or("all");
  if (list == "all") return known;
  if (list == "none") return {};
  std::vector<std::string> chosen;
  std::stringstream stream(list);
  std::string law;
  while (std::getline(stream, law, ','))
    if (!law.empty()) chosen.push_back(law);
  for (const auto& law : chosen)
    if (std::find(known.begin(), known.end(), law) == known.end()) {
      std::string names;
      for (const auto& name : known) names += (names.empty() ? "" : ", ") + name;
      throw tool::UsageError("--laws: unknown law '" + law + "' (known: " + names + ", or all, none)");
    }
  return chosen;
}

CalibrationRequest parse(tool::CommandLine& line) {
  const tool::RunArguments common = tool::run_arguments(line, "FILE");
  CalibrationRequest request{common.runs, common.campaign, common.output, {}};
  CalibrationOptions& options = request.options;
  options.laws = laws(line);
  options.max_iterations = int(line.integer("max-iterations", 1, 100000, options.max_iterations));
  options.confidence_level =
      line.real("confidence", tool::Range::open(0, 1), options.confidence_level);
  options.energy_weight = line.real("energy-weight", tool::Range::closed(0, 1e6), options.energy_weight);
  options.published_damping =
      line.real("published-damping", tool::Range::closed(0, 1e3), options.published_damping);
  const std::string stiffness = line.text("damped-stiffness").value_or("hertz");
  if (stiffness != "hertz" && stiffness != "fitted")
    throw tool::UsageError("--damped-stiffness: must be hertz or fitted, got '" + stiffness + "'");
  options.damped_plastic_hertz_stiffness = stiffness == "hertz";
  if (!common.quiet)
    options.progress = [](const std::string& text) {
      std::cerr << program << ": " << text << std::endl;
    };
  tool::require_output_directory(request.output);
  if (fs::is_directory(request.output))
    throw tool::UsageError("--output '" + request.output.string() + "' is a directory");
  return request;
}

int execute(const CalibrationRequest& request) {
  const CalibrationOutcome outcome = write_calibration(request);
  for (const auto& problem : outcome.calibration.problems) tool::print_problem(program, problem);
  if (!outcome.written) {
    std::cerr << program << ": error: nothing was written\n";
    return outcome.exit_code;
  }
  std::cout << calibration_summary(outcome.calibration) << "calibration written to "
            << request.output.string() << '\n';
  return outcome.exit_code;
}

} // namespace

int main(int argc, char** argv) { return tool::run(program, usage, argc, argv, parse, execute); }
