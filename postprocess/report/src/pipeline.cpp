// write_report (pipeline.hpp): run set -> calibration (and the validity map's rows'
// calibrations) -> assessment -> figures -> page.

#include "impact_postprocess/report/pipeline.hpp"
#include "map_words.hpp"

#include "impact_postprocess/calibration/calibrate_run_set.hpp"
#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/run/run_set.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;

// The calibration of the report: the given JSON, or one computed here.
struct ObtainedCalibration {
  std::optional<Calibration> calibration; ///< with the campaign's problems when made here
  std::string source;                     ///< how the page names it
  std::vector<Problem> problems;          ///< met reading the given JSON
  /// The calibration made here as calibrate returned it (before the campaign's problems were
  /// added): the validity map's row of the same runs.
  std::optional<Calibration> calibrated_here;
};

ObtainedCalibration read_calibration(const fs::path& file) {
  ObtainedCalibration obtained;
  obtained.source = file.string();
  if (!fs::is_regular_file(file)) {
    obtained.problems.push_back({obtained.source, ProblemKind::input,
                                 "the calibration file does not exist: the report shows the "
                                 "FEM data only"});
    return obtained;
  }
  try {
    std::ifstream in(file);
    obtained.calibration = calibration_from_json(nlohmann::json::parse(in));
  } catch (const std::exception& error) {
    obtained.problems.push_back({obtained.source, ProblemKind::input,
                                 std::string("the calibration cannot be read: ") + error.what() +
                                     "; the report shows the FEM data only"});
  }
  return obtained;
}

ObtainedCalibration calibrate_here(const ReportRequest& request, const Campaign& input) {
  ObtainedCalibration obtained;
  CalibrationOptions options;
  options.published_damping = request.published_damping;
  if (request.progress)
    options.progress = [&request](const std::string& line) {
      request.progress("calibration: " + line);
    };
  Calibration calibration = calibrate(input.runs, options);
  obtained.calibrated_here = calibration;
  std::vector<Problem> all(input.problems.begin(), input.problems.end());
  if (!calibration.campaign.fitted)
    all.push_back(campaign_not_fitted(request.campaign ? request.campaign->string() : "",
                                      calibration.campaign));
  all.insert(all.end(), calibration.problems.begin(), calibration.problems.end());
  calibration.problems = std::move(all);
  const fs::path file = request.output / "calibration.json";
  {
    std::ofstream out(file);
    out << to_json(calibration).dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
        << '\n';
    if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
  }
  obtained.source = file.string() + " (calibrated by impact-report)";
  obtained.calibration = std::move(calibration);
  return obtained;
}

/// Whether the calibration is of exactly these runs (the same HDF5 sources).
bool same_runs(const Calibration& calibration, const std::vector<FemRun>& runs) {
  std::vector<std::string> calibrated, given;
  for (const auto& run : calibration.runs) calibrated.push_back(run.source);
  for (const auto& run : runs) given.push_back(run.source);
  std::sort(calibrated.begin(), calibrated.end());
  std::sort(given.begin(), given.end());
  return calibrated == given;
}

} // namespace

std::vector<MapRowCalibration> calibrate_map_rows(const Campaign& campaign,
                                                  const CalibrationOptions& options,
                                                  const std::optional<Calibration>& detail) {
  std::vector<MapRowCalibration> calibrations;
  for (const MapRowRuns& row : map_rows(campaign)) {
    MapRowCalibration calibrated;
    if (!row.runs.empty()) {
      CalibrationOptions row_options = options;
      if (row_options.progress) {
        const auto progress = row_options.progress;
        row_options.progress = [progress, name = detail::map_row_name(row.parameter, row.value)](
                                   const std::string& line) {
          progress("map row " + name + ": " + line);
        };
      }
      if (detail && same_runs(*detail, row.runs)) {
        calibrated.calibration = detail;
        if (row_options.progress)
          row_options.progress("the calibration of the detail row, not repeated");
      } else {
        try {
          calibrated.calibration = calibrate(row.runs, row_options);
        } catch (const std::exception& error) {
          calibrated.error = error.what();
        }
      }
    }
    calibrations.push_back(std::move(calibrated));
  }
  return calibrations;
}

ReportOutcome write_report(const ReportRequest& request) {
  ReportOutcome outcome;
  Campaign input = read_run_set(request.runs, request.campaign);
  const std::string campaign_source = run_set_source(request.runs, request.campaign);
  if (input.runs.empty()) {
    // Nothing written from nothing: the problems say why there is no run.
    outcome.report.problems.assign(input.problems.begin(), input.problems.end());
    outcome.report.problems.push_back(
        {campaign_source, ProblemKind::input, "no usable run: nothing was written"});
    outcome.exit_code = exit_code(outcome.report.problems);
    return outcome;
  }
  fs::create_directories(request.output);

  // A two-axis campaign: the map covers every run, the sections after it one row.
  ReportOptions options;
  if (auto row = map_detail_row(input)) {
    options.map_campaign = std::move(input);
    options.detail_row = row->at;
    input = std::move(row->campaign);
  }
  ObtainedCalibration obtained =
      request.calibration ? read_calibration(*request.calibration) : calibrate_here(request, input);
  options.tolerances = request.tolerances;
  options.simulators = request.simulators;
  // The rows of a validity map (a two-axis campaign) are calibrated here, every law; the row
  // of the detail's runs is this calibration (the same options): not computed twice.
  if (options.map_campaign) {
    CalibrationOptions map_options;
    map_options.published_damping = obtained.calibration
                                        ? obtained.calibration->campaign.published_damping
                                        : request.published_damping;
    map_options.progress = request.progress;
    options.map_calibrations =
        calibrate_map_rows(*options.map_campaign, map_options, obtained.calibrated_here);
  }
  outcome.report = build_report(input, obtained.calibration, obtained.problems, campaign_source,
                                obtained.source, options);

  const fs::path figures_directory = "figures";
  const auto figure_problems =
      request.draw_figures(outcome.report, request.output, request.output / figures_directory);
  outcome.report.problems.insert(outcome.report.problems.end(), figure_problems.begin(),
                                 figure_problems.end());

  outcome.markdown = request.output / "report.md";
  outcome.html = request.output / "report.html";
  write_report_markdown(outcome.report, outcome.markdown, figures_directory);
  write_report_html(outcome.report, outcome.html, figures_directory);
  outcome.written = true;
  outcome.exit_code = exit_code(outcome.report.problems);
  return outcome;
}

} // namespace impact::postprocess
