#pragma once
/// @file
/// The reduced models compared with the FEM at the runs (compared_models.cpp): each model's
/// figures in and out of sample, its history, its force residual and its prediction band.

#include "impact_postprocess/assessment/fem_runs.hpp"
#include "impact_postprocess/assessment/no_value.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// One parameter value of a model, named as the calibration names it ("c", "b", "x_y") with
/// its unit ("N/m^n", "s/m"; "1" for a pure number).
struct ModelParameter {
  std::string name;
  double value;
  std::string unit;
};

/// One reduced model at one run.
struct ModelAtRun {
  std::optional<ImpactFigures> in_sample;     ///< fitted to all runs (or not fitted at all)
  std::optional<ImpactFigures> out_of_sample; ///< fitted without this velocity
  ImpactHistory history;                      ///< of the in-sample model
  std::vector<double> residual;   ///< (F_model - F_FEM) / F_max at the FEM history's times
  std::optional<NoValue> missing; ///< why there are no values (none when there are)
  /// The errors the verdict uses: out of sample when there are, else in sample.
  const std::optional<ImpactFigures>& judged() const {
    return out_of_sample ? out_of_sample : in_sample;
  }
};

/// Jackknife prediction band of a fitted model over the tested velocity range: the full
/// fit's prediction and, at each velocity, +- t_{g-1} times the jackknife standard error of
/// the held-out fits' predictions.
struct PredictionBand {
  std::vector<double> velocity;
  std::array<std::vector<double>, quantity_count> center, lower, upper; ///< by Quantity
};

/// Where a compared model's parameters come from.
enum class ModelBasis {
  campaign_fit,         ///< calibrated: one (c, n, b) fitted to the force histories of all runs
  per_run_fits,         ///< calibrated without a campaign fit: each run's own force-history fit
  force_and_energy_fit, ///< the force histories and the energy loss of every run
  velocity_damping_fit, ///< b(V) = b_1 (V / 1 m/s)^-q, histories and energy loss
  best_law,             ///< the comparison law ranked first by out-of-sample error
  best_law_in_sample,   ///< ranked first by in-sample error (fewer than three velocities)
  damped_plastic_fit,   ///< a damped elastic-plastic law: its yield parameter and b fitted
  nothing_fitted,       ///< a model that fits nothing (the calibration's reference model)
  no_calibration,       ///< no values: the report was given no calibration
  no_comparison_law,    ///< no values: the calibration has no fitted comparison law
};

struct ReportModel {
  std::string key;   ///< "calibrated", the calibration's key, "best-law", ...
  std::string label; ///< short name for legends and tables
  /// The values used, c, n, then the dissipation's (none for per-run fits or without values).
  std::vector<ModelParameter> parameters;
  ModelBasis basis = ModelBasis::campaign_fit;
  std::string calibration_key; ///< the model's key in the calibration ("" if none)
  std::size_t free_parameters = 0;
  bool converged = true;        ///< false when its fit did not converge (numbers marked so)
  bool out_of_sample = false;   ///< its judged errors are out of sample
  std::vector<ModelAtRun> runs; ///< parallel to Assessment::runs
  std::optional<PredictionBand> band;
  /// The model's curve over the tested range (no band): velocity and each quantity.
  std::optional<PredictionBand> curve;
};

} // namespace impact::postprocess
