#pragma once
/// @file
/// The numerical uncertainty of one FEM run from impact-fem's verification mode: the run on
/// three systematically refined discretisations (refinement ratio r, space and time
/// together), and for each derived quantity its observed order, Richardson-extrapolated value
/// and Roache's grid convergence index of the fine value (safety factor 1.25, ASME V&V 20).
/// File `verification.json` beside the run's summary:
///     {"format": "impact-verification", "format_version": 1, "refinement_ratio": r,
///      "levels": [{"name": "fine", ...}, ...],
///      "quantities": {"contact_time": {"unit", "fine", "medium", "coarse", "observed_order",
///                     "extrapolated", "gci_fine", "gci_fine_absolute", "convergence"}, ...}}
/// (quantities contact_time, force_max, time_force_max, approach_max, restitution; null
/// where the three values do not allow an order).

#include "impact_postprocess/run/fem_run.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace impact::postprocess {

struct VerifiedQuantity {
  std::string unit;
  double fine, medium, coarse; ///< the three values (the run's own is the fine one)
  double observed_order;       ///< NaN when not defined (oscillatory, converged)
  double extrapolated;         ///< Richardson value, NaN when not defined
  double gci_fine;             ///< relative GCI of the fine value (fraction), NaN if none
  double gci_fine_absolute;    ///< absolute GCI (unit of the quantity), NaN if none
  std::string convergence;     ///< "monotone", "oscillatory", "divergent", "converged"
};

struct Verification {
  std::string source; ///< the file read
  double refinement_ratio;
  std::map<std::string, VerifiedQuantity> quantities; ///< by summary key
};

/// The verification of the run read from `run_source` (its HDF5 file): verification.json in
/// the same directory, none if there is no such file. Throws RunInputError naming the file
/// and the key for a file that is not such a verification.
std::optional<Verification> read_verification(const std::filesystem::path& run_source);

} // namespace impact::postprocess
