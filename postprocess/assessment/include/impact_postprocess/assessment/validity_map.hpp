#pragma once
/// @file
/// The validity map of a campaign with sweep axes (validity_map.cpp): every row calibrated
/// and judged as a velocity campaign of its own.

#include "impact_postprocess/assessment/verdict.hpp"
#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace impact::postprocess {

/// One cell of a validity map: one run (a value of the other axis, a velocity) and one model.
struct MapCell {
  double velocity;                  ///< m/s
  std::string source;               ///< the FEM run
  std::optional<ImpactFigures> fem; ///< measured
  std::optional<ImpactFigures>
      judged; ///< the model's prediction judged (out of sample where the row allows)
  FemUncertainty uncertainty;      ///< the FEM's, of each quantity (relative)
  std::vector<Decision> decisions; ///< per tolerance of the report (increasing)
  bool yields = false;
  std::string missing; ///< why the model has no value here ("" if it has)
};

/// A model on one row (the runs at one value of the other axis).
struct MapModelRow {
  std::string parameters; ///< the values used on this row, as text with units
  bool out_of_sample = false;
  std::string missing; ///< why the model cannot be evaluated on this row ("" if it can)
  std::optional<NoVerdict> no_verdict; ///< the row has no verdict (missing then says so)
  std::vector<MapCell> cells;          ///< one per run of the row, ordered by velocity
};

struct MapRow {
  SweepValue value;                 ///< of the other axis
  std::vector<MapModelRow> models;  ///< parallel to ValidityMap::models
  std::string calibration_problems; ///< the row calibration's problems, in words ("" if none)
};

/// A model of the map.
struct MapModel {
  std::string key; ///< "calibrated", "best-law", "thin-plate"
  std::string label;
  std::string basis;  ///< how it is obtained on each row
  std::string region; ///< where it is valid, in a sentence
};

/// The validity map of a two-axis campaign (velocity x one other parameter): every row is
/// calibrated and judged as a velocity campaign, by the verdict's rule (postprocess/README.md).
struct ValidityMap {
  bool available = false;
  std::string reason;             ///< why there is no map, when not available
  std::string parameter;          ///< the other axis ("Scenario/Plate thickness")
  std::string unit;               ///< its unit, when known ("m")
  bool logarithmic = false;       ///< the other axis drawn on a log scale
  std::vector<double> velocities; ///< every velocity of the campaign, increasing
  std::vector<MapModel> models;
  std::vector<MapRow> rows;      ///< in the order of the axis's values
  std::size_t reference_row = 0; ///< the row whose Hunt–Crossley b the thin-plate model takes
};

/// A cell's class by the verdict's decisions: 0 .. bands-1 within that band (the tightest one
/// in which it is within), bands outside the loosest, bands + 1 not decided (the FEM's
/// uncertainty as large as the margin), bands + 2 not evaluated (no prediction); and its
/// name ("within 2 %", "outside 5 %", "not decided", "not evaluated").
std::size_t map_class(const MapCell& cell);
std::string map_class_name(const MapCell& cell, const std::vector<double>& tolerances);
/// The largest FEM uncertainty (relative) of the judged quantities at the cell, NaN if none
/// is known.
double map_uncertainty(const MapCell& cell);

/// One row of a validity map: a value of the other axis and the campaign's runs there.
struct MapRowRuns {
  SweepValue value;
  std::string name; ///< "Plate thickness = 0.05"
  std::vector<FemRun> runs;
};

/// The calibration of one row of a validity map.
struct MapRowCalibration {
  std::optional<Calibration>
      calibration;   ///< none when the row has no run or could not be calibrated
  std::string error; ///< why it could not be calibrated ("" otherwise)
};

/// The rows of the validity map of a two-axis campaign (velocity x one other parameter): each
/// value of the other axis, in the map's order (increasing when every value is a number), with
/// its runs; none for any other campaign.
std::vector<MapRowRuns> map_rows(const Campaign& campaign);

/// The row of a two-axis campaign (velocity x one other parameter) that the report's sections
/// after the map detail, as a velocity campaign of its own: the runs with the largest
/// Scenario/Plate thickness (the most massive plate, nearest to the reduced models'
/// assumption), else those at the other axis's first value; and the row's name ("Plate
/// thickness = 0.05 m"). Nothing for any other campaign (its sections show every run).
std::optional<std::pair<Campaign, std::string>> map_detail_row(const Campaign& campaign);

// Shared by the assessment and the report (namespace detail: not for a reader of the API).
namespace detail {

/// "Plate thickness" of "Scenario/Plate thickness".
std::string short_name(const std::string& parameter);
/// A sweep value with its unit ("0.05 m"; a text value as it is).
std::string with_unit(const SweepValue& value, const std::string& unit);
/// The judged quantity with the largest |error| at the cell, and that error.
std::optional<std::pair<Quantity, double>> map_worst_error(const MapCell& cell);

} // namespace detail

} // namespace impact::postprocess
