#pragma once
/// @file
/// What an FEM run records beyond the histories the calibration fits, and what the report
/// needs to judge the run itself: energy balance, stresses against the yield strength, the
/// smoothness of the force history, its verification, and from these the numerical
/// uncertainty of each compared quantity.
///
/// Read from summary.json beside the run file, else from its "result: <key>" attributes,
/// else (smoothness) measured on the history with the same definitions (force_smoothness.hpp).

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/force_smoothness.hpp"
#include "impact_postprocess/models/impact_quantities.hpp"
#include "impact_postprocess/run/verification.hpp"

#include <array>
#include <optional>
#include <string>

namespace impact::postprocess {

struct FemRunRecord {
  std::optional<double> energy_error; ///< max |balance error| / initial energy
  std::optional<double> lost_energy_fraction;
  std::optional<double> dissipated_energy_fraction;
  std::optional<double> radiated_energy_fraction;
  std::optional<double> max_von_mises;  ///< Pa, largest over both bodies
  std::optional<double> yield_strength; ///< Pa, smallest recorded
  std::string yield_source;             ///< the key it was read from
  /// The run exceeded a yield strength: the FEM's own flag (yield_exceeded) or its largest
  /// von Mises stress above the yield strength; none without a yield strength.
  std::optional<bool> yields;
  /// A body's material model is elastic-plastic ("<Body>/Material model" of the run's
  /// parameters): the FEM itself yields, and stays valid, above the yield strength.
  bool plastic_material = false;
  /// The permanent approach [m] (summary key "permanent_approach" of impact-fem: the approach
  /// at separation, linearly interpolated), else measured the same way on the history at the
  /// end of contact (first contact + t_c); none for a run without plastic material.
  std::optional<double> permanent_approach;
  ForceSmoothness smoothness;
  std::string smoothness_source; ///< "summary.json" or "measured on history.h5"
  double time_step;              ///< s, median step of the history
  double release_span;           ///< s, length of the release chatter
  std::optional<Verification> verification;
  std::string verification_problem; ///< why a verification.json could not be used
};

/// The record of `run` (never throws for what it cannot find: fields stay empty).
FemRunRecord read_fem_run_record(const FemRun& run);

/// The numerical uncertainty of one FEM quantity, relative to its value.
struct QuantityUncertainty {
  double relative;    ///< fraction; NaN when not known
  std::string source; ///< how it was obtained, in words
};
using FemUncertainty = std::array<QuantityUncertainty, quantity_count>;

/// The uncertainty of each quantity of the run: the GCI of its verification where there is
/// one; otherwise what the history shows: the step-to-step oscillation for the peak force
/// (its largest sample lies about half the oscillation above a smooth history's), one time
/// step or the release chatter, whichever is longer, for the contact time, one time step for
/// the time of the peak force; not known for e, 1 - e^2, 1 - e and x_max.
FemUncertainty fem_uncertainty(const FemRunRecord& record, const ImpactFigures& fem);

} // namespace impact::postprocess
