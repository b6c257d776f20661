// The words of a validity map (validity_map.hpp, ValidityMap): each model's region of validity as
// a sentence, from the cells' classes; the names and values of the swept parameter.

#include "steps.hpp"

#include <algorithm>

namespace impact::postprocess::detail {

namespace {

// The row values where every cell of the model is within `band` (by class), as a sentence
// part: "Plate thickness >= 0.02 m", "Plate thickness = 0.005 and 0.05 m", "no value".
std::string rows_words(const ValidityMap& map, std::size_t model, std::size_t band,
                       std::vector<std::string>& partial) {
  std::vector<std::size_t> full;
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    const MapModelRow& row = map.rows[r].models[model];
    if (row.cells.empty()) continue;
    std::size_t inside = 0;
    for (const auto& cell : row.cells) inside += class_index(cell) <= band ? 1 : 0;
    if (inside == row.cells.size())
      full.push_back(r);
    else if (inside > 0) {
      std::vector<double> velocities;
      for (const auto& cell : row.cells)
        if (class_index(cell) <= band) velocities.push_back(cell.velocity);
      partial.push_back(with_unit(map.rows[r].value, map.unit) +
                        " at V = " + velocity_list(velocities));
    }
  }
  const std::string name = short_name(map.parameter);
  if (full.empty()) return "";
  const bool contiguous = full.back() - full.front() + 1 == full.size();
  const bool ordered = std::all_of(map.rows.begin(), map.rows.end(),
                                   [](const MapRow& row) { return bool(row.value.number); });
  if (contiguous && ordered && full.size() < map.rows.size()) {
    if (full.back() + 1 == map.rows.size())
      return name + " >= " + with_unit(map.rows[full.front()].value, map.unit);
    if (full.front() == 0) return name + " <= " + with_unit(map.rows[full.back()].value, map.unit);
  }
  if (full.size() == map.rows.size()) return "every " + name + " tested";
  std::string list;
  for (std::size_t k = 0; k < full.size(); ++k)
    list += (k == 0 ? "" : k + 1 == full.size() ? " and " : ", ") + map.rows[full[k]].value.text;
  return name + " = " + list + (map.unit.empty() ? "" : " " + map.unit);
}

} // namespace

std::string map_region(const ValidityMap& map, std::size_t model,
                       const std::vector<double>& tolerances) {
  const MapModel& entry = map.models[model];
  std::string text, previous;
  for (std::size_t band = 0; band < tolerances.size(); ++band) {
    std::vector<std::string> partial;
    const std::string full = rows_words(map, model, band, partial);
    std::string where = full.empty() ? std::string("at every velocity for no tested value")
                                     : "for " + full + " at every velocity";
    if (!partial.empty()) {
      where += " (in part at ";
      for (std::size_t k = 0; k < partial.size(); ++k) where += (k ? "; " : "") + partial[k];
      where += ")";
    }
    if (where == previous) {
      text += " (and so within " + band_name(tolerances[band]) + ")";
      continue;
    }
    text += (text.empty() ? entry.label + " is " : "; ") + std::string("within ") +
            band_name(tolerances[band]) + " " + where;
    previous = where;
  }
  std::vector<std::string> missing, undecided;
  for (const auto& row : map.rows) {
    const MapModelRow& at = row.models[model];
    if (!at.missing.empty()) missing.push_back(with_unit(row.value, map.unit));
    for (const auto& cell : at.cells)
      if (at.missing.empty() && class_index(cell) == tolerances.size() + 1) {
        undecided.push_back(with_unit(row.value, map.unit));
        break;
      }
  }
  text += ".";
  if (!undecided.empty()) {
    text += " Not decided (FEM uncertainty as large as the margin) at some velocities of " +
            short_name(map.parameter) + " = ";
    for (std::size_t k = 0; k < undecided.size(); ++k) text += (k ? ", " : "") + undecided[k];
    text += ".";
  }
  if (!missing.empty()) {
    text += " Not evaluated at " + short_name(map.parameter) + " = ";
    for (std::size_t k = 0; k < missing.size(); ++k) text += (k ? ", " : "") + missing[k];
    text += " (see the table).";
  }
  return text;
}

std::string short_name(const std::string& parameter) {
  const auto slash = parameter.rfind('/');
  return slash == std::string::npos ? parameter : parameter.substr(slash + 1);
}

std::string with_unit(const SweepValue& value, const std::string& unit) {
  return value.text + (unit.empty() || !value.number ? "" : " " + unit);
}

} // namespace impact::postprocess::detail
