// The validity map in words (map_words.hpp): the assessment says which rows, classes and
// reasons (validity_map.hpp), the page says them here.

#include "map_words.hpp"
#include "model_words.hpp"

#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/number_format.hpp"

#include <algorithm>
#include <cmath>

namespace impact::postprocess::detail {

namespace {

// The rows of `rows` as a sentence part: "Plate thickness >= 0.02 m" (a contiguous range at an
// end of an ordered axis), "every Plate thickness tested", "Plate thickness = 0.005 and
// 0.05 m"; "" for none.
std::string rows_words(const ValidityMap& map, const std::vector<std::size_t>& full) {
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

// Where the model is within one band: "for Plate thickness >= 0.04 m at every velocity (in
// part at 0.004 m at V = 0.5 to 1 m/s)".
std::string where_words(const ValidityMap& map, const MapRegion& region) {
  const std::string full = rows_words(map, region.rows);
  std::string where = full.empty() ? std::string("at every velocity for no tested value")
                                   : "for " + full + " at every velocity";
  if (!region.partly.empty()) {
    where += " (in part at ";
    for (std::size_t k = 0; k < region.partly.size(); ++k)
      where += (k ? "; " : "") + with_unit(map.rows[region.partly[k].first].value, map.unit) +
               " at V = " + velocity_list(region.partly[k].second);
    where += ")";
  }
  return where;
}

// "Plate thickness = 0.004 m, 0.04 m" of the rows.
std::string row_values(const ValidityMap& map, const std::vector<std::size_t>& rows) {
  std::string text = short_name(map.parameter) + " = ";
  for (std::size_t k = 0; k < rows.size(); ++k)
    text += (k ? ", " : "") + with_unit(map.rows[rows[k]].value, map.unit);
  return text;
}

} // namespace

std::string short_name(const std::string& parameter) {
  const auto slash = parameter.rfind('/');
  return slash == std::string::npos ? parameter : parameter.substr(slash + 1);
}

std::string with_unit(const SweepValue& value, const std::string& unit) {
  return value.text + (unit.empty() || !value.number ? "" : " " + unit);
}

std::string map_row_name(const std::string& parameter, const SweepValue& value) {
  return short_name(parameter) + " = " + value.text;
}

std::string detail_row_name(const MapRowAt& row) {
  return map_row_name(row.parameter, row.value) + (row.unit.empty() ? "" : " " + row.unit);
}

std::string no_map_words(const ValidityMap& map) {
  std::string names;
  for (const auto& axis : map.axes) names += (names.empty() ? "" : ", ") + axis;
  return "the campaign has " + std::to_string(map.axes.size()) + " axes (" + names +
         "); a validity map needs exactly two: " + velocity_axis +
         " and one other parameter. No map is shown; the sections below treat all runs "
         "as one velocity campaign.";
}

std::string map_model_label(const std::string& key) {
  if (key == model_keys::calibrated) return "calibrated Hunt–Crossley";
  if (key == model_keys::best_law) return "the row's best law";
  if (key == model_keys::thin_plate) return "thin-plate model";
  if (key == model_keys::massive_plate) return "massive-plate model";
  return key;
}

std::string map_basis_words(const ValidityMap& map, const MapModel& model) {
  if (model.key == model_keys::calibrated)
    return "the row's campaign fit of c, n, b to the force histories, each velocity judged by "
           "the fit without it";
  if (model.key == model_keys::best_law)
    return std::string(
               "the comparison law ranked first on the row by out-of-sample error, "
               "judged out of sample") +
           (map.can_yield
                ? ""
                : "; the plastic laws (Thornton, Jackson–Green and Hunt–Crossley on their "
                  "springs) are not fitted: no material of the campaign can yield, so their "
                  "yield parameter would only stand in for the viscous loss");
  if (model.key == model_keys::thin_plate)
    return "Zener: Hertz contact (c from the run's materials, n = 3/2) on an infinite Kirchhoff "
           "plate of the run's thickness and material (Z = 8 sqrt(D rho h)), with the "
           "Hunt–Crossley damping b that makes it reproduce the FEM restitution of the most "
           "massive plate at the same velocity (the material's damping; in sample on that row, a "
           "prediction on the others)";
  if (model.key == model_keys::massive_plate)
    return "the thin-plate model's contact on a rigid support instead of the plate: Hertz c, "
           "n = 3/2 and the b that makes it reproduce the FEM restitution of the most massive "
           "plate at the same velocity — what a contact law calibrated on the massive plate "
           "predicts for the others (the row where it leaves the bands is where the "
           "massive-plate assumption fails)";
  return "";
}

std::string map_region_words(const ValidityMap& map, std::size_t model,
                             const std::vector<double>& tolerances) {
  const MapModel& entry = map.models[model];
  std::string text, previous;
  for (std::size_t band = 0; band < tolerances.size() && band < entry.within.size(); ++band) {
    const std::string where = where_words(map, entry.within[band]);
    if (where == previous) {
      text += " (and so within " + band_name(tolerances[band]) + ")";
      continue;
    }
    text += (text.empty() ? map_model_label(entry.key) + " is " : "; ") + std::string("within ") +
            band_name(tolerances[band]) + " " + where;
    previous = where;
  }
  text += ".";
  if (!entry.undecided_rows.empty())
    text += " Not decided (FEM uncertainty as large as the margin) at some velocities of " +
            row_values(map, entry.undecided_rows) + ".";
  if (!entry.unevaluated_rows.empty())
    text += " Not evaluated at " + row_values(map, entry.unevaluated_rows) + " (see the table).";
  return text;
}

std::string map_class_words(std::size_t map_class, const std::vector<double>& tolerances) {
  if (map_class < tolerances.size()) return "within " + band_name(tolerances[map_class]);
  if (map_class == tolerances.size()) return "outside " + band_name(tolerances.back());
  if (map_class == tolerances.size() + 1) return "not decided";
  return "not evaluated";
}

std::string map_parameters_words(const ValidityMap& map, const MapModelRow& row) {
  if (row.basis) return parameters_words(*row.basis, row.parameters);
  if (!row.plate) return "";
  // The thin-plate model's c, Z and lambda at the row's first run, then b at each velocity.
  std::string text;
  for (std::size_t k = 0; k < row.plate->damping.size(); ++k) {
    if (k == 0) {
      if (const auto& first = row.plate->first) {
        text += "c = " + significant(first->stiffness, 4) + " N/m^1.5, n = 1.5, ";
        text += std::isinf(first->impedance)
                    ? std::string("rigid support")
                    : "Z = " + significant(first->impedance, 4) +
                          " N s/m, lambda = " + significant(first->zener_lambda, 4) + " at " +
                          significant(first->velocity, 4) + " m/s";
      }
      text += "; b = ";
    } else {
      text += ", ";
    }
    text += short_number(row.plate->damping[k].second) + " s/m at " +
            short_number(row.plate->damping[k].first) + " m/s";
  }
  return text + " (b from the row " + with_unit(map.rows[map.reference_row].value, map.unit) +
         (row.out_of_sample ? ")" : ", this row: its e in sample)");
}

std::string map_no_value_words(const ValidityMap& map, const std::optional<NoValue>& missing) {
  if (missing && missing->reason == NoValueReason::no_reference_run)
    return "the row " + with_unit(map.rows[map.reference_row].value, map.unit) +
           " (the most massive plate) has no run at this velocity whose restitution the model "
           "reproduces";
  return no_value_words(missing);
}

} // namespace impact::postprocess::detail
