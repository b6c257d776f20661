#include "output.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impact::cli {

namespace {
void require_all_finite(const Json& value, const std::string& key) {
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    throw std::runtime_error("result '" + key + "' is not finite");
  if (value.is_object())
    for (const auto& [child_key, child] : value.items()) require_all_finite(child, child_key);
  if (value.is_array())
    for (const auto& child : value) require_all_finite(child, key);
}
} // namespace

void print_json(std::ostream& out, const Json& object) {
  require_all_finite(object, "");
  out << object.dump(2) << '\n';
}

void print_csv(std::ostream& out, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows,
               const std::vector<std::string>& optional) {
  const auto is_optional = [&](std::size_t j) {
    return std::find(optional.begin(), optional.end(), columns.at(j)) != optional.end();
  };
  for (const auto& row : rows)
    for (std::size_t j = 0; j < row.size(); ++j)
      if (!std::isfinite(row[j]) && !(std::isnan(row[j]) && is_optional(j)))
        throw std::runtime_error("column '" + columns.at(j) + "' is not finite");
  for (std::size_t j = 0; j < columns.size(); ++j) out << (j ? "," : "") << columns[j];
  out << '\n';
  const auto old_precision = out.precision(17);
  for (const auto& row : rows) {
    for (std::size_t j = 0; j < row.size(); ++j) {
      if (j) out << ',';
      if (!std::isnan(row[j])) out << row[j];
    }
    out << '\n';
  }
  out.precision(old_precision);
}

} // namespace impact::cli
