// The validity map of a two-axis campaign (report.hpp, ValidityMap): each value of the other
// axis is a row, a velocity campaign of its own that is calibrated and judged by the verdict
// itself (build_report on the row's runs); the thin-plate model is judged on the same rows
// by the same rule (tolerance_verdict). The region sentences and the section of the page.

#include "report/report_parts.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace impact::postprocess::detail {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr const char* plate_thickness_parameter = fem_format::plate_thickness.path;

// The unit of a swept parameter, as the FEM's contract declares it.
std::string unit_of(const std::string& parameter) {
  return std::string(fem_format::parameter_unit(parameter));
}

// The plate thickness of a row: the axis value when the axis is the thickness, else the
// runs' own parameter (NaN when they do not record it).
double row_thickness(const std::string& parameter, const SweepValue& value,
                     const std::vector<FemRun>& runs) {
  if (parameter == plate_thickness_parameter && value.number) return *value.number;
  for (const auto& run : runs)
    if (const auto thickness = text_number(run, plate_thickness_parameter)) return *thickness;
  return nan;
}

// The tightest band in which the cell is within; else outside the loosest, not decided or
// not evaluated. The class index: 0 .. bands-1 within that band, bands outside, bands + 1
// not decided, bands + 2 not evaluated.
std::size_t class_index_of(const MapCell& cell) {
  const std::size_t bands = cell.decisions.size();
  if (!cell.missing.empty() || cell.decisions.empty()) return bands + 2;
  for (std::size_t k = 0; k < bands; ++k)
    if (cell.decisions[k] == Decision::within) return k;
  switch (cell.decisions.back()) {
  case Decision::outside: return bands;
  case Decision::undecided: return bands + 1;
  default: return bands + 2;
  }
}

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
    if (inside == row.cells.size()) full.push_back(r);
    else if (inside > 0) {
      std::vector<double> velocities;
      for (const auto& cell : row.cells)
        if (class_index(cell) <= band) velocities.push_back(cell.velocity);
      partial.push_back(with_unit(map.rows[r].value, map.unit) + " at V = " +
                        velocity_list(velocities));
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

std::string region_of(const ValidityMap& map, std::size_t model,
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

// A row's model cells from the row's own report: the judged predictions and the verdict's
// decisions.
MapModelRow row_model(const Report& row, std::string_view key) {
  MapModelRow result;
  const ReportModel* model = row.model(key);
  const ModelVerdict* verdict = row.verdict(key);
  if (!model || !verdict) {
    result.missing = key == model_keys::best_law ? "the row's calibration has no comparison law"
                                       : "the row's calibration has no such model";
  } else if (key == model_keys::calibrated && !row.verdict_available) {
    result.missing = row.cause;
  }
  if (model) {
    result.parameters = model->parameters;
    result.out_of_sample = model->out_of_sample;
  }
  for (std::size_t i = 0; i < row.runs.size(); ++i) {
    const ReportRun& run = row.runs[i];
    MapCell cell{run.velocity, run.source, run.fem, std::nullopt, run.uncertainty, {}, run.yields, ""};
    if (model && verdict && result.missing.empty()) {
      cell.judged = model->runs[i].judged();
      cell.missing = model->runs[i].missing;
      if (!cell.judged && cell.missing.empty()) cell.missing = "no prediction";
    } else {
      cell.missing = result.missing;
    }
    result.cells.push_back(std::move(cell));
  }
  // The verdict's rule on the map's quantities (the row's own verdict also judges x_max).
  if (model && verdict && result.missing.empty()) {
    std::vector<std::optional<ImpactFigures>> judged;
    for (const auto& cell : result.cells) judged.push_back(cell.judged);
    for (const auto& band : verdict->tolerances) {
      const ToleranceVerdict decided = tolerance_verdict(
          row, judged, band.tolerance, {map_quantities.begin(), map_quantities.end()}, "");
      for (std::size_t i = 0; i < result.cells.size(); ++i)
        result.cells[i].decisions.push_back(decided.decisions[i]);
    }
  }
  if (model && result.missing.empty() &&
      std::all_of(result.cells.begin(), result.cells.end(),
                  [](const MapCell& cell) { return !cell.missing.empty(); }))
    result.missing = result.cells.front().missing;
  return result;
}


/// Whether the calibration is of exactly these runs (the same HDF5 sources).
bool same_runs(const Calibration& calibration, const std::vector<FemRun>& runs) {
  std::vector<std::string> calibrated, given;
  for (const auto& run : calibration.runs) calibrated.push_back(run.source);
  for (const auto& run : runs) given.push_back(run.source);
  std::sort(calibrated.begin(), calibrated.end());
  std::sort(given.begin(), given.end());
  return calibrated == given;
}

} // namespace

std::size_t class_index(const MapCell& cell) { return class_index_of(cell); }

std::string short_name(const std::string& parameter) {
  const auto slash = parameter.rfind('/');
  return slash == std::string::npos ? parameter : parameter.substr(slash + 1);
}

std::string with_unit(const SweepValue& value, const std::string& unit) {
  return value.text + (unit.empty() || !value.number ? "" : " " + unit);
}


namespace {

// The runs and the report of each row of a map, parallel to ValidityMap::rows.
struct MapRows {
  std::vector<std::vector<FemRun>> runs;
  std::vector<Report> reports;
};

// Why a campaign with sweep axes has no map ("" when it has one: velocity and one other axis).
std::string no_map_reason(const Campaign& campaign) {
  const bool has_velocity =
      std::any_of(campaign.axes.begin(), campaign.axes.end(),
                  [](const SweepAxis& axis) { return axis.parameter == velocity_axis; });
  if (campaign.axes.size() == 2 && has_velocity) return "";
  std::string names;
  for (const auto& axis : campaign.axes) names += (names.empty() ? "" : ", ") + axis.parameter;
  return "the campaign has " + std::to_string(campaign.axes.size()) + " axes (" + names +
         "); a validity map needs exactly two: " + velocity_axis +
         " and one other parameter. No map is shown; the sections below treat all runs "
         "as one velocity campaign.";
}

// The map's frame: its axis, unit and scale, velocities and models; the axis's values in the
// order of the rows.
std::vector<SweepValue> map_frame(ValidityMap& map, const Campaign& campaign,
                                  const SweepAxis& axis) {
  map.available = true;
  map.parameter = axis.parameter;
  map.unit = unit_of(axis.parameter);
  std::vector<SweepValue> values = axis.values;
  const bool numeric = std::all_of(values.begin(), values.end(),
                                   [](const SweepValue& value) { return bool(value.number); });
  if (numeric) {
    std::stable_sort(values.begin(), values.end(), [](const SweepValue& a, const SweepValue& b) {
      return *a.number < *b.number;
    });
    map.logarithmic = values.front().number > 0.0 && *values.back().number > 10 * *values.front().number;
  }
  for (const auto& run : campaign.runs)
    if (std::none_of(map.velocities.begin(), map.velocities.end(),
                     [&](double v) { return same_velocity(v, run.impact_velocity); }))
      map.velocities.push_back(run.impact_velocity);
  std::sort(map.velocities.begin(), map.velocities.end());
  map.models = {
      {std::string(model_keys::calibrated), "calibrated Hunt–Crossley",
       "the row's campaign fit of c, n, b to the force histories, each velocity judged by the "
       "fit without it",
       ""},
      {std::string(model_keys::best_law), "the row's best law",
       "the comparison law ranked first on the row by out-of-sample error, judged out of sample",
       ""},
      {std::string(model_keys::thin_plate), "thin-plate model",
       "Zener: Hertz contact (c from the run's materials, n = 3/2) on an infinite Kirchhoff plate "
       "of the run's thickness and material (Z = 8 sqrt(D rho h)), with the Hunt–Crossley "
       "damping b that makes it reproduce the FEM restitution of the most massive plate at the "
       "same velocity (the material's damping; in sample on that row, a prediction on the "
       "others)",
       ""},
      {std::string(model_keys::massive_plate), "massive-plate model",
       "the thin-plate model's contact on a rigid support instead of the plate: Hertz c, "
       "n = 3/2 and the b that makes it reproduce the FEM restitution of the most massive plate "
       "at the same velocity — what a contact law calibrated on the massive plate predicts for "
       "the others (the row where it leaves the bands is where the massive-plate assumption "
       "fails)",
       ""}};
  return values;
}

// Every row: a velocity campaign, calibrated and judged by the verdict (the calibrated
// Hunt–Crossley law and the row's best law).
MapRows calibrated_rows(ValidityMap& map, const Report& report, const Campaign& campaign,
                        const SweepAxis& axis, const std::vector<SweepValue>& values,
                        const ReportOptions& options) {
  MapRows rows;
  for (const auto& value : values) {
    std::vector<FemRun> runs;
    for (const auto& run : campaign.runs) {
      const auto at = run.sweep_point.find(axis.parameter);
      if (at != run.sweep_point.end() && at->second.matches(value)) runs.push_back(run);
    }
    MapRow row{value, {}, ""};
    std::optional<Calibration> calibration;
    Report row_report;
    if (!runs.empty()) {
      CalibrationOptions calibration_options = options.map_calibration;
      const std::string name = short_name(axis.parameter) + " = " + value.text;
      if (calibration_options.progress) {
        const auto progress = calibration_options.progress;
        calibration_options.progress = [progress, name](const std::string& line) {
          progress("map row " + name + ": " + line);
        };
      }
      if (options.detail_row_calibration && same_runs(*options.detail_row_calibration, runs)) {
        calibration = options.detail_row_calibration;
        if (calibration_options.progress)
          calibration_options.progress("the calibration of the detail row, not repeated");
      } else {
        try {
          calibration = calibrate(runs, calibration_options);
        } catch (const std::exception& error) {
          row.calibration_problems = std::string("the row could not be calibrated: ") + error.what();
        }
      }
      Campaign row_campaign;
      row_campaign.runs = runs;
      ReportOptions row_options;
      row_options.tolerances = report.tolerances;
      row_report = build_report(row_campaign, calibration, {}, report.campaign_source + " (" + name + ")",
                                "row calibration", row_options);
      if (calibration)
        for (const auto& problem : calibration->problems)
          row.calibration_problems +=
              (row.calibration_problems.empty() ? "" : "; ") + problem.message;
    }
    for (const std::string_view key : {model_keys::calibrated, model_keys::best_law}) {
      MapModelRow model = row_model(row_report, key);
      if (runs.empty()) model.missing = "no run at this value";
      row.models.push_back(std::move(model));
    }
    map.rows.push_back(std::move(row));
    rows.runs.push_back(std::move(runs));
    rows.reports.push_back(std::move(row_report));
  }
  return rows;
}

// The thin-plate model: the material's damping at each velocity from the row of the most
// massive (thickest) plate: the b with which the model itself reproduces that row's FEM
// restitution at the same velocity (in sample on that row, a prediction on the others). The
// models with the material's damping from the most massive plate: Zener's thin plate, and the
// same contact on a rigid support (what a massive-plate law predicts).
void add_plate_models(ValidityMap& map, const Report& report, const SweepAxis& axis,
                      const MapRows& rows) {
  double thickest = -INFINITY;
  for (std::size_t r = 0; r < map.rows.size(); ++r) {
    const double h = row_thickness(axis.parameter, map.rows[r].value, rows.runs[r]);
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
      const Report& row_report = rows.reports[r];
      if (rows.runs[r].empty()) model.missing = "no run at this value";
      else if (!std::isfinite(thickest))
        model.missing =
            "the runs do not record 'Scenario/Plate thickness', so the plate is not known";
      std::vector<std::optional<ImpactFigures>> judged;
      std::ostringstream parameters;
      for (std::size_t i = 0; i < rows.runs[r].size(); ++i) {
        const ReportRun& run = row_report.runs[i];
        MapCell cell{run.velocity, run.source, run.fem, std::nullopt,
                     run.uncertainty, {}, run.yields, ""};
        if (model.missing.empty()) {
          const auto at = std::find_if(reference_damping.begin(), reference_damping.end(),
                                       [&](const auto& entry) {
                                         return same_velocity(entry.first, run.velocity);
                                       });
          if (at == reference_damping.end() || !at->second) {
            cell.missing = "the row " + with_unit(map.rows[map.reference_row].value, map.unit) +
                           " (the most massive plate) has no run at this velocity whose "
                           "restitution the model reproduces";
          } else {
            const double b = *at->second;
            const ThinPlatePrediction prediction = thin_plate_prediction(rows.runs[r][i], b, rigid);
            cell.judged = prediction.quantities;
            cell.missing = prediction.missing;
            if (parameters.tellp() == 0) parameters << prediction.parameters << "; b = ";
            else parameters << ", ";
            parameters << short_number(b) << " s/m at " << short_number(run.velocity) << " m/s";
          }
        } else {
          cell.missing = model.missing;
        }
        judged.push_back(cell.judged);
        model.cells.push_back(std::move(cell));
      }
      if (model.missing.empty()) {
        model.out_of_sample = r != map.reference_row;
        model.parameters = parameters.str() + " (b from the row " +
                           with_unit(map.rows[map.reference_row].value, map.unit) +
                           (r == map.reference_row ? ", this row: its e in sample)" : ")");
        for (double tolerance : report.tolerances) {
          const ToleranceVerdict verdict = tolerance_verdict(
              row_report, judged, tolerance, {map_quantities.begin(), map_quantities.end()}, "");
          for (std::size_t i = 0; i < model.cells.size(); ++i)
            model.cells[i].decisions.push_back(verdict.decisions[i]);
        }
      }
      map.rows[r].models.push_back(std::move(model));
    }
  }
}

// Runs of the index that could not be read (e.g. no rebound within the run on a plate that
// holds the ball): a cell of every model, not evaluated, with the reader's reason.
void add_unread_runs(ValidityMap& map, const Campaign& campaign, const SweepAxis& axis,
                     const MapRows& rows) {
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
            const auto value = p.point.find(axis.parameter);
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
        if (rows.runs[r].empty())
          model.missing = "no FEM run of this value has a result (each run's reason below)";
        FemUncertainty unknown;
        for (auto& u : unknown) u = {std::numeric_limits<double>::quiet_NaN(), "no FEM result"};
        MapCell cell{v, problem->source, std::nullopt, std::nullopt, unknown, {}, false,
                     "the FEM run has no result: " + problem->message};
        const auto at = std::find_if(model.cells.begin(), model.cells.end(),
                                     [&](const MapCell& c) { return c.velocity > v; });
        model.cells.insert(at, std::move(cell));
      }
    }
}

} // namespace

