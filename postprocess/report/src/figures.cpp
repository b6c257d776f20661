// The figure data of the report (report.hpp): every curve as numbers, for
// postprocess/report_figures.py, which only draws them.

#include "map_words.hpp"
#include "model_words.hpp"
#include "sections.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include <cmath>
#include <limits>
#include <map>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

json scaled(const std::vector<double>& values, double scale) {
  json out = json::array();
  for (double v : values) out.push_back(std::isfinite(v) ? json(v * scale) : json(nullptr));
  return out;
}

json series(const std::string& label, json x, json y, const std::string& color,
            const std::string& linestyle, const std::string& marker) {
  return json{{"label", label}, {"x", std::move(x)},      {"y", std::move(y)},
              {"color", color}, {"linestyle", linestyle}, {"marker", marker}};
}

json fill(const std::string& label, json x, json y0, json y1, const std::string& color) {
  return json{{"label", label},      {"fill", true},   {"x", std::move(x)}, {"y0", std::move(y0)},
              {"y1", std::move(y1)}, {"color", color}, {"alpha", 0.18}};
}

const std::map<std::string, std::string>& model_colors() {
  static const std::map<std::string, std::string> colors = {
      {std::string(model_keys::calibrated), "tab:red"},
      {std::string(model_keys::hunt_crossley_energy), "tab:orange"},
      {std::string(model_keys::hunt_crossley_velocity_damping), "tab:brown"},
      {std::string(model_keys::best_law), "tab:purple"},
      {std::string(model_keys::kuwabara_kono_material), "tab:green"},
      {std::string(model_keys::hunt_crossley_published), "tab:blue"},
      {std::string(model_keys::hertz), "tab:gray"},
      // The damped elastic-plastic laws: pink on Thornton's spring, olive on Jackson–Green's,
      // dark magenta and teal with b(V) from A (as in the section Elastic-plastic laws).
      {std::string(model_keys::hunt_crossley_thornton), "tab:pink"},
      {std::string(model_keys::hunt_crossley_thornton_material), "tab:pink"},
      {std::string(model_keys::hunt_crossley_thornton_from_a), "darkmagenta"},
      {std::string(model_keys::hunt_crossley_jackson_green), "tab:olive"},
      {std::string(model_keys::hunt_crossley_jackson_green_material), "tab:olive"},
      {std::string(model_keys::hunt_crossley_jackson_green_from_a), "teal"},
      // Kuwabara–Kono damping on the springs: goldenrod on Thornton's, navy on Jackson–Green's.
      {std::string(model_keys::kuwabara_kono_thornton), "goldenrod"},
      {std::string(model_keys::kuwabara_kono_thornton_material), "goldenrod"},
      {std::string(model_keys::kuwabara_kono_jackson_green), "navy"},
      {std::string(model_keys::kuwabara_kono_jackson_green_material), "navy"}};
  return colors;
}

std::string color_of(const ReportModel& model) {
  const auto found = model_colors().find(model.key);
  return found == model_colors().end() ? "tab:cyan" : found->second;
}

// The models drawn in the per-run figures: the calibrated Hunt–Crossley and the best law.
std::vector<const ReportModel*> featured(const Report& report) {
  std::vector<const ReportModel*> models{&report.models.front()};
  if (const ReportModel* best = report.model(model_keys::best_law))
    if (!best->runs.empty() && !best->runs.front().history.time.empty()) models.push_back(best);
  return models;
}

// Display scale of the quantity figures: restitution and losses [1], t_c [us], F_max [kN],
// x_max [um].
double display_scale(Quantity quantity) {
  switch (quantity) {
    case Quantity::contact_time:
    case Quantity::time_force_max:
    case Quantity::approach_max:
      return 1e6;
    case Quantity::force_max:
      return 1e-3;
    default:
      return 1;
  }
}

std::string display_name(Quantity quantity) {
  switch (quantity) {
    case Quantity::energy_loss:
      return "energy loss 1 - e² [1]";
    case Quantity::restitution_deficit:
      return "1 - e [1]";
    case Quantity::restitution:
      return "restitution e [1]";
    case Quantity::contact_time:
      return "contact time t_c [µs]";
    case Quantity::force_max:
      return "peak force F_max [kN]";
    case Quantity::time_force_max:
      return "time of peak force [µs]";
    case Quantity::approach_max:
      return "peak approach x_max [µm]";
  }
  return "";
}

