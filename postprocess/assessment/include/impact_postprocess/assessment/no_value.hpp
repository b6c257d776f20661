#pragma once
/// @file
/// Why a reduced model has no value: at a run of the compared models (compared_models.cpp), on
/// a row or at a cell of the validity map (validity_map.cpp, map_plate_models.cpp). The report
/// words it (report/src/model_words.cpp, map_words.cpp).

#include "impact_postprocess/assessment/verdict.hpp"

#include <optional>
#include <string>

namespace impact::postprocess {

/// The reason; `NoValue::detail` carries what the words need where the entry says so.
enum class NoValueReason {
  // A compared model at a run.
  no_calibration,        ///< the report was given no calibration
  no_comparison_law,     ///< the calibration has no fitted comparison law
  prediction_incomplete, ///< the calibration's prediction is incomplete (detail: model key)
  no_prediction_for_run, ///< the calibration predicts other runs only (detail: model key)
  not_evaluable,         ///< a model that fits nothing cannot be evaluated at the run
  no_run_fit,            ///< no force-history fit of the run (per-run fits)
  no_run_fit_prediction, ///< the run's own fit has no prediction (per-run fits)
  no_history,            ///< the force history failed (detail: the reduced library's message)
  // A model on a row of the validity map.
  no_comparison_law_on_row, ///< the row's calibration has no comparison law
  no_model_on_row,          ///< the row's calibration has no such model
  no_verdict,               ///< the row has no verdict (NoValue::verdict says why)
  no_run_at_value,          ///< the campaign has no run at the row's value
  no_fem_result_on_row,     ///< no run of the row has an FEM result
  thickness_not_recorded,   ///< the runs do not record Scenario/Plate thickness
  // A cell of the validity map.
  no_prediction,      ///< the model gives no figures at the run
  no_fem_result,      ///< the FEM run has no result (detail: the reader's message)
  no_reference_run,   ///< the row of the most massive plate has no run at this velocity
  plate_not_recorded, ///< the run does not record the plate's or the sphere's constants
  thin_plate_failed,  ///< the thin-plate model failed (detail: the reduced library's message)
};

/// Why a model has no value, with the detail its words need ("" where none).
struct NoValue {
  NoValueReason reason;
  std::string detail;
  std::optional<NoVerdict> verdict = {}; ///< no_verdict: why the row has none
};

} // namespace impact::postprocess
