#pragma once
/// @file
/// The FEM runs as the assessment holds them: what each measured (the calibration's numbers
/// where it has the run), its history around the contact, what it records and its
/// uncertainty; and the one rule by which a run of one list is found in another.

#include "impact_postprocess/impact_quantities.hpp"
#include "impact_postprocess/run/fem_run_record.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// A time history since first contact: time [s], approach [m], contact force [N].
struct ImpactHistory {
  std::vector<double> time;
  std::vector<double> approach;
  std::vector<double> force;
};

struct ReportEstimate {
  double value;
  double lower;
  double upper;
};

/// A force after release above this fraction of the peak is chatter: a quality warning
/// (postprocess/README.md, "A warning on the FEM's quality").
inline constexpr double release_chatter_warning = 1e-3;

/// What the FEM history itself shows that limits its result: each set only beyond its
/// warning threshold (the report words them as warnings of kind quality; the result stays
/// complete).
struct FemQualityWarnings {
  /// The step-to-step oscillation of the force over its peak, above force_oscillation_warning.
  std::optional<double> oscillation;
  /// The force after the first zero that follows the peak, over the peak, above
  /// release_chatter_warning (release chatter).
  std::optional<double> after_release;
  /// The energy error at the end of the run over the impact energy (signed), beyond
  /// energy_balance_target.
  std::optional<double> energy_balance;
  /// The index in Assessment::problems before which the report places these warnings (where
  /// the run's other problems are).
  std::size_t problem_position = 0;
};

struct ReportRun {
  std::string source;
  double velocity;                 ///< m/s
  double mass;                     ///< kg
  ImpactFigures fem;               ///< measured (the calibration's numbers when it has the run)
  ImpactHistory fem_history;       ///< window around the contact, at most ~1500 samples
  bool calibrated = false;         ///< the calibration holds this run
  double damping_from_restitution; ///< b [s/m] of the run (NaN when not calibrated)
  ReportEstimate history_damping;  ///< b of the run's force-history fit
  ReportEstimate history_stiffness;
  ReportEstimate history_exponent;
  FemRunRecord record;
  FemUncertainty uncertainty; ///< of each FEM quantity (relative)
  /// The FEM exceeds the yield strength of a body without plasticity at this run: the flag
  /// "(yields)" (never set when the material is elastic-plastic, FemRunRecord::plastic_material:
  /// that FEM yields and stays valid).
  bool yields = false;
  FemQualityWarnings quality;
};

// Shared by the assessment and the report (namespace detail: not for a reader of the API).
namespace detail {

/// The same run in another list: the same source file, or the same velocity (same_value.hpp).
bool same_source(const std::string& a, const std::string& b);
bool same_velocity(double a, double b);

/// The seed paper's measured range of (1 - e)/V [s/m] (steel, glass, brass; Goldsmith).
inline constexpr double measured_alpha_low = 0.08, measured_alpha_high = 0.32;
/// (1 - e)/V [s/m] of the FEM run (effective_alpha.cpp).
double effective_alpha(const ReportRun& run);

} // namespace detail

/// The FEM's effective alpha (1 - e)/V over the runs (effective_alpha.cpp): its range and how
/// many runs lie below, inside and above the measured range.
struct EffectiveAlpha {
  double low, high; ///< s/m
  std::size_t below = 0, inside = 0, above = 0, count = 0;
};

namespace detail {

/// The effective alpha over the runs; none when no run has one.
std::optional<EffectiveAlpha> effective_alpha(const std::vector<ReportRun>& runs);

} // namespace detail

} // namespace impact::postprocess