// The data of the three per-run figures (one panel per run, or two for the histories).
struct PerRunFigures {
  json loops, histories, residuals;
};

PerRunFigures per_run_figures(const Report& report) {
  json loops = json::array(), histories = json::array(), residuals = json::array();
  const auto models = featured(report);
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const auto& run = report.runs[i];
    const std::string title = velocity_label(run.velocity) + (run.yields ? " (yields)" : "");
    const auto panel = [&](const std::string& xlabel, const std::string& ylabel) {
      return json{{"title", title},
                  {"xlabel", xlabel},
                  {"ylabel", ylabel},
                  {"series", json::array()}};
    };
    json loop = panel("approach x [µm]", "contact force F [kN]");
    loop["series"].push_back(series("FEM", scaled(run.fem_history.approach, 1e6),
                                    scaled(run.fem_history.force, 1e-3), "black", "-", ""));
    json approach = panel("time since first contact [µs]", "approach x [µm]");
    approach["series"].push_back(series("FEM", scaled(run.fem_history.time, 1e6),
                                        scaled(run.fem_history.approach, 1e6), "black", "-", ""));
    json force = panel("time since first contact [µs]", "contact force F [kN]");
    force["series"].push_back(series("FEM", scaled(run.fem_history.time, 1e6),
                                     scaled(run.fem_history.force, 1e-3), "black", "-", ""));
    json residual = panel("time since first contact [µs]", "(F_model - F_FEM) / F_max [%]");
    for (const ReportModel* model : models) {
      const ModelAtRun& at = model->runs[i];
      const std::string style = model->key == model_keys::calibrated ? "--" : "-.";
      if (at.history.time.empty()) {
        loop["note"] = detail::no_value_words(at.missing);
        continue;
      }
      loop["series"].push_back(series(model->label, scaled(at.history.approach, 1e6),
                                      scaled(at.history.force, 1e-3), color_of(*model), style, ""));
      approach["series"].push_back(series(model->label, scaled(at.history.time, 1e6),
                                          scaled(at.history.approach, 1e6), color_of(*model), style,
                                          ""));
      force["series"].push_back(series(model->label, scaled(at.history.time, 1e6),
                                       scaled(at.history.force, 1e-3), color_of(*model), style,
                                       ""));
      residual["series"].push_back(series(model->label, scaled(run.fem_history.time, 1e6),
                                          scaled(at.residual, 100), color_of(*model), "-", ""));
    }
    residual["hlines"] = json::array({{{"y", 0}, {"color", "black"}, {"linestyle", ":"}}});
    loops.push_back(loop);
    histories.push_back(approach);
    histories.push_back(force);
    residuals.push_back(residual);
  }
  return {{{"title", "Force–approach loops"}, {"columns", 3}, {"panels", loops}},
          {{"title", "Approach and force against time"}, {"columns", 2}, {"panels", histories}},
          {{"title", "Force residuals against time"}, {"columns", 3}, {"panels", residuals}}};
}

// A model's curve of `quantity` against V, with its band when it has one.
void add_model_curve(json& panel, const ReportModel& model, Quantity quantity, double scale,
                     bool with_band) {
  if (!model.curve) return;
  const std::size_t q = std::size_t(quantity);
  const std::string style =
      model.key == model_keys::calibrated ? "-" : (model.free_parameters == 0 ? ":" : "--");
  if (with_band && model.band) {
    panel["series"].push_back(fill(model.label + " (jackknife band)",
                                   scaled(model.band->velocity, 1),
                                   scaled(model.band->lower[q], scale),
                                   scaled(model.band->upper[q], scale), color_of(model)));
  }
  panel["series"].push_back(series(model.label, scaled(model.curve->velocity, 1),
                                   scaled(model.curve->center[q], scale), color_of(model), style,
                                   ""));
}

// The velocities above the FEM's yield onset, shaded in every figure against V.
void add_yield_band(json& panel, const Report& report) {
  const auto& plasticity = report.plasticity;
  if (!plasticity.first_yielding_velocity || report.runs.empty()) return;
  const double from = plasticity.onset_estimate.value_or(*plasticity.first_yielding_velocity);
  const double to = report.runs.back().velocity;
  panel["vbands"] = json::array({{{"x0", std::max(from, report.runs.front().velocity)},
                                  {"x1", to},
                                  {"color", "0.9"},
                                  {"alpha", 0.3},
                                  {"hatch", "//"},
                                  {"label",
                                   "FEM above the yield strength: viscoelastic model "
                                   "not valid"}}});
}

