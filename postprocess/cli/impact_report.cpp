// impact-report: the model-validity report of a campaign of FEM impact runs (HTML page with
// embedded figures, Markdown twin, figure PNGs beside them). The options are parsed here; the
// report is made by write_report (impact_postprocess/report/pipeline.hpp).
// Exit codes: 0 complete report (possibly with warnings on the FEM's quality); 2 bad input
// (a run, the calibration, the simulators' results: the report says what is missing; with
// no usable run nothing is written); 3 a fit did not converge (numbers marked so); 4 the
// figures could not be drawn (report without them); 1 internal error.

#include "tool.hpp"

#include "impact_postprocess/report/pipeline.hpp"

#include <impact_fem/as_written.h>

#include <filesystem>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace impact::postprocess;

const std::string program = "impact-report";

tool::Usage usage() {
  using namespace impact::cli;
  std::vector<Option> options = tool::run_options(
      "DIR",
      "where report.html, report.md, figures/ and report_data.json go (created if "
      "needed)");
  std::string tolerances;
  for (const double tolerance : default_tolerances)
    tolerances += (tolerances.empty() ? "" : ",") + impact_fem::as_written(100 * tolerance);
  options.push_back(text_option("calibration", "FILE",
                                "the JSON of impact-calibrate for these runs; without it the "
                                "runs are calibrated here (all laws) and DIR/calibration.json "
                                "is written"));
  options.push_back(reals_option("tolerances", "LIST", Range::open(0, 100),
                                 "the tolerance bands of the verdict in per cent")
                        .with_default(tolerances));
  options.push_back(real_option("published-damping", "B", Range::closed(0, 1e3),
                                "b [s/m] of the published Hunt-Crossley model when the runs are "
                                "calibrated here (with --calibration the calibration's)")
                        .with_default(impact_fem::as_written(ReportRequest{}.published_damping)));
  options.push_back(text_option("simulators", "DIR",
                                "the result files of tests/consumers/run_in_simulators.sh "
                                "(every DIR/*.json, format impact-simulator-run): the section "
                                "\"In your simulator\" (without it the section gives the "
                                "commands)"));
  return {R"(usage: impact-report --campaign DIR --output DIR [--calibration FILE] [options]
       impact-report RUN... --output DIR [--calibration FILE] [options]

Writes the model-validity report of a campaign of impact-fem runs: where the calibrated
Hunt-Crossley law F = c x^n (1 + b dx/dt) and the other reduced models reproduce the FEM's
energy loss 1 - e^2, contact time, peak force and peak approach, judged out of sample
(leave one velocity out) against the FEM's own numerical uncertainty.
A sweep campaign of the velocity and one other parameter (impact-fem --sweep) gets a
validity map first (every row calibrated here); the sections after it detail one row,
that of the thickest plate (--calibration FILE, if given, is that row's calibration).

  RUN                   a run directory or HDF5 file of impact-fem (instead of --campaign)
)",
          options,
          R"(Environment: IMPACT_REPORT_PYTHON, the Python 3 with matplotlib that draws the figures
(default: the one found when the project was configured).

Exit codes: 0 complete report, 2 bad input (a run, the calibration, the simulators
directory or one of its result files; the report says what is missing), 3 a fit did not
converge, 4 the figures could not be drawn, 1 internal error.
)"};
}

ReportRequest parse(tool::CommandLine& line) {
  const tool::RunArguments common = tool::run_arguments(line, "DIR");
  ReportRequest request;
  request.runs = common.runs;
  request.campaign = common.campaign;
  request.output = common.output;
  if (const auto calibration = line.text("calibration")) request.calibration = *calibration;
  if (const auto simulators = line.text("simulators")) request.simulators = *simulators;
  if (line.has("tolerances")) {
    const std::string list = line.given_text("tolerances");
    try {
      request.tolerances = line.reals("tolerances");
    } catch (const tool::UsageError&) {
      throw tool::UsageError("--tolerances must be per cents in (0, 100), comma-separated (got '" +
                             list + "')");
    }
    for (double& tolerance : request.tolerances) tolerance /= 100;
  }
  request.published_damping = line.real("published-damping");
  if (!common.quiet)
    request.progress = [](const std::string& text) {
      std::cerr << program << ": " << text << std::endl;
    };
  if (fs::exists(request.output) && !fs::is_directory(request.output))
    throw tool::UsageError("--output '" + request.output.string() +
                           "' exists and is not a directory");
  return request;
}

int execute(const ReportRequest& request) {
  const ReportOutcome outcome = write_report(request);
  for (const auto& problem : outcome.report.problems) tool::print_problem(program, problem);
  if (!outcome.written) return outcome.exit_code;
  if (!complete(outcome.report.problems))
    std::cerr << program << ": the report is incomplete; it lists these problems\n";
  else if (!outcome.report.problems.empty())
    std::cerr << program << ": the report is complete; it lists these warnings on the FEM\n";
  std::cout << "markdown written to " << outcome.markdown.string() << '\n'
            << "report written to " << outcome.html.string() << '\n';
  return outcome.exit_code;
}

} // namespace

int main(int argc, char** argv) {
  return tool::run(program, usage(), argc, argv, parse, execute);
}
