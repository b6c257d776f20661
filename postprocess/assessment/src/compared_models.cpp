// The reduced models the report compares with the FEM, in this order:
//   - calibrated: Hunt–Crossley fitted to the force histories of all runs (or, without a
//     campaign fit, each run's own force-history fit, and the page says so);
//   - Hunt–Crossley fitted to the force histories and the energy loss;
//   - Hunt–Crossley with b(V) = b_1 V^-q (histories and energy loss);
//   - best-law: the best-ranked comparison law of the library;
//   - Hunt–Crossley damping on the elastic-plastic springs, fitted (damped_plastic_models.hpp;
//     not again when it is the best law);
//   - Kuwabara–Kono without tension, A from the material (no fit);
//   - Hunt–Crossley on the elastic-plastic springs from the material (no fit);
//   - the published Hunt–Crossley (b of the published example, c from Hertz, n = 3/2);
//   - Hertz (b = 0).
// Predicted values are the calibration's (so the tables hold the JSON's numbers); the
// curves, histories, residuals and prediction bands are recomputed from the parameters by
// impact::reduced (predict_impact, predict_history).

#include "steps.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/same_value.hpp"

#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/plastic_models.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess::detail {

namespace {

namespace fs = std::filesystem;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t model_history_points = 1000;
constexpr std::size_t curve_points = 40;

// The index of the entry of `list` that belongs to the run (source, velocity): same file,
// else the only entry at the same velocity.
template <class Entry>
std::optional<std::size_t> matching(const std::vector<Entry>& list, const std::string& source,
                                    double velocity) {
  for (std::size_t i = 0; i < list.size(); ++i)
    if (same_source(list[i].source, source)) return i;
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < list.size(); ++i)
    if (same_velocity(list[i].velocity, velocity)) {
      if (found) return std::nullopt; // ambiguous
      found = i;
    }
  return found;
}

std::vector<ModelParameter> parameters_of(const std::vector<std::string>& names,
                                          const std::vector<std::string>& units,
                                          const std::vector<double>& values) {
  std::vector<ModelParameter> parameters;
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
    parameters.push_back({names[i], values[i], units[i]});
  return parameters;
}

ImpactHistory history_of(const std::vector<reduced::ImpactSample>& samples) {
  ImpactHistory history;
  for (const auto& sample : samples) {
    history.time.push_back(sample.time);
    history.approach.push_back(sample.approach);
    history.force.push_back(sample.force);
  }
  return history;
}

// (F_model - F_FEM) / F_max at the FEM history's times; the model force interpolated
// linearly between its samples (1000 per contact: far below the residuals shown).
std::vector<double> residual_of(const ImpactHistory& model, const ReportRun& run) {
  std::vector<double> residual;
  if (model.time.size() < 2) return residual;
  for (std::size_t i = 0; i < run.fem_history.time.size(); ++i) {
    const double t = run.fem_history.time[i];
    double force = 0;
    if (t > 0 && t < model.time.back()) {
      const auto after = std::upper_bound(model.time.begin(), model.time.end(), t);
      const std::size_t k = std::size_t(after - model.time.begin());
      const double s = (t - model.time[k - 1]) / (model.time[k] - model.time[k - 1]);
      force = (1 - s) * model.force[k - 1] + s * model.force[k];
    }
    residual.push_back((force - run.fem_history.force[i]) / run.fem.force_max);
  }
  return residual;
}

double median_mass(const std::vector<ReportRun>& runs) {
  std::vector<double> masses;
  for (const auto& run : runs) masses.push_back(run.mass);
  std::sort(masses.begin(), masses.end());
  return masses.empty() ? nan : masses[masses.size() / 2];
}

std::vector<double> velocity_grid(const std::vector<ReportRun>& runs) {
  double low = INFINITY, high = 0;
  for (const auto& run : runs) {
    low = std::min(low, run.velocity);
    high = std::max(high, run.velocity);
  }
  std::vector<double> grid;
  if (!(high > low)) return grid;
  for (std::size_t i = 0; i < curve_points; ++i)
    grid.push_back(low * std::pow(high / low, double(i) / double(curve_points - 1)));
  return grid;
}