json fem_points(const Report& report, Quantity quantity, double scale) {
  std::vector<double> velocities, values, errors;
  for (const auto& run : report.runs) {
    velocities.push_back(run.velocity);
    const double v = value(run.fem, quantity);
    values.push_back(v);
    const double u = run.uncertainty[std::size_t(quantity)].relative;
    errors.push_back(std::isfinite(u) ? u * std::abs(v) : 0.0);
  }
  json fem = series("FEM", scaled(velocities, 1), scaled(values, scale), "black", "none", "o");
  fem["yerr"] = {scaled(errors, scale), scaled(errors, scale)};
  return fem;
}

json quantities_figure(const Report& report) {
  json panels = json::array();
  for (Quantity quantity : {Quantity::restitution, Quantity::energy_loss, Quantity::contact_time,
                            Quantity::force_max, Quantity::approach_max}) {
    const double scale = display_scale(quantity);
    json panel = {{"title", display_name(quantity)},
                  {"xlabel", "impact velocity V [m/s]"},
                  {"ylabel", display_name(quantity)},
                  {"series", json::array()}};
    for (const auto& model : report.models)
      add_model_curve(panel, model, quantity, scale,
                      model.key == model_keys::calibrated || model.key == model_keys::best_law);
    panel["series"].push_back(fem_points(report, quantity, scale));
    add_yield_band(panel, report);
    panels.push_back(panel);
  }
  return {{"title", "Impact quantities against V"},
          {"columns", 2},
          {"shared_legend", true},
          {"panels", panels}};
}

json energy_loss_figure(const Report& report) {
  json panel = {{"title", "1 - e against V (log-log): the velocity trend of the dissipation"},
                {"xlabel", "impact velocity V [m/s]"},
                {"ylabel", "1 - e [1]"},
                {"xscale", "log"},
                {"yscale", "log"},
                {"series", json::array()}};
  std::vector<double> tested;
  for (const auto& run : report.runs) tested.push_back(run.velocity);
  panel["xticks"] = tested;
  for (const auto& model : report.models)
    if (model.key != model_keys::hertz) // 1 - e = 0: nothing to draw in log scale
      add_model_curve(panel, model, Quantity::restitution_deficit, 1,
                      model.key == model_keys::calibrated || model.key == model_keys::best_law ||
                          model.key == model_keys::hunt_crossley_velocity_damping);
  // Reference slopes through the FEM's geometric mean point.
  double mean_v = 0, mean_y = 0;
  std::size_t count = 0;
  double low = INFINITY, high = 0;
  for (const auto& run : report.runs)
    if (run.fem.restitution < 1) {
      mean_v += std::log(run.velocity);
      mean_y += std::log(1 - run.fem.restitution);
      low = std::min(low, run.velocity);
      high = std::max(high, run.velocity);
      ++count;
    }
  if (count >= 2) {
    mean_v /= double(count);
    mean_y /= double(count);
    const std::vector<double> ends{low, high};
    const std::array<const char*, 3> dashes = {"-.", ":", "--"};
    for (std::size_t k = 0; k < reference_slopes().size(); ++k) {
      const auto& reference = reference_slopes()[k];
      std::vector<double> y;
      for (double v : ends)
        y.push_back(std::exp(mean_y + reference.slope * (std::log(v) - mean_v)));
      panel["series"].push_back(
          series("reference slope " + short_number(reference.slope) + " (" + reference.family + ")",
                 scaled(ends, 1), scaled(y, 1), "0.55", dashes[k % 3], ""));
    }
    if (report.trend) {
      std::vector<double> y;
      for (double v : ends)
        y.push_back(report.trend->prefactor * std::pow(v, report.trend->exponent));
      panel["series"].push_back(series("FEM fit: p = " + short_number(report.trend->exponent) +
                                           " [" + short_number(report.trend->lower) + ", " +
                                           short_number(report.trend->upper) + "]",
                                       scaled(ends, 1), scaled(y, 1), "black", "-", ""));
    }
  }
  json fem = fem_points(report, Quantity::restitution_deficit, 1);
  panel["series"].push_back(fem);
  add_yield_band(panel, report);
  // A model without loss at some velocities (an elastic-plastic law below its yield, 1 - e = 0)
  // has no point on the log scale: values far below the FEM's smallest loss are not drawn, so
  // that its band does not stretch the axis over ten decades.
  double smallest = INFINITY;
  for (const auto& run : report.runs)
    if (run.fem.restitution < 1) smallest = std::min(smallest, 1 - run.fem.restitution);
  if (std::isfinite(smallest))
    for (auto& entry : panel["series"])
      for (const char* key : {"y", "y0", "y1"})
        if (entry.contains(key))
          for (auto& y : entry[key])
            if (y.is_number() && y.get<double>() < 1e-2 * smallest) y = nullptr;
  return {{"title", "Energy loss against V"},
          {"columns", 1},
          {"shared_legend", true},
          {"panels", json::array({panel})}};
}

