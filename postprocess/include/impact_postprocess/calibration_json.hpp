#pragma once
/// @file
/// The calibration as JSON (layout documented in postprocess/README.md): every fitted value
/// with its standard error, confidence interval and unit; fit quality per run and per
/// campaign; the problems met; and a "multibody" block with the recommended Hunt–Crossley
/// parameters. Non-finite numbers are written as null.

#include "impact_postprocess/calibration.hpp"

#include <nlohmann/json.hpp>

namespace impact::postprocess {

/// Version of the JSON layout; incremented when a key changes meaning or disappears.
inline constexpr int calibration_format_version = 1;

nlohmann::json to_json(const Calibration& calibration);

} // namespace impact::postprocess
