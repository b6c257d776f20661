#pragma once
// Reading the calibration JSON for the report: a missing member or a non-number is not an
// error there, it is shown as "n/a".

#include <nlohmann/json.hpp>

#include <limits>
#include <string>

namespace impact::postprocess::detail {

/// node[key], or null when `node` is not an object or has no such member.
inline const nlohmann::json& member(const nlohmann::json& node, const std::string& key) {
  static const nlohmann::json null_value;
  if (!node.is_object()) return null_value;
  const auto found = node.find(key);
  return found == node.end() ? null_value : *found;
}

/// The number `node` holds, or NaN.
inline double number(const nlohmann::json& node) {
  return node.is_number() ? node.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

} // namespace impact::postprocess::detail