json damping_figure(const Report& report) {
  std::vector<double> velocities, b_restitution, b_history, b_low, b_high;
  for (const auto& run : report.runs) {
    velocities.push_back(run.velocity);
    b_restitution.push_back(run.damping_from_restitution);
    b_history.push_back(run.history_damping.value);
    b_low.push_back(run.history_damping.value - run.history_damping.lower);
    b_high.push_back(run.history_damping.upper - run.history_damping.value);
  }
  json damping = {{"title", "per-run b (constant only where Hunt–Crossley is the right law)"},
                  {"xlabel", "impact velocity V [m/s]"},
                  {"ylabel", "damping b [s/m]"},
                  {"series", json::array({series("b from the restitution", scaled(velocities, 1),
                                                 scaled(b_restitution, 1), "black", "-", "o")})},
                  {"hlines", json::array()},
                  {"bands", json::array()}};
  json history_series = series("b of the force-history fit", scaled(velocities, 1),
                               scaled(b_history, 1), "tab:orange", "none", "s");
  history_series["yerr"] = {scaled(b_low, 1), scaled(b_high, 1)};
  damping["series"].push_back(history_series);
  if (!report.calibration) return {};
  const CampaignCalibration& campaign = report.calibration->campaign;
  damping["hlines"].push_back(
      {{"y", campaign.published_damping},
       {"label", "published b = " + short_number(campaign.published_damping) + " s/m"},
       {"color", "tab:blue"},
       {"linestyle", ":"}});
  if (campaign.hunt_crossley) {
    const Estimate& b = campaign.hunt_crossley->fit.parameter;
    damping["hlines"].push_back({{"y", b.value},
                                 {"label", "campaign b (calibrated)"},
                                 {"color", "tab:red"},
                                 {"linestyle", "--"}});
    const auto& jackknife = campaign.hunt_crossley->jackknife;
    const Estimate interval = jackknife.size() > 2 ? jackknife[2] : b;
    if (std::isfinite(interval.lower) && std::isfinite(interval.upper))
      damping["bands"].push_back(
          {{"y0", interval.lower},
           {"y1", interval.upper},
           {"color", "tab:red"},
           {"alpha", 0.15},
           {"label", std::string("campaign b interval (") +
                         (jackknife.size() > 2 ? "jackknife" : "conditional on the model") + ")"}});
  }
  if (campaign.hunt_crossley_energy)
    damping["hlines"].push_back({{"y", campaign.hunt_crossley_energy->fit.parameter.value},
                                 {"label", "campaign b (force + energy)"},
                                 {"color", "tab:orange"},
                                 {"linestyle", "-."}});
  if (campaign.hunt_crossley_velocity_damping && velocities.size() >= 2) {
    const ModelFit& fit = campaign.hunt_crossley_velocity_damping->fit;
    std::vector<double> grid, b;
    const double low = velocities.front(), high = velocities.back();
    for (int i = 0; i <= 40; ++i) {
      grid.push_back(low * std::pow(high / low, i / 40.0));
      b.push_back(fit.parameter.value * std::pow(grid.back(), -fit.extra.at(0).estimate.value));
    }
    damping["series"].push_back(series("b(V) = b_1 V^-q of the b(V) fit", scaled(grid, 1),
                                       scaled(b, 1), "tab:brown", "--", ""));
  }
  return {{"title", "Per-run damping"}, {"columns", 1}, {"panels", json::array({damping})}};
}