// Values of every quantity along the grid for parameters (c, n, dissipation...).
std::array<std::vector<double>, quantity_count> along(const ContactModel& model, double mass,
                                                      const std::vector<double>& grid,
                                                      const std::vector<double>& parameters) {
  std::array<std::vector<double>, quantity_count> values;
  const std::vector<double> dissipation(parameters.begin() + 2, parameters.end());
  for (double velocity : grid) {
    const ImpactFigures impact =
        predict_impact(model, mass, velocity, parameters[0], parameters[1], dissipation);
    for (Quantity quantity : all_quantities)
      values[std::size_t(quantity)].push_back(value(impact, quantity));
  }
  return values;
}

PredictionBand curve_of(const ContactModel& model, double mass, const std::vector<double>& grid,
                        const std::vector<double>& parameters) {
  PredictionBand curve;
  curve.velocity = grid;
  curve.center = along(model, mass, grid, parameters);
  return curve;
}

// Jackknife band: +- t_{g-1} sqrt((g-1)/g sum (y_i - mean)^2) about the full fit's curve.
std::optional<PredictionBand> band_of(const ContactModel& model, double mass,
                                      const std::vector<double>& grid, const CampaignModelFit& fit,
                                      double level) {
  const std::size_t g = fit.held_out.size();
  if (g < 3 || grid.empty()) return std::nullopt;
  PredictionBand band = curve_of(model, mass, grid, fit.fit.parameter_values());
  std::vector<std::array<std::vector<double>, quantity_count>> held;
  for (const auto& held_out : fit.held_out)
    held.push_back(along(model, mass, grid, held_out.parameters));
  const boost::math::students_t distribution{double(g - 1)};
  const double t = boost::math::quantile(distribution, 0.5 + level / 2);
  for (std::size_t q = 0; q < quantity_count; ++q)
    for (std::size_t j = 0; j < grid.size(); ++j) {
      double mean = 0;
      for (const auto& values : held) mean += values[q][j] / double(g);
      double sum = 0;
      for (const auto& values : held) sum += (values[q][j] - mean) * (values[q][j] - mean);
      const double error = std::sqrt(double(g - 1) / double(g) * sum);
      band.lower[q].push_back(band.center[q][j] - t * error);
      band.upper[q].push_back(band.center[q][j] + t * error);
    }
  return band;
}

// The histories and residuals of a model with fixed parameters at every run.
void add_histories(ReportModel& model, const ContactModel& law, const std::vector<ReportRun>& runs,
                   const std::vector<double>& parameters) {
  const std::vector<double> dissipation(parameters.begin() + 2, parameters.end());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    ModelAtRun& at = model.runs[i];
    try {
      at.history = history_of(predict_history(law, runs[i].mass, runs[i].velocity, parameters[0],
                                              parameters[1], dissipation, model_history_points));
      at.residual = residual_of(at.history, runs[i]);
    } catch (const std::exception& error) {
      at.history = {};
      if (!at.missing) at.missing = NoValue{NoValueReason::no_history, error.what()};
    }
  }
}

// The model of `name` with the scenario's constants where it needs them.
ContactModel model_named(const std::string& name, const std::vector<FemRun>& fem_runs) {
  return needs_scenario(name) ? comparison_model(name, fem_runs) : contact_model(name);
}

