// The validity map of a two-axis campaign (validity_map.hpp, ValidityMap): each value of the
// other axis is a row, a velocity campaign of its own, judged by the verdict itself (assess
// on the row's runs with the row's calibration, made by the report pipeline and handed in);
// the plate models are judged on the same rows by the same rule (map_plate_models.cpp); where
// each model is valid is map_regions.cpp's. The report words them (report/src/map_words.cpp).

#include "steps.hpp"

#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

namespace {

// The tightest band in which the cell is within; else outside the loosest, not decided or
// not evaluated. The class index: 0 .. bands-1 within that band, bands outside, bands + 1
// not decided, bands + 2 not evaluated.
std::size_t class_index_of(const MapCell& cell) {
  const std::size_t bands = cell.decisions.size();
  if (cell.missing || cell.decisions.empty()) return bands + 2;
  for (std::size_t k = 0; k < bands; ++k)
    if (cell.decisions[k] == Decision::within) return k;
  switch (cell.decisions.back()) {
    case Decision::outside:
      return bands;
    case Decision::undecided:
      return bands + 1;
    default:
      return bands + 2;
  }
}

// A row's model cells from the row's own report: the judged predictions and the verdict's
// decisions.
MapModelRow row_model(const Assessment& row, std::string_view key) {
  MapModelRow result;
  const ReportModel* model = row.model(key);
  const ModelVerdict* verdict = row.verdict(key);
  if (!model || !verdict) {
    result.missing = NoValue{key == model_keys::best_law ? NoValueReason::no_comparison_law_on_row
                                                         : NoValueReason::no_model_on_row,
                             ""};
  } else if (key == model_keys::calibrated && !row.verdict_available && row.no_verdict) {
    result.missing = NoValue{NoValueReason::no_verdict, "", row.no_verdict};
  }
  if (model) {
    result.basis = model->basis;
    result.parameters = model->parameters;
    result.out_of_sample = model->out_of_sample;
  }
  for (std::size_t i = 0; i < row.runs.size(); ++i) {
    const ReportRun& run = row.runs[i];
    MapCell cell{run.velocity,    run.source, run.fem,    std::nullopt,
                 run.uncertainty, {},         run.yields, std::nullopt};
    if (model && verdict && !result.missing) {
      cell.judged = model->runs[i].judged();
      cell.missing = model->runs[i].missing;
      if (!cell.judged && !cell.missing) cell.missing = NoValue{NoValueReason::no_prediction, ""};
    } else {
      cell.missing = result.missing;
    }
    result.cells.push_back(std::move(cell));
  }
  // The verdict's rule on the map's quantities (the row's own verdict also judges x_max).
  if (model && verdict && !result.missing) {
    std::vector<std::optional<ImpactFigures>> judged;
    for (const auto& cell : result.cells) judged.push_back(cell.judged);
    for (const auto& band : verdict->tolerances) {
      const ToleranceVerdict decided =
          tolerance_verdict(row, judged, band.tolerance,
                            {map_quantities.begin(), map_quantities.end()});
      for (std::size_t i = 0; i < result.cells.size(); ++i)
        result.cells[i].decisions.push_back(decided.decisions[i]);
    }
  }
  if (model && !result.missing &&
      std::all_of(result.cells.begin(), result.cells.end(),
                  [](const MapCell& cell) { return bool(cell.missing); }))
    result.missing = result.cells.front().missing;
  return result;
}

// A campaign with sweep axes has a map when it has two: the velocity and one other.
bool has_map(const Campaign& campaign) {
  const bool has_velocity =
      std::any_of(campaign.axes.begin(), campaign.axes.end(),
                  [](const SweepAxis& axis) { return axis.parameter == velocity_axis; });
  return campaign.axes.size() == 2 && has_velocity;
}

// The other axis of a map campaign (not the velocity).
const SweepAxis& other_axis(const Campaign& campaign) {
  return campaign.axes.front().parameter == velocity_axis ? campaign.axes.back()
                                                          : campaign.axes.front();
}

// The map's frame: its axis, unit and scale, velocities and models.
void map_frame(ValidityMap& map, const Campaign& campaign, const std::vector<MapRowRuns>& rows) {
  map.available = true;
  map.parameter = other_axis(campaign).parameter;
  map.unit = std::string(fem_format::parameter_unit(map.parameter));
  const bool numeric = std::all_of(rows.begin(), rows.end(),
                                   [](const MapRowRuns& row) { return bool(row.value.number); });
  if (numeric && !rows.empty())
    map.logarithmic = rows.front().value.number > 0.0 &&
                      *rows.back().value.number > 10 * *rows.front().value.number;
  for (const auto& run : campaign.runs)
    if (std::none_of(map.velocities.begin(), map.velocities.end(),
                     [&](double v) { return same_velocity(v, run.impact_velocity); }))
      map.velocities.push_back(run.impact_velocity);
  std::sort(map.velocities.begin(), map.velocities.end());
  map.can_yield = runs_can_yield(campaign.runs);
  for (const std::string_view key : {model_keys::calibrated, model_keys::best_law,
                                     model_keys::thin_plate, model_keys::massive_plate})
    map.models.push_back({std::string(key), {}, {}, {}});
}

// Every row: a velocity campaign with its calibration (handed in, parallel to the rows),
// judged by the verdict (the calibrated Hunt–Crossley law and the row's best law).
MapRowReports judged_rows(ValidityMap& map, const Assessment& report,
                          const std::vector<MapRowRuns>& rows, const AssessmentOptions& options) {
  MapRowReports judged;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const MapRowRuns& runs = rows[r];
    MapRow row{runs.value, {}, false, "", {}};
    Assessment row_report;
    if (!runs.runs.empty()) {
      std::optional<Calibration> calibration;
      if (r < options.map_calibrations.size()) {
        row.calibrated = true;
        calibration = options.map_calibrations[r].calibration;
        row.calibration_error = options.map_calibrations[r].error;
      }
      Campaign row_campaign;
      row_campaign.runs = runs.runs;
      AssessmentOptions row_options;
      row_options.tolerances = report.tolerances;
      row_report =
          assess(row_campaign, calibration, {},
                 report.campaign_source + " (" + runs.parameter + " = " + runs.value.text + ")",
                 "row calibration", row_options);
      if (calibration) row.calibration_problems = calibration->problems;
    }
    for (const std::string_view key : {model_keys::calibrated, model_keys::best_law}) {
      MapModelRow model = row_model(row_report, key);
      if (runs.runs.empty()) model.missing = NoValue{NoValueReason::no_run_at_value, ""};
      row.models.push_back(std::move(model));
    }
    map.rows.push_back(std::move(row));
    judged.runs.push_back(runs.runs);
    judged.reports.push_back(std::move(row_report));
  }
  return judged;
}