// The page's first figure: every model's judged error (out of sample where it is) in the
// verdict's quantities against V, one panel per quantity in one row, with the tolerance bands,
// the FEM's uncertainty (bars at 0) and the velocities where the FEM yields. Errors beyond
// twice the widest band are drawn on a symmetric log scale (linear within it), so that the
// bands stay readable beside a model that is off by 100 %.
json errors_figure(const Report& report) {
  json panels = json::array();
  std::vector<double> velocities;
  for (const auto& run : report.runs) velocities.push_back(run.velocity);
  const double widest = report.tolerances.empty() ? 0.05 : report.tolerances.back();
  const double linear_limit = 2 * widest * 100; // [%]
  for (Quantity quantity : verdict_quantities) {
    json bands = json::array();
    const std::array<const char*, 3> colors = {"tab:green", "tab:orange", "tab:red"};
    for (std::size_t k = report.tolerances.size(); k-- > 0;)
      bands.push_back({{"y0", -report.tolerances[k] * 100},
                       {"y1", report.tolerances[k] * 100},
                       {"color", colors[std::min<std::size_t>(k, 2)]},
                       {"alpha", 0.12 + 0.06 * double(k == 0)},
                       {"label", "±" + short_number(report.tolerances[k] * 100) + " %"}});
    json panel = {{"title",
                   std::string(quantity_words(quantity)) + " " + quantity_symbol(quantity)},
                  {"xlabel", "impact velocity V [m/s]"},
                  {"ylabel", "(model - FEM) / FEM [%]"},
                  {"series", json::array()},
                  {"bands", bands}};
    std::vector<double> zero(velocities.size(), 0.0), uncertainty;
    for (const auto& run : report.runs) {
      const double u = run.uncertainty[std::size_t(quantity)].relative;
      uncertainty.push_back(std::isfinite(u) ? u : 0.0);
    }
    json fem =
        series("FEM uncertainty", scaled(velocities, 1), scaled(zero, 100), "black", "none", "_");
    fem["yerr"] = {scaled(uncertainty, 100), scaled(uncertainty, 100)};
    panel["series"].push_back(fem);
    double largest = 0; // [%]
    for (const ReportModel& model : report.models) {
      std::vector<double> errors;
      for (std::size_t i = 0; i < report.runs.size(); ++i) {
        const auto& judged = model.runs[i].judged();
        errors.push_back(judged ? relative_error(*judged, report.runs[i].fem, quantity) : nan);
        if (std::isfinite(errors.back()))
          largest = std::max(largest, std::abs(errors.back()) * 100);
      }
      const std::string style =
          model.key == model_keys::calibrated ? "-" : (model.free_parameters == 0 ? ":" : "--");
      panel["series"].push_back(series(model.label + detail::not_converged(model),
                                       scaled(velocities, 1), scaled(errors, 100), color_of(model),
                                       style, "o"));
    }
    if (largest > linear_limit) {
      panel["yscale"] = "symlog";
      panel["linthresh"] = linear_limit;
      // No tick at 0: on this scale it would crowd the tolerance ticks.
      json ticks = json::array();
      for (double tolerance : report.tolerances) {
        ticks.push_back(tolerance * 100);
        ticks.push_back(-tolerance * 100);
      }
      for (double tick = linear_limit; tick <= largest; tick *= 10) {
        ticks.push_back(tick);
        ticks.push_back(-tick);
      }
      panel["yticks"] = ticks;
    }
    add_yield_band(panel, report);
    panels.push_back(panel);
  }
  return {{"title", ""},         {"columns", panels.size()}, {"width", 13.0},   {"row_height", 3.2},
          {"legend_columns", 4}, {"shared_legend", true},    {"panels", panels}};
}

