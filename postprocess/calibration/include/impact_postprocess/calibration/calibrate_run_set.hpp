#pragma once
/// @file
/// The calibration from end to end, as impact-calibrate makes it: the run set read, calibrated
/// (calibrate), the problems of reading and of the campaign added, the JSON written
/// atomically. The command-line tool only parses its options into a CalibrationRequest and
/// calls write_calibration.

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/problem.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

struct CalibrationRequest {
  std::vector<std::filesystem::path> runs;       ///< run files, or
  std::optional<std::filesystem::path> campaign; ///< a campaign directory
  std::filesystem::path output;                  ///< the calibration JSON
  CalibrationOptions options;
};

struct CalibrationOutcome {
  /// False when there was no usable run: then nothing was written.
  bool written = false;
  /// With every problem met: reading the runs, the campaign, the fits.
  Calibration calibration;
  /// exit_code(calibration.problems): 0 success, 2 bad input, 3 a fit did not converge.
  int exit_code = 0;
};

/// Calibrates the runs of `request` and writes the JSON (through a temporary file renamed
/// over `output`). Never throws for bad input; throws std::runtime_error when the file cannot
/// be written.
CalibrationOutcome write_calibration(const CalibrationRequest& request);

/// The problem (kind input) by which a calibration's problems say that its campaign was not
/// fitted and why: written by impact-calibrate for a campaign (or several runs) and by
/// impact-report when it calibrates the runs itself.
Problem campaign_not_fitted(const std::string& source, const CampaignCalibration& campaign);
/// Whether `problem` is campaign_not_fitted of `campaign` (by its kind and its statement,
/// whichever tool wrote it and from wherever).
bool is_campaign_not_fitted(const Problem& problem, const CampaignCalibration& campaign);

/// The campaign's Hunt–Crossley fits and the model ranked first, in a few lines.
std::string calibration_summary(const Calibration& calibration);

} // namespace impact::postprocess