// Runs of the index that could not be read (e.g. no rebound within the run on a plate that
// holds the ball): a cell of every model, not evaluated, with the reader's reason.
void add_unread_runs(ValidityMap& map, const Campaign& campaign, const MapRowReports& rows) {
  std::vector<SweepValue> all_velocities;
  for (const auto& any : campaign.axes)
    if (any.parameter == velocity_axis) all_velocities = any.values;
  for (std::size_t r = 0; r < map.rows.size(); ++r)
    for (const auto& velocity : all_velocities) {
      if (!velocity.number) continue;
      const double v = *velocity.number;
      const auto& cells = map.rows[r].models.front().cells;
      if (std::any_of(cells.begin(), cells.end(),
                      [&](const MapCell& cell) { return same_velocity(cell.velocity, v); }))
        continue;
      const auto problem =
          std::find_if(campaign.problems.begin(), campaign.problems.end(), [&](const auto& p) {
            const auto value = p.point.find(map.parameter);
            const auto speed = p.point.find(velocity_axis);
            return value != p.point.end() && value->second.matches(map.rows[r].value) &&
                   speed != p.point.end() && speed->second.matches(velocity);
          });
      if (problem == campaign.problems.end()) continue;
      if (std::none_of(map.velocities.begin(), map.velocities.end(),
                       [&](double w) { return same_velocity(w, v); })) {
        map.velocities.push_back(v);
        std::sort(map.velocities.begin(), map.velocities.end());
      }
      for (auto& model : map.rows[r].models) {
        if (rows.runs[r].empty()) model.missing = NoValue{NoValueReason::no_fem_result_on_row, ""};
        FemUncertainty unknown;
        for (auto& u : unknown) u = {std::numeric_limits<double>::quiet_NaN(), "no FEM result"};
        MapCell cell{v,
                     problem->source,
                     std::nullopt,
                     std::nullopt,
                     unknown,
                     {},
                     false,
                     NoValue{NoValueReason::no_fem_result, problem->message}};
        const auto at = std::find_if(model.cells.begin(), model.cells.end(),
                                     [&](const MapCell& c) { return c.velocity > v; });
        model.cells.insert(at, std::move(cell));
      }
    }
}

} // namespace

