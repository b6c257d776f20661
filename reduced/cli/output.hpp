#pragma once
// Machine-readable output of the impact-reduced tool: JSON objects and CSV tables.
// Both refuse to print NaN or Inf: a non-finite result is an internal error, never data.

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace impact::cli {

using Json = nlohmann::ordered_json;

/// Prints `object` as indented JSON; throws std::runtime_error if any number is not finite.
void print_json(std::ostream& out, const Json& object);

/// A CSV table: a header line with the column names, then one line per row, numbers with
/// 17 significant digits (exact round trip). Throws std::runtime_error on a non-finite value.
void print_csv(std::ostream& out, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows);

} // namespace impact::cli