// One validity map per model: a grid of cells (velocity on x, the other axis on y), coloured
// by class, each with its largest error.
std::vector<std::pair<const MapModel*, json>> map_figures(const Report& report) {
  std::vector<std::pair<const MapModel*, json>> figures;
  if (!report.map || !report.map->available) return figures;
  const ValidityMap& map = *report.map;
  const std::size_t bands = report.tolerances.size();
  json classes = json::array();
  const std::vector<std::string> within_colors = {"#1a9641", "#a6d96a", "#d9ef8b", "#ffffbf"};
  for (std::size_t k = 0; k < bands; ++k)
    classes.push_back({{"name", "within " + band_name(report.tolerances[k])},
                       {"color", within_colors[std::min(k, within_colors.size() - 1)]}});
  classes.push_back(
      {{"name", "outside " + band_name(report.tolerances.back())}, {"color", "#e66a5c"}});
  classes.push_back({{"name", "not decided (FEM uncertainty)"}, {"color", "#bdbdbd"}});
  classes.push_back({{"name", "not evaluated"}, {"color", "#ffffff"}});
  const std::string name = detail::short_name(map.parameter);
  for (std::size_t m = 0; m < map.models.size(); ++m) {
    json cells = json::array(), rows = json::array(), labels = json::array();
    for (std::size_t r = 0; r < map.rows.size(); ++r) {
      const MapRow& row = map.rows[r];
      rows.push_back(row.value.number ? json(*row.value.number) : json(nullptr));
      labels.push_back(row.value.text);
      for (const auto& cell : row.models[m].cells) {
        std::size_t column = 0;
        while (column < map.velocities.size() &&
               !detail::same_velocity(map.velocities[column], cell.velocity))
          ++column;
        std::string text;
        if (const auto worst = detail::map_worst_error(cell))
          text = percent_cell(worst->second) + "\n" + quantity_symbol(worst->first);
        else
          text = "n/a";
        text += "\nU " + unsigned_percent(map_uncertainty(cell));
        if (cell.yields) text += "\n(yields)";
        cells.push_back(
            {{"column", column}, {"row", r}, {"class", map_class(cell)}, {"text", text}});
      }
    }
    figures.emplace_back(
        &map.models[m],
        json{{"kind", "map"},
             {"title", "Validity map: " + detail::map_model_label(map.models[m].key)},
             {"xlabel", "impact velocity V [m/s]"},
             {"ylabel", name + (map.unit.empty() ? "" : " [" + map.unit + "]")},
             {"yscale", map.logarithmic ? "log" : "linear"},
             {"columns_values", scaled(map.velocities, 1)},
             {"rows_values", rows},
             {"rows_labels", labels},
             {"classes", classes},
             {"cells", cells},
             {"note",
              "cell: the largest out-of-sample error of 1 - e², t_c, F_max (which), "
              "U = the FEM's largest uncertainty there"}});
  }
  return figures;
}

} // namespace

std::vector<ReportFigure> report_figures(const Report& report) {
  if (report.runs.empty() || report.models.empty()) return {};
  PerRunFigures per_run = per_run_figures(report);
  std::vector<ReportFigure> figures = {
      {FigureId::loops, "", "loops.png",
       "Force against approach per velocity: FEM, calibrated Hunt–Crossley and the best "
       "comparison law.",
       std::move(per_run.loops)},
      {FigureId::histories, "", "histories.png",
       "Approach and contact force against time since first contact, per velocity: FEM, "
       "calibrated Hunt–Crossley and the best comparison law.",
       std::move(per_run.histories)},
      {FigureId::residuals, "", "residuals.png",
       "Force residuals (model - FEM) / F_max against time, per velocity.",
       std::move(per_run.residuals)},
      {FigureId::quantities, "", "quantities.png",
       "Restitution, energy loss, contact time, peak force and peak approach against V: FEM "
       "(with its uncertainty where known) and the models, with the jackknife prediction bands "
       "of the calibrated Hunt–Crossley and the best law.",
       quantities_figure(report)},
      {FigureId::energy_loss, "", "energy_loss.png",
       "1 - e against V in log-log: the FEM, its power-law fit, the reference slopes "
       "(Hunt–Crossley 1, Kuwabara–Kono 1/5, constant e 0) and the models with their "
       "prediction bands.",
       energy_loss_figure(report)}};
  if (report.calibration)
    figures.push_back({FigureId::damping, "", "damping.png",
                       "Per-run b against V: from the restitution (exact inverse of k) and from "
                       "each run's force-history fit (with its interval), the campaign b with "
                       "its jackknife interval, the b(V) fit and the published b.",
                       damping_figure(report)});
  for (auto& [model, data] : map_figures(report)) {
    const std::string title = data["title"].get<std::string>();
    figures.push_back({FigureId::validity_map, model->key, "map_" + model->key + ".png",
                       title + ": the class of each cell (one run) by the verdict's rule, with "
                               "its largest error and the FEM's uncertainty.",
                       std::move(data)});
  }
  for (auto& figure : detail::plastic_figures(report)) figures.push_back(std::move(figure));
  figures.push_back({FigureId::errors, "", "errors.png",
                     "Each model's error in the four quantities the verdict judges (out of sample "
                     "where the model is fitted and there are three velocities or more), the "
                     "tolerance bands and the FEM's uncertainty (bars at 0); logarithmic beyond "
                     "twice the widest band.",
                     errors_figure(report)});
  return figures;
}

json figure_specification(const Report& report) {
  json figures = json::array();
  for (auto& figure : report_figures(report)) {
    json data = std::move(figure.data);
    data["file"] = figure.file;
    figures.push_back(std::move(data));
  }
  return {{"figures", figures}};
}

} // namespace impact::postprocess
