#pragma once
/// @file
/// The calibration as JSON (layout documented in postprocess/README.md): every fitted value
/// with its standard error, confidence interval and unit; fit quality per run and per
/// campaign; the out-of-sample predictions and jackknife intervals; the reference models;
/// the ranking; the problems met; and a "multibody" block with the recommended Hunt–Crossley
/// parameters. Non-finite numbers are written as null. The reader turns such a file back
/// into the typed structures of calibration.hpp (null numbers become NaN).

#include "impact_postprocess/calibration/calibration.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace impact::postprocess {

/// Version of the JSON layout; incremented when a key changes meaning or disappears.
/// 2: ranking by out-of-sample error over every model (fitted and reference), the combined
/// and b(V) fits, held-out fits and jackknife intervals, reference models, restitution maps.
inline constexpr int calibration_format_version = 2;

nlohmann::json to_json(const Calibration& calibration);

/// A calibration JSON that cannot be read: `what()` names the key and the problem.
class CalibrationFormatError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Reads what to_json writes (format "impact-calibration", format_version 2). Throws
/// CalibrationFormatError for another format or version, a missing key or a value of the
/// wrong type.
Calibration calibration_from_json(const nlohmann::json& json);

/// The model's recommendation for a multibody code: the Hunt–Crossley fit with the smaller
/// out-of-sample score (force histories, or with the energy loss), else the force-history
/// fit, else a single run's; null without any.
const ModelFit* recommended_hunt_crossley(const Calibration& calibration, std::string* basis);

} // namespace impact::postprocess