ReportModel fitted_model(const std::vector<ReportRun>& runs, const std::vector<FemRun>& fem_runs,
                         const CampaignModelFit& fit, std::string key, std::string label,
                         ModelBasis basis, double level) {
  const ModelFit& parameters = fit.fit;
  std::vector<std::string> units{"N/m^n", "1", parameters.parameter_unit};
  for (const auto& extra : parameters.extra) units.push_back(extra.unit);
  ReportModel model;
  model.key = std::move(key);
  model.label = std::move(label);
  model.parameters =
      parameters_of(parameters.parameter_names(), units, parameters.parameter_values());
  model.basis = basis;
  model.calibration_key = fit.key;
  model.free_parameters = parameters.free_parameters();
  model.converged = parameters.converged;
  model.out_of_sample = !fit.held_out.empty();
  for (const auto& run : runs) {
    ModelAtRun at;
    if (const auto index = matching(fit.runs, run.source, run.velocity)) {
      const RunResidual& residual = fit.runs[*index];
      const ImpactFigures in = residual.prediction;
      if (std::isfinite(in.restitution))
        at.in_sample = in;
      else
        at.missing = NoValue{NoValueReason::prediction_incomplete, fit.key};
      if (residual.out_of_sample) at.out_of_sample = *residual.out_of_sample;
    } else {
      at.missing = NoValue{NoValueReason::no_prediction_for_run, fit.key};
    }
    model.runs.push_back(std::move(at));
  }
  try {
    const ContactModel law = model_named(parameters.model, fem_runs);
    add_histories(model, law, runs, parameters.parameter_values());
    const auto grid = velocity_grid(runs);
    if (!grid.empty()) {
      model.curve = curve_of(law, median_mass(runs), grid, parameters.parameter_values());
      model.band = band_of(law, median_mass(runs), grid, fit, level);
    }
  } catch (const std::exception& error) {
    for (auto& at : model.runs)
      if (!at.missing) at.missing = NoValue{NoValueReason::no_history, error.what()};
  }
  return model;
}

ReportModel reference_model(const std::vector<ReportRun>& runs, const std::vector<FemRun>& fem_runs,
                            const ReferenceModel& reference, std::string label) {
  ReportModel model;
  model.key = reference.key;
  model.label = std::move(label);
  std::vector<double> values{reference.stiffness, reference.exponent};
  values.insert(values.end(), reference.dissipation.begin(), reference.dissipation.end());
  std::vector<std::string> names{"c", "n", reference.parameter_name},
      units{"N/m^n", "1", reference.parameter_unit};
  names.insert(names.end(), reference.extra_names.begin(), reference.extra_names.end());
  units.insert(units.end(), reference.extra_units.begin(), reference.extra_units.end());
  model.parameters = parameters_of(names, units, values);
  model.basis = ModelBasis::nothing_fitted;
  model.calibration_key = reference.key;
  model.out_of_sample = true; // nothing fitted
  for (const auto& run : runs) {
    ModelAtRun at;
    if (const auto index = matching(reference.runs, run.source, run.velocity)) {
      const ImpactFigures impact = reference.runs[*index].prediction;
      if (std::isfinite(impact.restitution))
        at.in_sample = at.out_of_sample = impact;
      else
        at.missing = NoValue{NoValueReason::not_evaluable, ""};
    } else {
      at.missing = NoValue{NoValueReason::no_prediction_for_run, reference.key};
    }
    model.runs.push_back(std::move(at));
  }
  try {
    const ContactModel law = model_named(reference.model, fem_runs);
    add_histories(model, law, runs, values);
    const auto grid = velocity_grid(runs);
    if (!grid.empty()) model.curve = curve_of(law, median_mass(runs), grid, values);
  } catch (const std::exception& error) {
    for (auto& at : model.runs)
      if (!at.missing) at.missing = NoValue{NoValueReason::no_history, error.what()};
  }
  return model;
}

// Each run's own force-history fit, for a calibration without a campaign fit.
// (The page says why there is no campaign fit: the calibration's reason.)
ReportModel per_run_model(const std::vector<ReportRun>& runs, const Calibration& calibration) {
  ReportModel model;
  model.key = std::string(model_keys::calibrated);
  model.label = "Hunt–Crossley (per-run fit)";
  model.basis = ModelBasis::per_run_fits;
  model.free_parameters = 3;
  const ContactModel law = hunt_crossley_model();
  for (const auto& run : runs) {
    ModelAtRun at;
    const auto index = matching(calibration.runs, run.source, run.velocity);
    const RunCalibration* entry = index ? &calibration.runs[*index] : nullptr;
    if (!entry || !entry->history) {
      at.missing = NoValue{NoValueReason::no_run_fit, ""};
      model.runs.push_back(std::move(at));
      continue;
    }
    if (!entry->history->converged) model.converged = false;
    if (entry->history_prediction)
      at.in_sample = *entry->history_prediction;
    else
      at.missing = NoValue{NoValueReason::no_run_fit_prediction, ""};
    try {
      const ModelFit& fit = *entry->history;
      at.history =
          history_of(predict_history(law, run.mass, run.velocity, fit.stiffness.value,
                                     fit.exponent.value, fit.dissipation(), model_history_points));
      at.residual = residual_of(at.history, run);
    } catch (const std::exception& error) {
      if (!at.missing) at.missing = NoValue{NoValueReason::no_history, error.what()};
    }
    model.runs.push_back(std::move(at));
  }
  return model;
}

