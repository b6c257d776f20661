// impact-report: the model-validity report of a campaign of FEM impact runs (HTML page with
// embedded figures, Markdown twin, figure PNGs beside them).
// Exit codes: 0 complete report (possibly with warnings on the FEM's quality); 2 bad input
// (a run, the calibration, the simulators' results: the report says what is missing); 3 a
// fit did not converge (numbers marked so); 4 the figures could not be drawn (report without
// them); 1 internal error. A report is written in every case but a usage error and exit 1.

#include "command_line.hpp"

#include "impact_postprocess/calibration.hpp"
#include "impact_postprocess/calibration_json.hpp"
#include "impact_postprocess/fem_run.hpp"
#include "impact_postprocess/fem_run_format.hpp"
#include "impact_postprocess/report.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace impact::postprocess;

const std::string program = "impact-report";

const char* usage = R"(usage: impact-report --campaign DIR --output DIR [--calibration FILE] [options]
       impact-report RUN... --output DIR [--calibration FILE] [options]

Writes the model-validity report of a campaign of impact-fem runs: where the calibrated
Hunt-Crossley law F = c x^n (1 + b dx/dt) and the other reduced models reproduce the FEM's
energy loss 1 - e^2, contact time, peak force and peak approach, judged out of sample
(leave one velocity out) against the FEM's own numerical uncertainty.
A sweep campaign of the velocity and one other parameter (impact-fem --sweep) gets a
validity map first (every row calibrated here); the sections after it detail one row,
that of the thickest plate (--calibration FILE, if given, is that row's calibration).

  --campaign DIR       the runs of a campaign (as impact-calibrate reads them)
  RUN                  a run directory or HDF5 file of impact-fem (instead of --campaign)
  --output DIR         where report.html, report.md, figures/ and report_data.json go
                       (created if needed)
  --calibration FILE   the JSON of impact-calibrate for these runs; without it the runs
                       are calibrated here (all laws) and DIR/calibration.json is written
  --tolerances LIST    the tolerance bands of the verdict in per cent, comma-separated,
                       each in (0, 100) (default 2,5)
  --published-damping B  b [s/m] of the published Hunt-Crossley model when the runs are
                       calibrated here (default 0.1; with --calibration the calibration's)
  --simulators DIR     the result files of tests/consumers/run_in_simulators.sh (every
                       DIR/*.json, format impact-simulator-run): the section "In your
                       simulator" (without it the section gives the commands)
  --quiet              no progress messages on stderr
  --help               this text

Environment: IMPACT_REPORT_PYTHON, the Python 3 with matplotlib that draws the figures
(default: the one found when the project was configured).

Exit codes: 0 complete report, 2 bad input (a run, the calibration, the simulators
directory or one of its result files; the report says what is missing), 3 a fit did not
converge, 4 the figures could not be drawn, 1 internal error.
)";

struct Arguments : cli::RunArguments {
  std::optional<fs::path> calibration;
  std::vector<double> tolerances = default_tolerances;
  double published_damping = CalibrationOptions{}.published_damping;
  std::optional<fs::path> simulators;
};

// A number spelled in full, or none.
std::optional<double> parse_number(const std::string& text) {
  try {
    std::size_t end = 0;
    const double value = std::stod(text, &end);
    if (end == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

Arguments parse(int argc, char** argv) {
  Arguments arguments;
  const auto option = [&](const std::string& argument,
                          const std::function<std::string()>& value) {
    if (argument == "--calibration") arguments.calibration = value();
    else if (argument == "--simulators") arguments.simulators = value();
    else if (argument == "--tolerances") {
      const std::string list = value();
      arguments.tolerances.clear();
      std::stringstream stream(list);
      std::string item;
      while (std::getline(stream, item, ',')) {
        const auto percent = parse_number(item);
        if (!percent || !(*percent > 0 && *percent < 100))
          throw cli::UsageError("--tolerances must be per cents in (0, 100), comma-separated "
                                "(got '" + list + "')");
        arguments.tolerances.push_back(*percent / 100);
      }
      if (arguments.tolerances.empty())
        throw cli::UsageError("--tolerances needs at least one per cent (got '" + list + "')");
    } else if (argument == "--published-damping") {
      const std::string text = value();
      const auto damping = parse_number(text);
      if (!damping || !(*damping >= 0 && *damping <= 1e3))
        throw cli::UsageError("--published-damping must be a number of s/m in [0, 1000] (got '" +
                              text + "')");
      arguments.published_damping = *damping;
    } else return false;
    return true;
  };
  cli::parse_run_arguments(argc, argv, arguments, "DIR", option);
  if (arguments.help) return arguments;
  if (fs::exists(*arguments.output) && !fs::is_directory(*arguments.output))
    throw cli::UsageError("--output '" + arguments.output->string() +
                          "' exists and is not a directory");
  return arguments;
}

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The figure script: installed beside the executable's share directory, else in the source
// tree the executable was built from.
fs::path figure_script() {
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed =
        executable.parent_path().parent_path() / "share" / "impact" / "report_figures.py";
    if (fs::exists(installed)) return installed;
  }
  return IMPACT_REPORT_FIGURE_SCRIPT;
}

std::string python_interpreter() {
  const char* chosen = std::getenv("IMPACT_REPORT_PYTHON");
  return chosen && *chosen ? chosen : IMPACT_REPORT_PYTHON;
}

// Draws the figures; returns the problems (none when every figure file was written).
std::vector<ReportProblem> draw_figures(const Report& report, const fs::path& output,
                                        const fs::path& figures) {
  const auto expected = report_figures(report);
  if (expected.empty()) return {};
  fs::create_directories(figures);
  for (const auto& figure : expected) fs::remove(figures / figure.file); // no stale image
  const fs::path data = output / "report_data.json";
  {
    std::ofstream out(data);
    out << figure_specification(report).dump() << '\n';
    if (!out) return {{data.string(), "figures", "cannot write the figure data file"}};
  }
  const fs::path log = output / "figures.log";
  const std::string python = python_interpreter();
  const fs::path script = figure_script();
  const std::string command = shell_quote(python) + " " + shell_quote(script.string()) + " " +
                              shell_quote(data.string()) + " " + shell_quote(figures.string()) +
                              " >" + shell_quote(log.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::vector<ReportProblem> problems;
  if (code != 0) {
    std::string message;
    {
      std::ifstream in(log);
      std::string line;
      while (std::getline(in, line))
        if (!line.empty()) message = line; // the last line says what failed
    }
    problems.push_back({script.string(), "figures",
                        "the figures could not be drawn (" + python + " " + script.string() +
                            " exited with " + std::to_string(code) + ": " +
                            (message.empty() ? "no message" : message) +
                            "); install python3-matplotlib or set IMPACT_REPORT_PYTHON"});
  }
  for (const auto& figure : expected)
    if (!fs::exists(figures / figure.file) || fs::file_size(figures / figure.file) == 0)
      problems.push_back({(figures / figure.file).string(), "figures", "the figure was not drawn"});
  return problems;
}

// Without an index, the campaign reader finds runs by their HDF5 files, so a run directory
// whose HDF5 file is missing would go unnoticed: it is found here by its summary.json.
std::vector<InputProblem> runs_without_history(const fs::path& campaign) {
  namespace format = fem_format;
  std::vector<InputProblem> problems;
  if (!fs::is_directory(campaign) || fs::exists(campaign / format::campaign_index_json) ||
      fs::exists(campaign / format::campaign_index_csv))
    return problems;
  for (const auto& item : fs::directory_iterator(campaign)) {
    const fs::path& path = item.path();
    if (item.is_directory() && fs::exists(path / format::summary_file) &&
        !fs::exists(path / format::history_file) &&
        !fs::exists(path / format::incomplete_history_file))
      problems.push_back({path.string(), "run '" + path.string() + "': the directory holds " +
                                             format::summary_file + " but no " +
                                             format::history_file +
                                             ": the HDF5 file of the run is missing"});
  }
  return problems;
}

// The calibration: the given JSON, or one computed here (and written beside the report).
std::optional<Calibration> obtain_calibration(const Arguments& arguments, const Campaign& input,
                                              std::vector<ReportProblem>& problems,
                                              std::string& source,
                                              std::optional<Calibration>& calibrated_here) {
  if (arguments.calibration) {
    source = arguments.calibration->string();
    if (!fs::is_regular_file(*arguments.calibration)) {
      problems.push_back({source, "input", "the calibration file does not exist: the report "
                                           "shows the FEM data only"});
      return std::nullopt;
    }
    try {
      std::ifstream in(*arguments.calibration);
      return calibration_from_json(json::parse(in));
    } catch (const std::exception& error) {
      problems.push_back({source, "input", std::string("the calibration cannot be read: ") +
                                               error.what() + "; the report shows the FEM data only"});
      return std::nullopt;
    }
  }
  if (input.runs.empty()) return std::nullopt;
  CalibrationOptions options;
  options.published_damping = arguments.published_damping;
  if (!arguments.quiet)
    options.progress = [](const std::string& line) {
      std::cerr << "impact-report: calibration: " << line << std::endl;
    };
  Calibration calibration = calibrate(input.runs, options);
  calibrated_here = calibration; // before the campaign's input problems are added
  std::vector<CalibrationProblem> all;
  for (const auto& problem : input.problems)
    all.push_back({problem.source, problem.no_rebound ? "no rebound" : "input", problem.message});
  if (!calibration.campaign.fitted)
    all.push_back({arguments.campaign ? arguments.campaign->string() : "", "input",
                   "campaign not fitted: " + calibration.campaign.reason});
  all.insert(all.end(), calibration.problems.begin(), calibration.problems.end());
  calibration.problems = all;
  const fs::path file = *arguments.output / "calibration.json";
  {
    std::ofstream out(file);
    out << to_json(calibration).dump(2) << '\n';
  }
  source = file.string() + " (calibrated by impact-report)";
  return calibration;
}

int execute(const Arguments& arguments) {
  const fs::path output = *arguments.output;
  fs::create_directories(output);

  Campaign input = cli::read_input(arguments);
  std::vector<ReportProblem> problems;
  std::string campaign_source;
  if (arguments.campaign) {
    campaign_source = arguments.campaign->string();
    const auto lost = runs_without_history(*arguments.campaign);
    input.problems.insert(input.problems.end(), lost.begin(), lost.end());
  } else {
    for (const auto& run : arguments.runs)
      campaign_source += (campaign_source.empty() ? "" : ", ") + run.string();
  }

  // A two-axis campaign: the map covers every run, the sections after it one row.
  ReportOptions options;
  if (auto row = map_detail_row(input)) {
    options.map_campaign = std::move(input);
    input = std::move(row->first);
    options.detail_row = row->second;
  }
  std::string calibration_source;
  std::optional<Calibration> calibrated_here;
  const auto calibration =
      obtain_calibration(arguments, input, problems, calibration_source, calibrated_here);
  // The map's row of these runs is this calibration (the same options): not computed twice.
  if (options.map_campaign) options.detail_row_calibration = std::move(calibrated_here);
  options.tolerances = arguments.tolerances;
  options.simulators = arguments.simulators;
  // The rows of a validity map (a two-axis campaign) are calibrated here, every law.
  options.map_calibration.published_damping =
      calibration ? calibration->campaign.published_damping : arguments.published_damping;
  if (!arguments.quiet)
    options.map_calibration.progress = [](const std::string& line) {
      std::cerr << "impact-report: " << line << std::endl;
    };
  Report report =
      build_report(input, calibration, problems, campaign_source, calibration_source, options);

  const fs::path figures_directory = "figures";
  const auto figure_problems = draw_figures(report, output, output / figures_directory);
  report.problems.insert(report.problems.end(), figure_problems.begin(), figure_problems.end());

  write_report_markdown(report, output / "report.md", figures_directory);
  write_report_html(report, output / "report.html", figures_directory);

  bool input_problem = false, convergence_problem = false, figure_problem = false;
  bool incomplete = false;
  for (const auto& problem : report.problems) {
    input_problem = input_problem || problem.kind == "input";
    convergence_problem = convergence_problem || problem.kind == "convergence";
    figure_problem = figure_problem || problem.kind == "figures";
    incomplete = incomplete || (problem.kind != "quality" && problem.kind != "no rebound");
    cli::print_problem(program, problem);
  }
  if (incomplete)
    std::cerr << "impact-report: the report is incomplete; it lists these problems\n";
  else if (!report.problems.empty())
    std::cerr << "impact-report: the report is complete; it lists these warnings on the FEM\n";
  std::cout << "markdown written to " << (output / "report.md").string() << '\n'
            << "report written to " << (output / "report.html").string() << '\n';
  if (input_problem) return 2;
  if (convergence_problem) return 3;
  return figure_problem ? 4 : 0;
}

} // namespace

int main(int argc, char** argv) {
  return cli::run_command(program, usage, argc, argv, parse, execute);
}
