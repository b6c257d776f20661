#pragma once
/// @file
/// The law to recommend (recommendation.cpp): every ranked law judged by the verdict's rule
/// in the loosest band.

#include "impact_postprocess/assessment/verdict.hpp"
#include "impact_postprocess/impact_quantities.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// Why a law is not within the band at a run, measured from the calibration (the verdict's
/// rule, the fit to every velocity and the fit without this one).
enum class BreakCause {
  /// Not decided: the band lies within |error| ± U, the FEM's own uncertainty U leaves it open.
  fem_uncertainty,
  /// Beyond the band also in the fit to every velocity, or nothing is fitted: no parameters the
  /// law was given follow the FEM there (the law's shape, or for a law from the material its
  /// constants).
  law_shape,
  /// Within the band in the fit to every velocity, beyond it in the fit without this velocity:
  /// what the other velocities say of the parameters does not carry over to this one.
  held_out,
};

/// A run at which a law is not within the band: the quantity that keeps it out and why.
struct BreakingRun {
  std::size_t run;   ///< index in the report's runs
  Quantity quantity; ///< the largest |error| - U of those with |error| + U beyond the band
  BreakCause cause;
  double error;           ///< out of sample, signed relative
  double uncertainty;     ///< the FEM's U of the quantity, relative (NaN: not recorded)
  double in_sample_error; ///< of the fit to every velocity (the same for a law with nothing fitted)
  bool fitted;            ///< the law has a fit (false: its parameters come from the material)
  /// held_out: the fitted parameter that moves most (relative to the fit to every velocity),
  /// its value in that fit and in the fit without this velocity; "" otherwise.
  std::string parameter;
  std::string unit;
  double fitted_value = 0;
  double held_out_value = 0;
};

/// A ranked law judged at every run of the report by the verdict's rule (decide, with the
/// FEM's uncertainty) in the loosest band: where it holds, and its largest error.
struct JudgedLaw {
  std::string key;   ///< the calibration's key (its ranking)
  std::string label; ///< as the page names it
  std::size_t rank;  ///< 0-based, in the calibration's ranking
  double score;      ///< the ranking's RMS error
  /// The errors judged are out of sample (fitted without the velocity, or nothing fitted). A
  /// fit scored in sample (fewer than three velocities) is never said to hold: its errors are
  /// those of the runs it was fitted to.
  bool out_of_sample = false;
  /// F = c x^n (1 + b x') with a constant b or b(V) = b_1 V^-q: the law a multibody code takes
  /// as it is (Simbody's HuntCrossleyForce, the force of the block "For a multibody code").
  bool hunt_crossley_form = false;
  std::vector<Decision> decisions; ///< per report run, in the loosest band
  /// The runs where it is not within and has a prediction, in run order.
  std::vector<BreakingRun> breaks;
  std::size_t within = 0;    ///< runs within
  double worst_error;        ///< largest |relative error| of the judged quantities (signed)
  Quantity worst_quantity;   ///< where it is
  std::size_t worst_run = 0; ///< at which report run
};

/// An export run in its simulator (Assessment::simulators) against the FEM: its largest error.
struct ExportError {
  std::size_t simulator; ///< index in Assessment::simulators
  double worst_error;    ///< largest |relative error| of the tool's own measurement (signed)
  Quantity worst_quantity;
  double velocity; ///< m/s, where it is
};

/// The law to recommend, by the verdict's rule in the loosest band (5 %): one that holds where
/// it is recommended, or none, with the law and the export that come closest.
struct LawRecommendation {
  double tolerance = 0;        ///< the loosest band of the report
  std::vector<JudgedLaw> laws; ///< every ranked law that could be judged, in rank order
  /// Index in laws: the out-of-sample law within at the most tested velocities, the better
  /// ranked among equals; none when no law holds anywhere.
  std::optional<std::size_t> recommended;
  /// Index in laws: the same among the Hunt–Crossley forms (the block for a multibody code).
  std::optional<std::size_t> multibody;
  /// Runs at which no out-of-sample law is within the band.
  std::vector<std::size_t> uncovered;
  /// Index in laws: the law ranked first (out of sample where one is), the closest when
  /// none holds; none without a ranking.
  std::optional<std::size_t> closest;
  /// The export closest to the FEM in its simulator, when the simulators' runs are given.
  std::optional<ExportError> closest_export;
};

} // namespace impact::postprocess
