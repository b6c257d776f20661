// impact-calibrate: Hunt–Crossley (and comparison-law) parameters from FEM impact runs.
// Exit codes: 0 success; 2 bad input (the message names the problem; the JSON, when it
// could be written, lists what is missing); 3 a fit did not converge; 1 internal error.

#include "command_line.hpp"

#include "impact_postprocess/calibration.hpp"
#include "impact_postprocess/calibration_json.hpp"
#include "impact_postprocess/fem_run.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
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
  --campaign DIR       all runs of a campaign: those listed in DIR/index.json or
                       DIR/index.csv, else every subdirectory holding history.h5
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
  --quiet              no progress messages on stderr
  --help               this text

Exit codes: 0 success, 2 bad input (message names the problem; the JSON says what is
missing), 3 a fit did not converge (see "problems" in the JSON), 1 internal error.
)";

struct Arguments : cli::RunArguments {
  std::vector<std::string> laws = impact::reduced::comparison_law_names();
  int max_iterations = 100;
  double confidence = 0.95;
  double energy_weight = CalibrationOptions{}.energy_weight;
  double published_damping = CalibrationOptions{}.published_damping;
};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

// The number that `text` spells in full (read by std::stol for an integral T, else by
// std::stod), or none.
template <class T>
std::optional<T> whole_number(const std::string& text) {
  std::size_t end = 0;
  try {
    T number;
    if constexpr (std::is_integral_v<T>) number = std::stol(text, &end);
    else number = std::stod(text, &end);
    if (end == text.size()) return number;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

Arguments parse(int argc, char** argv) {
  using cli::UsageError;
  Arguments arguments;
  const auto option = [&](const std::string& argument,
                          const std::function<std::string()>& value) {
    if (argument == "--laws") {
      const std::string list = value();
      if (list == "all") {
        arguments.laws = impact::reduced::comparison_law_names();
      } else if (list == "none") {
        arguments.laws.clear();
      } else {
        arguments.laws = split(list);
        const auto known = impact::reduced::comparison_law_names();
        for (const auto& law : arguments.laws)
          if (std::find(known.begin(), known.end(), law) == known.end()) {
            std::string names;
            for (const auto& name : known) names += (names.empty() ? "" : ", ") + name;
            throw UsageError("--laws: unknown law '" + law + "' (known: " + names +
                             ", or all, none)");
          }
      }
    } else if (argument == "--max-iterations") {
      const std::string text = value();
      const auto iterations = whole_number<long>(text);
      if (!iterations || *iterations < 1 || *iterations > 100000)
        throw UsageError("--max-iterations must be an integer in [1, 100000] (got '" + text + "')");
      arguments.max_iterations = int(*iterations);
    } else if (argument == "--confidence") {
      const std::string text = value();
      const auto level = whole_number<double>(text);
      if (!level || !(*level > 0 && *level < 1))
        throw UsageError("--confidence must be a number in (0, 1) (got '" + text + "')");
      arguments.confidence = *level;
    } else if (argument == "--energy-weight") {
      const std::string text = value();
      const auto weight = whole_number<double>(text);
      if (!weight || !(*weight >= 0 && *weight <= 1e6))
        throw UsageError("--energy-weight must be a number in [0, 1e6] (got '" + text + "')");
      arguments.energy_weight = *weight;
    } else if (argument == "--published-damping") {
      const std::string text = value();
      const auto damping = whole_number<double>(text);
      if (!damping || !(*damping >= 0 && *damping <= 1e3))
        throw UsageError("--published-damping must be a number of s/m in [0, 1000] (got '" +
                         text + "')");
      arguments.published_damping = *damping;
    } else {
      return false;
    }
    return true;
  };
  cli::parse_run_arguments(argc, argv, arguments, "FILE", option);
  if (arguments.help) return arguments;
  const fs::path directory = arguments.output->parent_path();
  if (!directory.empty() && !fs::is_directory(directory))
    throw UsageError("the directory of --output '" + arguments.output->string() +
                     "' does not exist");
  if (fs::is_directory(*arguments.output))
    throw UsageError("--output '" + arguments.output->string() + "' is a directory");
  return arguments;
}

void write_json(const fs::path& path, const Calibration& calibration) {
  const fs::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary);
    out << to_json(calibration).dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  fs::rename(temporary, path);
}

int execute(const Arguments& arguments) {
  const Campaign input = cli::read_input(arguments);
  for (const auto& problem : input.problems)
    std::cerr << "impact-calibrate: error: " << problem.message << '\n';

  CalibrationOptions options;
  options.laws = arguments.laws;
  options.max_iterations = arguments.max_iterations;
  options.confidence_level = arguments.confidence;
  options.energy_weight = arguments.energy_weight;
  options.published_damping = arguments.published_damping;
  if (!arguments.quiet)
    options.progress = [](const std::string& line) {
      std::cerr << "impact-calibrate: " << line << std::endl;
    };
  Calibration calibration = calibrate(input.runs, options);
  std::vector<CalibrationProblem> problems;
  for (const auto& problem : input.problems)
    problems.push_back({problem.source, "input", problem.message});
  if (input.runs.empty())
    problems.push_back({arguments.campaign ? arguments.campaign->string() : "",
                        "input", "no usable run: nothing was calibrated"});
  else if (!calibration.campaign.fitted && (arguments.campaign || arguments.runs.size() > 1))
    problems.push_back({arguments.campaign ? arguments.campaign->string() : "", "input",
                        "campaign not fitted: " + calibration.campaign.reason});
  problems.insert(problems.end(), calibration.problems.begin(), calibration.problems.end());
  calibration.problems = problems;

  bool input_problem = false, convergence_problem = false;
  for (const auto& problem : calibration.problems) {
    if (problem.kind == "input") input_problem = true;
    if (problem.kind == "convergence") convergence_problem = true;
    if (problem.kind != "input" || problem.message.rfind("campaign not fitted", 0) == 0 ||
        problem.message.rfind("no usable run", 0) == 0)
      cli::print_problem(program, problem);
  }
  write_json(*arguments.output, calibration);

  const auto& hc = calibration.campaign.hunt_crossley;
  if (hc) {
    std::cout.precision(6);
    std::cout << "Hunt-Crossley over " << calibration.runs.size() << " runs: c = "
              << hc->fit.stiffness.value << " N/m^n, n = " << hc->fit.exponent.value
              << ", b = " << hc->fit.parameter.value << " s/m (RMS residual "
              << hc->fit.quality.rms_residual * 100 << " % of the peak force)\n";
  }
  if (const auto& fixed = calibration.campaign.hunt_crossley_hertz_exponent) {
    std::cout.precision(6);
    std::cout << "Hunt-Crossley with n = " << hertz_exponent << " fixed: c = "
              << fixed->fit.stiffness.value << " N/m^" << hertz_exponent
              << ", b = " << fixed->fit.parameter.value << " s/m (RMS residual "
              << fixed->fit.quality.rms_residual * 100 << " % of the peak force)\n";
  }
  if (const auto& energy = calibration.campaign.hunt_crossley_energy) {
    std::cout.precision(6);
    std::cout << "Hunt-Crossley fitted to force histories and energy loss: c = "
              << energy->fit.stiffness.value << " N/m^n, n = " << energy->fit.exponent.value
              << ", b = " << energy->fit.parameter.value << " s/m\n";
  }
  if (!calibration.campaign.ranking.empty()) {
    const auto& best = calibration.campaign.ranking.front();
    std::cout.precision(4);
    std::cout << "ranked first by " << (best.out_of_sample ? "out-of-sample" : "in-sample")
              << " error: " << best.key << " (RMS error " << best.score * 100
              << " % in 1 - e^2, t_c, F_max, x_max)\n";
  }
  std::cout << "calibration written to " << arguments.output->string() << '\n';
  if (input_problem) return 2;
  return convergence_problem ? 3 : 0;
}

} // namespace

int main(int argc, char** argv) {
  return cli::run_command(program, usage, argc, argv, parse, execute);
}
