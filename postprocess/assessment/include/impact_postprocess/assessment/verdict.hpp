#pragma once
/// @file
/// The verdict's decisions (verdict.cpp): within, outside or not decided in each tolerance
/// band, against the FEM's own uncertainty; and where the FEM itself yields.

#include <array>
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
  std::string text;                           ///< the verdict in words
};

struct ModelVerdict {
  std::string model_key; ///< ReportModel::key
  bool out_of_sample = false;
  std::vector<ToleranceVerdict> tolerances;
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
  std::string text;
};

// Shared by the assessment and the report (namespace detail: not for a reader of the API).
namespace detail {

/// "2 %".
std::string band_name(double tolerance);

} // namespace detail

} // namespace impact::postprocess
