// impact-calibrate: Hunt–Crossley (and comparison-law) parameters from FEM impact runs. The
// options are parsed here; the calibration is made by write_calibration
// (impact_postprocess/calibration/calibrate_run_set.hpp).
// Exit codes: 0 success; 2 bad input (the message names the problem; the JSON lists what is
// missing; with no usable run nothing is written); 3 a fit did not converge; 1 internal error.

#include "tool.hpp"

#include "impact_postprocess/calibration/calibrate_run_set.hpp"

#include <impact_fem/as_written.h>

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

// The names of the comparison laws, comma-separated.
std::string law_names() {
  std::string names;
  for (const auto& name : impact::postprocess::comparison_model_names())
    names += (names.empty() ? "" : ", ") + name;
  return names;
}

tool::Usage usage() {
  using namespace impact::cli;
  const CalibrationOptions defaults;
  std::vector<Option> options = tool::run_options("FILE", "the calibration JSON to write");
  options.push_back(text_option("laws", "LIST",
                                "comparison laws fitted over the campaign: comma-separated "
                                "names (" +
                                    law_names() + "), 'all' or 'none'")
                        .with_default("all"));
  options.push_back(
      integer_option("max-iterations", "N", 1, 100000, "iteration limit of each least-squares fit")
          .with_default(std::to_string(defaults.max_iterations)));
  options.push_back(
      real_option("confidence", "LEVEL", Range::open(0, 1), "level of the confidence intervals")
          .with_default(impact_fem::as_written(defaults.confidence_level)));
  options.push_back(real_option("energy-weight", "W", Range::closed(0, 1e6),
                                "weight of the energy-loss residuals of the combined fits (1: a "
                                "1 % error in 1 - e^2 costs as much as a 1 % RMS force "
                                "residual; 0 fits the force histories only)")
                        .with_default(impact_fem::as_written(defaults.energy_weight)));
  options.push_back(real_option("published-damping", "B", Range::closed(0, 1e3),
                                "b [s/m] of the published Hunt-Crossley reference model (c "
                                "from Hertz, n = 3/2; 0.1 is the published steel example)")
                        .with_default(impact_fem::as_written(defaults.published_damping)));
  options.push_back(choice_option("damped-stiffness", {"hertz", "fitted"},
                                  "c of the damped elastic-plastic laws (hunt-crossley-thornton, "
                                  "...): held at the Hertz value of the runs' materials (hertz; "
                                  "fitted when the runs do not record them) or fitted")
                        .with_default("hertz"));
  return {R"(usage: impact-calibrate RUN... --output FILE [options]
       impact-calibrate --campaign DIR --output FILE [options]

Calibrates the Hunt-Crossley contact law F = c x^n (1 + b dx/dt) (and the comparison laws
of the reduced library) from impact-fem runs and writes the result as JSON.

  RUN                   a run directory of impact-fem (holding history.h5 and summary.json)
                        or its HDF5 file
)",
          options,
          R"(Exit codes: 0 success, 2 bad input (message names the problem; the JSON says what is
missing; with no usable run nothing is written), 3 a fit did not converge (see "problems"
in the JSON), 1 internal error.
)"};
}

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
      throw tool::UsageError("--laws: unknown law '" + law + "' (known: " + law_names() +
                             ", or all, none)");
    }
  return chosen;
}

CalibrationRequest parse(tool::CommandLine& line) {
  const tool::RunArguments common = tool::run_arguments(line, "FILE");
  CalibrationRequest request{common.runs, common.campaign, common.output, {}};
  CalibrationOptions& options = request.options;
  options.laws = laws(line);
  options.max_iterations = int(line.integer("max-iterations"));
  options.confidence_level = line.real("confidence");
  options.energy_weight = line.real("energy-weight");
  options.published_damping = line.real("published-damping");
  options.damped_plastic_hertz_stiffness = line.choice("damped-stiffness") == "hertz";
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

int main(int argc, char** argv) {
  return tool::run(program, usage(), argc, argv, parse, execute);
}
