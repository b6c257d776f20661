#pragma once
// The validity map in words (map_words.cpp): the names of the swept parameter and its values,
// the map's models and how each is obtained, where each is valid, a cell's class, why a model
// has no value. The map section, its figures and the pipeline's row names use them.

#include "impact_postprocess/report/report.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

/// "Plate thickness" of "Scenario/Plate thickness".
std::string short_name(const std::string& parameter);
/// A sweep value with its unit ("0.05 m"; a text value as it is).
std::string with_unit(const SweepValue& value, const std::string& unit);
/// A row of the map by its value: "Plate thickness = 0.05".
std::string map_row_name(const std::string& parameter, const SweepValue& value);
/// The row the sections after the map detail: "Plate thickness = 0.05 m".
std::string detail_row_name(const MapRowAt& row);

/// Why a campaign with sweep axes has no map (ValidityMap::axes).
std::string no_map_words(const ValidityMap& map);
/// A model of the map by its key: "calibrated Hunt–Crossley", "thin-plate model", ...
std::string map_model_label(const std::string& key);
/// How a model of the map is obtained on each row.
std::string map_basis_words(const ValidityMap& map, const MapModel& model);
/// Where the map's model `model` is valid, in a sentence: "calibrated Hunt–Crossley is within
/// 2 % for Plate thickness >= 0.04 m at every velocity (and so within 5 %)."
std::string map_region_words(const ValidityMap& map, std::size_t model,
                             const std::vector<double>& tolerances);
/// A cell's class (map_class): "within 2 %", "outside 5 %", "not decided", "not evaluated".
std::string map_class_words(std::size_t map_class, const std::vector<double>& tolerances);
/// The values a model uses on one row ("" when it has none).
std::string map_parameters_words(const ValidityMap& map, const MapModelRow& row);
/// Why a model has no value on a row or at a cell ("" when it has one).
std::string map_no_value_words(const ValidityMap& map, const std::optional<NoValue>& missing);

} // namespace impact::postprocess::detail