// The page's name of a damped elastic-plastic law (damped_plastic_models.hpp), none for
// another key.
std::optional<std::string> damped_label(const std::string& key) {
  if (key == model_keys::hunt_crossley_thornton) return "Hunt–Crossley on Thornton";
  if (key == model_keys::hunt_crossley_jackson_green) return "Hunt–Crossley on Jackson–Green";
  if (key == model_keys::hunt_crossley_thornton_from_a)
    return "Hunt–Crossley on Thornton, b ∝ V^-4/5";
  if (key == model_keys::hunt_crossley_jackson_green_from_a)
    return "Hunt–Crossley on Jackson–Green, b ∝ V^-4/5";
  if (key == model_keys::kuwabara_kono_thornton) return "Kuwabara–Kono on Thornton";
  if (key == model_keys::kuwabara_kono_jackson_green) return "Kuwabara–Kono on Jackson–Green";
  return std::nullopt;
}

// A model without values: `why` is its basis and the reason at every run.
ReportModel missing_model(const std::vector<ReportRun>& runs, std::string key, std::string label,
                          NoValueReason why) {
  ReportModel model;
  model.key = std::move(key);
  model.label = std::move(label);
  model.basis = why == NoValueReason::no_calibration ? ModelBasis::no_calibration
                                                     : ModelBasis::no_comparison_law;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    ModelAtRun at;
    at.missing = NoValue{why, ""};
    model.runs.push_back(std::move(at));
  }
  return model;
}

} // namespace

bool same_source(const std::string& a, const std::string& b) {
  if (a == b) return true;
  std::error_code error;
  const fs::path pa = fs::weakly_canonical(a, error);
  if (error) return false;
  const fs::path pb = fs::weakly_canonical(b, error);
  return !error && pa == pb;
}

bool same_velocity(double a, double b) {
  return same_value(a, b);
}

namespace {

// The comparison law ranked first, fitted to all runs; missing when none was fitted.
ReportModel best_law_model(const std::vector<ReportRun>& runs, const std::vector<FemRun>& fem_runs,
                           const CampaignCalibration& campaign, double level) {
  const CampaignModelFit* best = nullptr;
  const RankedModel* best_entry = nullptr;
  for (const auto& entry : campaign.ranking) {
    for (const auto& law : campaign.comparison_laws)
      if (law.key == entry.key) {
        best = &law;
        best_entry = &entry;
      }
    if (best) break;
  }
  // Scored in sample (fewer than three velocities), the rank says how well the law fits
  // these runs, not how well it predicts another velocity.
  if (best)
    return fitted_model(runs, fem_runs, *best, std::string(model_keys::best_law),
                        damped_label(best->key).value_or(best->key) + " (best law)",
                        best_entry->out_of_sample ? ModelBasis::best_law
                                                  : ModelBasis::best_law_in_sample,
                        level);
  return missing_model(runs, std::string(model_keys::best_law), "best comparison law",
                       NoValueReason::no_comparison_law);
}

// The models that fit nothing: from the material (Kuwabara–Kono, the damped elastic-plastic
// laws), Hunt–Crossley with a published damping, Hertz.
void add_reference_models(std::vector<ReportModel>& models, const std::vector<ReportRun>& runs,
                          const std::vector<FemRun>& fem_runs,
                          const CampaignCalibration& campaign) {
  const auto reference = [&](const std::string& key) -> const ReferenceModel* {
    for (const auto& model : campaign.reference_models)
      if (model.key == key) return &model;
    return nullptr;
  };
  if (const auto* material = reference(std::string(model_keys::kuwabara_kono_material)))
    models.push_back(
        reference_model(runs, fem_runs, *material, "Kuwabara–Kono (A from the material)"));
  if (const auto* damped = reference(std::string(model_keys::hunt_crossley_thornton_material)))
    models.push_back(
        reference_model(runs, fem_runs, *damped, "Hunt–Crossley on Thornton (from the material)"));
  for (const auto& [key, label] : {std::pair{model_keys::hunt_crossley_jackson_green_material,
                                             "Hunt–Crossley on Jackson–Green (from the material)"},
                                   std::pair{model_keys::kuwabara_kono_thornton_material,
                                             "Kuwabara–Kono on Thornton (from the material)"},
                                   std::pair{model_keys::kuwabara_kono_jackson_green_material,
                                             "Kuwabara–Kono on Jackson–Green (from the material)"}})
    if (const auto* damped = reference(std::string(key)))
      models.push_back(reference_model(runs, fem_runs, *damped, label));
  if (const auto* published = reference(std::string(model_keys::hunt_crossley_published)))
    models.push_back(reference_model(runs, fem_runs, *published, published->label));
  if (const auto* hertz = reference(std::string(model_keys::hertz)))
    models.push_back(reference_model(runs, fem_runs, *hertz, hertz->label));
}

} // namespace

