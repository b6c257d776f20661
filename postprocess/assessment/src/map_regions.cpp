// Where each model of a validity map (validity_map.hpp, ValidityMap) is valid, from the cells'
// classes: in each band the rows where every cell is within it and those where some are; the
// rows with a cell not decided and those where the model cannot be evaluated. The report words
// it (report/src/map_words.cpp).

#include "steps.hpp"

namespace impact::postprocess::detail {

void add_map_region(ValidityMap& map, std::size_t model, std::size_t bands) {
  MapModel& entry = map.models[model];
  entry.within.assign(bands, {});
  for (std::size_t band = 0; band < bands; ++band)
    for (std::size_t r = 0; r < map.rows.size(); ++r) {
      const MapModelRow& row = map.rows[r].models[model];
      if (row.cells.empty()) continue;
      std::vector<double> velocities;
      for (const auto& cell : row.cells)
        if (class_index(cell) <= band) velocities.push_back(cell.velocity);
      if (velocities.size() == row.cells.size())
        entry.within[band].rows.push_back(r);
      else if (!velocities.empty())
        entry.within[band].partly.push_back({r, std::move(velocities)});
    }
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    const MapModelRow& at = map.rows[r].models[model];
    if (at.missing) entry.unevaluated_rows.push_back(r);
    for (const auto& cell : at.cells)
      if (!at.missing && class_index(cell) == bands + 1) {
        entry.undecided_rows.push_back(r);
        break;
      }
  }
}

} // namespace impact::postprocess::detail
