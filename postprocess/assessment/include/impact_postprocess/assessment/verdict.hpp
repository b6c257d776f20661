#pragma once
/// @file
/// The verdict's decisions (verdict.cpp): within, outside or not decided in each tolerance
/// band, against the FEM's own uncertainty; why the calibrated model fails; how the per-run
/// damping varies with V; and where the FEM itself yields. Numbers and decisions only: the
/// report words them (report/src/verdict_words.cpp).

#include "impact_postprocess/impact_quantities.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The decision for one model at one run and tolerance.
enum class Decision { within, outside, undecided, unknown };

/// Where a model holds within one tolerance.
struct ToleranceVerdict {
  double tolerance;
  std::vector<Decision> decisions;            ///< per run
  std::optional<std::array<double, 2>> range; ///< widest contiguous velocity range within
  std::size_t range_runs = 0;                 ///< the runs in that range
};

struct ModelVerdict {
  std::string model_key; ///< ReportModel::key
  bool out_of_sample = false;
  std::vector<ToleranceVerdict> tolerances;
};

/// Why a campaign has no verdict: there is no calibration, it has no campaign fit, or its fit
/// did not converge.
struct NoVerdict {
  enum class Kind { no_calibration, not_fitted, not_converged } kind;
  std::string reason; ///< not_fitted: the calibration's own reason ("" when it gives none)
};

/// Why and where the calibrated model fails, judged in the tightest band (verdict.cpp): its
/// largest error of all, and the quantity that breaks first (the fewest velocities within the
/// band, the larger error among equals) with its errors at every run.
struct FailureCause {
  double tolerance;        ///< the tightest band
  bool holds = false;      ///< the largest error is within it: the model holds everywhere
  double worst_error = 0;  ///< signed, relative
  Quantity worst_quantity; ///< where the largest error is
  std::size_t worst_run = 0;
  Quantity first_breaking;                   ///< the quantity that breaks first (when !holds)
  std::size_t first_breaking_within = 0;     ///< its velocities within the band
  std::vector<double> first_breaking_errors; ///< its signed errors per run (NaN: none)
};

/// How the per-run b (from the restitution) varies with V: the least-squares line through
/// the runs that have one (verdict.cpp).
struct DampingTrend {
  double first_velocity, last_velocity; ///< m/s, of the first and last run with a b
  double first, last;                   ///< b [s/m] there
  double low, high;                     ///< the smallest and largest b [s/m]
  double change; ///< the line's change over the tested range, relative to the mean b
  /// |change| <= 2 % and the spread <= 4 % of the mean: b is constant within 2 %.
  bool constant = false;
};

/// Where the viscoelastic FEM model itself is not valid: the runs above the yield strength.
/// With an elastic-plastic material the FEM is valid above yield: then plastic_material is set
/// and first_yielding_velocity stays empty (no velocity is flagged).
struct PlasticityCheck {
  bool recorded = false;         ///< some run records a yield strength and its stress
  bool plastic_material = false; ///< the FEM's material is elastic-plastic
  std::optional<double> first_yielding_velocity; ///< m/s, the lowest tested velocity that yields
  std::optional<double>
      onset_estimate; ///< m/s, log-log interpolation of the stress to the yield strength
  /// Indices in the assessment's runs: the first that yields (by the viscoelastic FEM's
  /// stress, or the elastic-plastic FEM's own record), the last below yield before it.
  std::optional<std::size_t> first_yielding_run, last_elastic_run;
};

} // namespace impact::postprocess
