#pragma once
/// @file
/// "The same value" for numbers that travel between the tools through files (velocities,
/// masses, radii, sweep values, the FEM's numbers in a simulator's result file): one rule for
/// every comparison of postprocess/. The files carry doubles without loss (HDF5 doubles,
/// JSON written with 17 significant digits), so two values of the same quantity agree to the
/// last bits; a relative difference of 1e-9 is far beyond rounding and far below any physical
/// difference between two runs of a campaign.

#include <algorithm>
#include <cmath>

namespace impact::postprocess {

/// The relative tolerance of same_value.
inline constexpr double same_value_tolerance = 1e-9;

/// |a - b| <= 1e-9 max(|a|, |b|); false when either is NaN.
inline bool same_value(double a, double b) {
  return std::abs(a - b) <= same_value_tolerance * std::max(std::abs(a), std::abs(b));
}

} // namespace impact::postprocess
