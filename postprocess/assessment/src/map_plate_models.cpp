// The plate models of a validity map (validity_map.hpp, ValidityMap): the thin-plate model (Zener)
// and the same contact on a rigid support, both with the material's damping taken from the
// row of the most massive plate, judged on every row by the verdict's rule.

#include "steps.hpp"

#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

namespace {

// The plate thickness of a row: the axis value when the axis is the thickness, else the
// runs' own parameter (NaN when they do not record it).
double row_thickness(const std::string& parameter, const SweepValue& value,
                     const std::vector<FemRun>& runs) {
  if (parameter == fem_format::plate_thickness.path && value.number) return *value.number;
  for (const auto& run : runs)
    if (const auto thickness = text_number(run, fem_format::plate_thickness.path))
      return *thickness;
  return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

// The material's damping at each velocity from the row of the most massive (thickest)
// plate: the b with which the model itself reproduces that row's FEM restitution at the same
// velocity (in sample on that row, a prediction on the others). The models with it: Zener's
// thin plate, and the same contact on a rigid support (what a massive-plate law predicts).
void add_plate_models(ValidityMap& map, const Assessment& report, const MapRowReports& rows) {
  double thickest = -INFINITY;
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    const double h = row_thickness(map.parameter, map.rows[r].value, rows.runs[r]);
    if (std::isfinite(h) && h > thickest && !rows.runs[r].empty()) {
      thickest = h;
      map.reference_row = r;
    }
  }
  for (const bool rigid : {false, true}) {
    std::vector<std::pair<double, std::optional<double>>> reference_damping; // V, b
    if (std::isfinite(thickest))
      for (const FemRun& run : rows.runs[map.reference_row])
        reference_damping.push_back({run.impact_velocity, thin_plate_damping(run, rigid)});
    for (std::size_t r = 0; r < map.rows.size(); ++r) {
      MapModelRow model;
      const Assessment& row_report = rows.reports[r];
      if (rows.runs[r].empty())
        model.missing = NoValue{NoValueReason::no_run_at_value, ""};
      else if (!std::isfinite(thickest))
        model.missing = NoValue{NoValueReason::thickness_not_recorded, ""};
      std::vector<std::optional<ImpactFigures>> judged;
      PlateModelValues values;
      for (std::size_t i = 0; i < rows.runs[r].size(); ++i) {
        const ReportRun& run = row_report.runs[i];
        MapCell cell{run.velocity,    run.source, run.fem,    std::nullopt,
                     run.uncertainty, {},         run.yields, std::nullopt};
        if (!model.missing) {
          const auto at = std::find_if(reference_damping.begin(), reference_damping.end(),
                                       [&](const auto& entry) {
                                         return same_velocity(entry.first, run.velocity);
                                       });
          if (at == reference_damping.end() || !at->second) {
            cell.missing = NoValue{NoValueReason::no_reference_run, ""};
          } else {
            const double b = *at->second;
            const ThinPlatePrediction prediction = thin_plate_prediction(rows.runs[r][i], b, rigid);
            cell.judged = prediction.quantities;
            cell.missing = prediction.missing;
            if (values.damping.empty()) values.first = prediction.values;
            values.damping.push_back({run.velocity, b});
          }
        } else {
          cell.missing = model.missing;
        }
        judged.push_back(cell.judged);
        model.cells.push_back(std::move(cell));
      }
      if (!model.missing) {
        model.out_of_sample = r != map.reference_row;
        model.plate = std::move(values);
        for (double tolerance : report.tolerances) {
          const ToleranceVerdict verdict =
              tolerance_verdict(row_report, judged, tolerance,
                                {map_quantities.begin(), map_quantities.end()});
          for (std::size_t i = 0; i < model.cells.size(); ++i)
            model.cells[i].decisions.push_back(verdict.decisions[i]);
        }
      }
      map.rows[r].models.push_back(std::move(model));
    }
  }
}

} // namespace impact::postprocess::detail