std::size_t class_index(const MapCell& cell) {
  return class_index_of(cell);
}

void add_validity_map(Assessment& report, const Campaign& campaign,
                      const AssessmentOptions& options) {
  if (campaign.axes.size() <= 1) return; // a velocity campaign: the report as before
  ValidityMap map;
  for (const auto& axis : campaign.axes) map.axes.push_back(axis.parameter);
  if (!has_map(campaign)) {
    report.map = std::move(map);
    return;
  }
  const std::vector<MapRowRuns> rows = map_rows(campaign);
  map_frame(map, campaign, rows);
  const MapRowReports judged = judged_rows(map, report, rows, options);
  add_plate_models(map, report, judged);
  add_unread_runs(map, campaign, judged);
  // Every cell carries a decision per band (unknown where it has no prediction), so that its
  // class index counts the report's bands.
  for (auto& row : map.rows)
    for (auto& model : row.models)
      for (auto& cell : model.cells)
        cell.decisions.resize(report.tolerances.size(), Decision::unknown);
  for (std::size_t m = 0; m < map.models.size(); ++m)
    add_map_region(map, m, report.tolerances.size());
  report.map = std::move(map);
}

std::optional<std::pair<Quantity, double>> map_worst_error(const MapCell& cell) {
  if (!cell.judged || !cell.fem) return std::nullopt;
  std::optional<std::pair<Quantity, double>> worst;
  for (Quantity quantity : map_quantities) {
    const double error = relative_error(*cell.judged, *cell.fem, quantity);
    if (std::isfinite(error) && (!worst || std::abs(error) > std::abs(worst->second)))
      worst = std::pair<Quantity, double>{quantity, error};
  }
  return worst;
}

} // namespace impact::postprocess::detail

namespace impact::postprocess {

std::vector<MapRowRuns> map_rows(const Campaign& campaign) {
  if (!detail::has_map(campaign)) return {};
  const SweepAxis& axis = detail::other_axis(campaign);
  std::vector<SweepValue> values = axis.values;
  const bool numeric = std::all_of(values.begin(), values.end(),
                                   [](const SweepValue& value) { return bool(value.number); });
  if (numeric)
    std::stable_sort(values.begin(), values.end(), [](const SweepValue& a, const SweepValue& b) {
      return *a.number < *b.number;
    });
  std::vector<MapRowRuns> rows;
  for (const auto& value : values) {
    MapRowRuns row{axis.parameter, value, {}};
    for (const auto& run : campaign.runs) {
      const auto at = run.sweep_point.find(axis.parameter);
      if (at != run.sweep_point.end() && at->second.matches(value)) row.runs.push_back(run);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::size_t map_class(const MapCell& cell) {
  return detail::class_index(cell);
}

double map_uncertainty(const MapCell& cell) {
  double largest = std::numeric_limits<double>::quiet_NaN();
  for (Quantity quantity : map_quantities) {
    const double u = cell.uncertainty[std::size_t(quantity)].relative;
    if (std::isfinite(u)) largest = std::isfinite(largest) ? std::max(largest, u) : u;
  }
  return largest;
}

std::optional<MapDetailRow> map_detail_row(const Campaign& campaign) {
  if (campaign.axes.size() != 2) return std::nullopt;
  const SweepAxis* other = nullptr;
  bool has_velocity = false;
  for (const auto& axis : campaign.axes) {
    if (axis.parameter == velocity_axis)
      has_velocity = true;
    else
      other = &axis;
  }
  if (!has_velocity || !other || other->values.empty()) return std::nullopt;
  // The value of the row: that of the run with the thickest plate, else the first.
  std::optional<SweepValue> chosen;
  double thickest = -INFINITY;
  for (const auto& run : campaign.runs) {
    const auto at = run.sweep_point.find(other->parameter);
    const auto h = text_number(run, fem_format::plate_thickness.path);
    if (at != run.sweep_point.end() && h && *h > thickest) {
      thickest = *h;
      chosen = at->second;
    }
  }
  if (!chosen) chosen = other->values.front();
  Campaign row;
  for (const auto& run : campaign.runs) {
    const auto at = run.sweep_point.find(other->parameter);
    if (at != run.sweep_point.end() && at->second.matches(*chosen)) row.runs.push_back(run);
  }
  for (const auto& problem : campaign.problems) row.problems.push_back(problem);
  return MapDetailRow{std::move(row),
                      {other->parameter, *chosen,
                       std::string(fem_format::parameter_unit(other->parameter))}};
}

} // namespace impact::postprocess
