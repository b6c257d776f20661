#pragma once
/// @file
/// The report from end to end, as impact-report makes it: the run set read, its calibration
/// (read from impact-calibrate's JSON or computed here and written beside the report), the
/// assessment (assess), the figures drawn, the page written as HTML and Markdown. The
/// command-line tool only parses its options into a ReportRequest and calls write_report.

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/problem.hpp"
#include "impact_postprocess/report/report.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// Draws the figures of `report` into `figures` (a directory); `output` is the report's
/// directory, for the files the drawing needs (report_data.json, figures.log). Returns the
/// problems (kind figures), none when every figure of report_figures was drawn.
using FigureDrawer =
    std::function<std::vector<Problem>(const Report& report, const std::filesystem::path& output,
                                       const std::filesystem::path& figures)>;

/// The drawer of the installed tool: postprocess/report_figures.py run by the Python 3 with
/// matplotlib (the environment variable IMPACT_REPORT_PYTHON, else the one found when the
/// project was configured), the script found beside the executable's share directory, else
/// in the source tree.
std::vector<Problem> draw_figures_with_python(const Report& report,
                                              const std::filesystem::path& output,
                                              const std::filesystem::path& figures);

struct ReportRequest {
  std::vector<std::filesystem::path> runs;       ///< run files, or
  std::optional<std::filesystem::path> campaign; ///< a campaign directory
  std::filesystem::path output;                  ///< the report's directory
  /// impact-calibrate's JSON for these runs; none: the runs are calibrated here (every law)
  /// and output/calibration.json is written.
  std::optional<std::filesystem::path> calibration;
  std::vector<double> tolerances = default_tolerances;
  /// b [s/m] of the published Hunt–Crossley model when the runs are calibrated here.
  double published_damping = CalibrationOptions{}.published_damping;
  std::optional<std::filesystem::path> simulators; ///< the simulators' result files
  /// Progress lines (none: quiet).
  std::function<void(const std::string&)> progress;
  FigureDrawer draw_figures = draw_figures_with_python;
};

struct ReportOutcome {
  /// False when there was no usable run: then nothing was written (not even the directory)
  /// and `report` is empty but for its problems.
  bool written = false;
  Report report;
  std::filesystem::path markdown, html;
  /// exit_code(report.problems): 0 complete, 2 bad input, 3 a fit did not converge,
  /// 4 the figures could not be drawn.
  int exit_code = 0;
};

/// Calibrates every row of the validity map of `campaign` (map_rows; none for a campaign
/// without map) with `options`, parallel to map_rows; a row of the same runs (the same HDF5
/// sources) as `detail` takes `detail` instead of being calibrated again. Progress lines of a
/// row start with "map row <row name>: ". Never throws for a row that cannot be calibrated
/// (MapRowCalibration::error says why).
std::vector<MapRowCalibration> calibrate_map_rows(const Campaign& campaign,
                                                  const CalibrationOptions& options,
                                                  const std::optional<Calibration>& detail = {});

/// Makes the report of `request`. Never throws for bad input (every problem is in
/// report.problems, the page lists it); throws std::runtime_error when a file cannot be
/// written.
ReportOutcome write_report(const ReportRequest& request);

} // namespace impact::postprocess
