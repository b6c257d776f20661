#pragma once
// Machine-readable output of the impact-reduced tool: JSON objects and CSV tables.
// Both refuse to print NaN or Inf: a non-finite result is an internal error, never data. A
// result that has no value in some cases is written so on purpose: null in JSON, an empty
// field in a CSV column declared optional.

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace impact::cli {

using Json = nlohmann::ordered_json;

/// Prints `object` as indented JSON; throws std::runtime_error if any number is not finite.
void print_json(std::ostream& out, const Json& object);

/// A CSV table: a header line with the column names, then one line per row, numbers with
/// 17 significant digits (exact round trip). NaN in one of the `optional` columns is written
/// as an empty field (no value); throws std::runtime_error on any other non-finite value.
void print_csv(std::ostream& out, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows,
               const std::vector<std::string>& optional = {});

} // namespace impact::cli
