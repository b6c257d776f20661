#pragma once
/// @file
/// The validity map of a campaign with sweep axes (validity_map.cpp): every row calibrated
/// and judged as a velocity campaign of its own. Numbers, classes and reasons only: the report
/// words them (report/src/map_words.cpp).

#include "impact_postprocess/assessment/compared_models.hpp"
#include "impact_postprocess/assessment/no_value.hpp"
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
  std::optional<NoValue> missing; ///< why the model has no value here (none if it has)
};

/// The thin-plate model's values at one run (steps.hpp, thin_plate_prediction): Hertz c
/// [N/m^1.5] (n = 3/2) from the run's materials, the plate's point impedance Z [N s/m]
/// (infinite: the rigid support of the massive-plate model) and Zener's lambda, at the run's
/// impact velocity [m/s].
struct ThinPlateValues {
  double stiffness;
  double impedance;
  double zener_lambda;
  double velocity;
};

/// The values of a plate model (thin-plate, massive-plate) on one row.
struct PlateModelValues {
  /// The model at the row's first run that has a damping (none when it failed there).
  std::optional<ThinPlateValues> first;
  /// (V [m/s], b [s/m]) at each run of the row that has one: the damping taken from the
  /// reference row (ValidityMap::reference_row) at the same velocity.
  std::vector<std::pair<double, double>> damping;
};

/// A model on one row (the runs at one value of the other axis).
struct MapModelRow {
  /// The calibrated Hunt–Crossley and the best law: the row's compared model's basis and
  /// values (compared_models.hpp); none for the plate models.
  std::optional<ModelBasis> basis;
  std::vector<ModelParameter> parameters;
  /// The plate models: their values on the row (none where they cannot be evaluated).
  std::optional<PlateModelValues> plate;
  bool out_of_sample = false;
  std::optional<NoValue>
      missing;                ///< why the model cannot be evaluated on this row (none if it can)
  std::vector<MapCell> cells; ///< one per run of the row, ordered by velocity
};

struct MapRow {
  SweepValue value;                ///< of the other axis
  std::vector<MapModelRow> models; ///< parallel to ValidityMap::models
  /// The row's calibration (AssessmentOptions::map_calibrations): whether one was handed in,
  /// why calibrate failed on the row (its message, "" if it did not), and the calibration's
  /// own problems.
  bool calibrated = false;
  std::string calibration_error;
  std::vector<Problem> calibration_problems;
};

/// Where a model of the map is within one band: the rows where every cell is, and the rows
/// where some are (the row, the velocities [m/s] of those cells).
struct MapRegion {
  std::vector<std::size_t> rows;
  std::vector<std::pair<std::size_t, std::vector<double>>> partly;
};

/// A model of the map: its key ("calibrated", "best-law", "thin-plate", "massive-plate",
/// model_keys.hpp) and where it is valid, by the cells' classes.
struct MapModel {
  std::string key;
  std::vector<MapRegion> within;             ///< per band of the report (increasing)
  std::vector<std::size_t> undecided_rows;   ///< rows with a cell not decided
  std::vector<std::size_t> unevaluated_rows; ///< rows where the model cannot be evaluated
};

/// The validity map of a two-axis campaign (velocity x one other parameter): every row is
/// calibrated and judged as a velocity campaign, by the verdict's rule (postprocess/README.md).
struct ValidityMap {
  bool available = false;
  /// The campaign's sweep axes (entry paths): when not available, why (a map needs exactly
  /// two, one of them the velocity).
  std::vector<std::string> axes;
  std::string parameter;          ///< the other axis ("Scenario/Plate thickness")
  std::string unit;               ///< its unit, when known ("m")
  bool logarithmic = false;       ///< the other axis drawn on a log scale
  std::vector<double> velocities; ///< every velocity of the campaign, increasing
  std::vector<MapModel> models;
  std::vector<MapRow> rows;      ///< in the order of the axis's values
  std::size_t reference_row = 0; ///< the row whose Hunt–Crossley b the thin-plate model takes
  /// A material of the campaign can yield: the rows' calibrations fit the plastic laws too.
  bool can_yield = true;
};

/// A cell's class by the verdict's decisions: 0 .. bands-1 within that band (the tightest one
/// in which it is within), bands outside the loosest, bands + 1 not decided (the FEM's
/// uncertainty as large as the margin), bands + 2 not evaluated (no prediction).
std::size_t map_class(const MapCell& cell);
/// The largest FEM uncertainty (relative) of the judged quantities at the cell, NaN if none
/// is known.
double map_uncertainty(const MapCell& cell);

/// One row of a validity map: a value of the other axis and the campaign's runs there.
struct MapRowRuns {
  std::string parameter; ///< the other axis ("Scenario/Plate thickness")
  SweepValue value;
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

/// A row of a two-axis campaign by its place on the other axis: the axis, its value there and
/// the axis's unit ("m"; "" when not known).
struct MapRowAt {
  std::string parameter;
  SweepValue value;
  std::string unit;
};

/// The row of a two-axis campaign that the report's sections after the map detail: its runs
/// (with the campaign's problems) and where it lies.
struct MapDetailRow {
  Campaign campaign;
  MapRowAt at;
};

/// The row of a two-axis campaign (velocity x one other parameter) that the report's sections
/// after the map detail, as a velocity campaign of its own: the runs with the largest
/// Scenario/Plate thickness (the most massive plate, nearest to the reduced models'
/// assumption), else those at the other axis's first value. Nothing for any other campaign
/// (its sections show every run).
std::optional<MapDetailRow> map_detail_row(const Campaign& campaign);

// Shared by the assessment and the report (namespace detail: not for a reader of the API).
namespace detail {

/// The judged quantity with the largest |error| at the cell, and that error.
std::optional<std::pair<Quantity, double>> map_worst_error(const MapCell& cell);

} // namespace detail

} // namespace impact::postprocess