std::vector<ReportModel> report_models(const std::vector<ReportRun>& runs,
                                       const std::vector<FemRun>& fem_runs,
                                       const std::optional<Calibration>& calibration,
                                       std::vector<Problem>& problems) {
  std::vector<ReportModel> models;
  if (!calibration) {
    models.push_back(missing_model(runs, std::string(model_keys::calibrated),
                                   "Hunt–Crossley (calibrated)", NoValueReason::no_calibration));
    return models;
  }
  const CampaignCalibration& campaign = calibration->campaign;
  const double level = calibration->confidence_level;
  if (campaign.fitted && campaign.hunt_crossley)
    models.push_back(fitted_model(runs, fem_runs, *campaign.hunt_crossley,
                                  std::string(model_keys::calibrated), "Hunt–Crossley (calibrated)",
                                  ModelBasis::campaign_fit, level));
  else
    models.push_back(per_run_model(runs, *calibration));
  if (campaign.fitted && campaign.hunt_crossley_energy)
    models.push_back(fitted_model(runs, fem_runs, *campaign.hunt_crossley_energy,
                                  campaign.hunt_crossley_energy->key,
                                  "Hunt–Crossley (force + energy)",
                                  ModelBasis::force_and_energy_fit, level));
  if (campaign.fitted && campaign.hunt_crossley_velocity_damping)
    models.push_back(fitted_model(runs, fem_runs, *campaign.hunt_crossley_velocity_damping,
                                  campaign.hunt_crossley_velocity_damping->key,
                                  "Hunt–Crossley b(V)", ModelBasis::velocity_damping_fit, level));
  if (campaign.fitted) models.push_back(best_law_model(runs, fem_runs, campaign, level));
  // The damped elastic-plastic laws (damped_plastic_models.hpp), fitted, unless one of them is
  // the best law shown above.
  std::string best_key;
  for (const auto& model : models)
    if (model.key == model_keys::best_law) best_key = model.calibration_key;
  if (campaign.fitted)
    for (const auto& key : damped_plastic_model_names()) {
      const CampaignModelFit* fit = campaign.find(key);
      if (fit && best_key != key)
        models.push_back(fitted_model(runs, fem_runs, *fit, fit->key,
                                      *damped_label(key) + " (fitted)",
                                      ModelBasis::damped_plastic_fit, level));
    }
  add_reference_models(models, runs, fem_runs, campaign);
  for (const auto& model : models)
    if (!model.converged)
      problems.push_back({model.label, ProblemKind::convergence,
                          "the fit of " + model.label +
                              " did not converge: its numbers are shown marked 'not converged'"});
  return models;
}

} // namespace impact::postprocess::detail
