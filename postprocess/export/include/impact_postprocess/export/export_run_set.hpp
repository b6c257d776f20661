#pragma once
/// @file
/// The export from end to end, as impact-export makes it: the run set read (every run must be
/// readable), the calibration JSON read and checked against it, the files written
/// (write_exports). The command-line tool only parses its options into an ExportRequest and
/// calls export_run_set.

#include "impact_postprocess/problem.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

struct ExportRequest {
  std::vector<std::filesystem::path> runs;       ///< run files, or
  std::optional<std::filesystem::path> campaign; ///< a campaign directory
  std::filesystem::path calibration;             ///< impact-calibrate's JSON of these runs
  std::filesystem::path output;                  ///< the export directory
  std::optional<double> reference_velocity;      ///< m/s, MuJoCo's (none: the median run)
  /// The damped elastic-plastic law of the restitution table (none: the first-ranked one;
  /// no table when the calibration has none), and its number of log-spaced velocities.
  std::optional<std::string> table_law;
  std::size_t table_points = 25;
};

struct ExportOutcome {
  /// Every problem met (kind input), each naming its file; when there is one, nothing was
  /// written.
  std::vector<Problem> problems;
  nlohmann::json manifest; ///< export.json, when written
};

/// Writes the exports of `request`. Never throws for bad input.
ExportOutcome export_run_set(const ExportRequest& request);

/// The sphere radius [m] that every run records (impact-fem's text parameter
/// 'Scenario/Sphere radius'); throws ExportInputError naming the run when one does not record
/// it, records a value that is not a positive length, or differs from the others.
double sphere_radius(const Campaign& input);

} // namespace impact::postprocess