void add_validity_map(Report& report, const Campaign& campaign, const ReportOptions& options) {
  if (campaign.axes.size() <= 1) return; // a velocity campaign: the report as before
  ValidityMap map;
  map.reason = no_map_reason(campaign);
  if (!map.reason.empty()) {
    report.map = std::move(map);
    return;
  }
  const SweepAxis& axis = campaign.axes.front().parameter == velocity_axis ? campaign.axes.back()
                                                                            : campaign.axes.front();
  const std::vector<SweepValue> values = map_frame(map, campaign, axis);
  const MapRows rows = calibrated_rows(map, report, campaign, axis, values, options);
  add_plate_models(map, report, axis, rows);
  add_unread_runs(map, campaign, axis, rows);
  // Every cell carries a decision per band (unknown where it has no prediction), so that its
  // class index counts the report's bands.
  for (auto& row : map.rows)
    for (auto& model : row.models)
      for (auto& cell : model.cells)
        cell.decisions.resize(report.tolerances.size(), Decision::unknown);
  for (std::size_t m = 0; m < map.models.size(); ++m)
    map.models[m].region = region_of(map, m, report.tolerances);
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

std::string map_class_name(const MapCell& cell, const std::vector<double>& tolerances) {
  const std::size_t index = detail::class_index(cell);
  if (index < tolerances.size()) return "within " + detail::band_name(tolerances[index]);
  if (index == tolerances.size()) return "outside " + detail::band_name(tolerances.back());
  if (index == tolerances.size() + 1) return "not decided";
  return "not evaluated";
}

std::size_t map_class(const MapCell& cell) { return detail::class_index(cell); }

double map_uncertainty(const MapCell& cell) {
  double largest = std::numeric_limits<double>::quiet_NaN();
  for (Quantity quantity : map_quantities) {
    const double u = cell.uncertainty[std::size_t(quantity)].relative;
    if (std::isfinite(u)) largest = std::isfinite(largest) ? std::max(largest, u) : u;
  }
  return largest;
}


} // namespace impact::postprocess

namespace impact::postprocess {

std::optional<std::pair<Campaign, std::string>> map_detail_row(const Campaign& campaign) {
  if (campaign.axes.size() != 2) return std::nullopt;
  const SweepAxis* other = nullptr;
  bool has_velocity = false;
  for (const auto& axis : campaign.axes) {
    if (axis.parameter == velocity_axis) has_velocity = true;
    else other = &axis;
  }
  if (!has_velocity || !other || other->values.empty()) return std::nullopt;
  // The value of the row: that of the run with the thickest plate, else the first.
  std::optional<SweepValue> chosen;
  double thickest = -INFINITY;
  for (const auto& run : campaign.runs) {
    const auto at = run.sweep_point.find(other->parameter);
    const auto h = text_number(run, detail::plate_thickness_parameter);
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
  const std::string unit = detail::unit_of(other->parameter);
  return std::pair<Campaign, std::string>{
      std::move(row), detail::short_name(other->parameter) + " = " + chosen->text +
                          (unit.empty() ? "" : " " + unit)};
}

} // namespace impact::postprocess
