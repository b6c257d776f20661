// The section "Validity map" (sections.hpp): the map of assessment/validity_map.cpp in
// words, figures and one table per model.

#include "map_words.hpp"
#include "sections.hpp"
#include "impact_postprocess/report/verdict_words.hpp"

namespace impact::postprocess::detail {

void map_section(Document& doc, const Report& report, const FigurePlacer& figure) {
  if (!report.map) return;
  const ValidityMap& map = *report.map;
  doc.heading("Validity map");
  if (!map.available) {
    doc.warning("No validity map: " + no_map_words(map));
    return;
  }
  const std::string name = short_name(map.parameter);
  doc.paragraph(
      "The campaign has two axes, the impact velocity and " + map.parameter + ". Each value of " +
      name +
      " is a row: the velocity campaign at that value, calibrated "
      "on its own (every law, as impact-calibrate does) and judged as the verdict judges a "
      "velocity campaign: a cell (one run: a value of " +
      name +
      ", a velocity) is within a band "
      "when every |error| + U of 1 - e^2, t_c and F_max is within it, outside when one "
      "|error| - U exceeds it, not decided in between (U: the FEM's numerical uncertainty of "
      "the run, its GCI from verification.json where it was verified). Errors are out of "
      "sample: each velocity predicted by the row's fit without it. " +
      (!report.detail_row
           ? "The sections after this one treat all runs as one velocity campaign (one "
             "calibration for every " +
                 name + ")."
           : "The sections after this one detail the row " + detail_row_name(*report.detail_row) +
                 " as a velocity campaign (its calibration, verdict, figures and runs)."));
  std::vector<std::string> items;
  for (const auto& model : map.models)
    items.push_back(map_model_label(model.key) + ": " + map_basis_words(map, model) + ".");
  doc.list(items);
  doc.paragraph("Where each model is valid:");
  std::vector<std::string> regions;
  for (std::size_t m = 0; m < map.models.size(); ++m)
    regions.push_back(map_region_words(map, m, report.tolerances));
  doc.list(regions);
  for (std::size_t m = 0; m < map.models.size(); ++m) {
    const MapModel& model = map.models[m];
    doc.heading("Map: " + map_model_label(model.key), 3);
    figure(FigureId::validity_map, model.key);
    Table table;
    table.header = {name + (map.unit.empty() ? "" : " [" + map.unit + "]"),
                    "V [m/s]",
                    "FEM U (largest)",
                    "error 1 - e^2",
                    "error t_c",
                    "error F_max",
                    "class"};
    std::vector<std::string> notes;
    for (const auto& row : map.rows) {
      const MapModelRow& at = row.models[m];
      const std::string parameters = map_parameters_words(map, at);
      if (at.missing)
        notes.push_back(with_unit(row.value, map.unit) +
                        ": not evaluated: " + map_no_value_words(map, at.missing));
      else if (!parameters.empty())
        notes.push_back(with_unit(row.value, map.unit) + ": " + parameters +
                        (at.out_of_sample ? " (out of sample)" : " (in sample)"));
      for (const auto& cell : at.cells)
        if (!cell.fem && cell.missing)
          notes.push_back(with_unit(row.value, map.unit) + ", V = " + short_number(cell.velocity) +
                          " m/s: not evaluated: " + map_no_value_words(map, cell.missing));
      if (at.cells.empty())
        table.rows.push_back({row.value.text, "-", "-", "-", "-", "-", "not evaluated"});
      for (const auto& cell : at.cells) {
        const auto error = [&](Quantity quantity) {
          return cell.judged && cell.fem
                     ? percent_cell(relative_error(*cell.judged, *cell.fem, quantity))
                     : std::string("n/a");
        };
        table.rows.push_back({row.value.text,
                              short_number(cell.velocity) + (cell.yields ? " (yields)" : ""),
                              unsigned_percent(map_uncertainty(cell)), error(Quantity::energy_loss),
                              error(Quantity::contact_time), error(Quantity::force_max),
                              map_class_words(map_class(cell), report.tolerances)});
      }
    }
    doc.table(table);
    doc.list(notes);
  }
}

} // namespace impact::postprocess::detail
