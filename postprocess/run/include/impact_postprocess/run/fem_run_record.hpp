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
#include "impact_postprocess/impact_quantities.hpp"
#include "impact_postprocess/run/verification.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The FEM's energy balance at the end of a run may miss the initial energy by at most this
/// fraction of it (fem/README.md, "Time integration": the O(dt^2) of the scheme closes to a
/// few 1e-5 at the end; 1e-4 is the target the FEM's benchmarks check). A run above it is
/// flagged, as a force oscillation above force_oscillation_warning is.
inline constexpr double energy_balance_target = 1e-4;

/// The name of the entry of a run that records only the largest stress over both bodies.
inline constexpr const char* both_bodies = "both bodies";

/// One body's largest von Mises stress against that body's own yield strength.
struct BodyStress {
  /// "Sphere" or "Plate"; "both bodies" when the run records only the largest stress over
  /// both (then against the smallest yield strength it records).
  std::string body;
  std::optional<double> max_von_mises;  ///< Pa
  std::optional<double> yield_strength; ///< Pa, the smallest the body records
  std::string yield_source;             ///< the key it was read from
  /// The FEM's own flag for the body (yield_exceeded_<body>), else stress above strength;
  /// none without both.
  std::optional<bool> yields;
  /// max_von_mises / yield_strength, NaN without both.
  double ratio() const;
};

struct FemRunRecord {
  std::optional<double> energy_error; ///< max |balance error| / initial energy
  /// The balance error at the end of the run / initial energy (signed; summary key
  /// energy_error_final): what energy_balance_target judges.
  std::optional<double> energy_error_final;
  std::optional<double> lost_energy_fraction;
  std::optional<double> dissipated_energy_fraction;
  std::optional<double> radiated_energy_fraction;
  /// Each body's stress against its own yield strength (the sphere's, then the plate's).
  std::vector<BodyStress> bodies;
  /// Of the body nearest to (or furthest past) its own yield strength, the largest ratio of
  /// `bodies` (without a strength: the largest stress): its stress, its strength and the key
  /// of the strength. A stress is never judged against another body's strength.
  std::optional<double> max_von_mises;  ///< Pa
  std::optional<double> yield_strength; ///< Pa
  std::string yield_source;             ///< the key it was read from
  /// The run exceeded a yield strength: the FEM's own flag (yield_exceeded), else a body whose
  /// stress exceeds its own strength; none without a yield strength.
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
