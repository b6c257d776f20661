// The calibration JSON (calibration_json.hpp): the writer (the typed reader of the same
// layout: calibration_json_reader.cpp), and the recommended Hunt–Crossley fit.

#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- Writing ----------------------------------------------------------------------------

json number(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

json estimate_json(const Estimate& estimate, const std::string& unit, bool fixed) {
  return {{"value", number(estimate.value)},
          {"standard_error", number(estimate.standard_error)},
          {"interval", json::array({number(estimate.lower), number(estimate.upper)})},
          {"unit", unit},
          {"fixed", fixed}};
}

json quality_json(const FitQuality& quality) {
  return {{"rms_residual", number(quality.rms_residual)},
          {"r_squared", number(quality.r_squared)},
          {"samples", quality.samples}};
}

json prediction_json(const ImpactPrediction& prediction) {
  return {{"damping", number(prediction.damping)},
          {"restitution", number(prediction.restitution)},
          {"contact_time", number(prediction.contact_time)},
          {"force_max", number(prediction.force_max)},
          {"time_force_max", number(prediction.time_force_max)},
          {"approach_max", number(prediction.approach_max)}};
}

json quantities_json(const ImpactFigures& quantities) {
  return {{"restitution", number(quantities.restitution)},
          {"contact_time", number(quantities.contact_time)},
          {"force_max", number(quantities.force_max)},
          {"time_force_max", number(quantities.time_force_max)},
          {"approach_max", number(quantities.approach_max)}};
}

std::vector<std::string> units_of(const ModelFit& fit) {
  std::vector<std::string> units{"N/m^n", "1", fit.parameter_unit};
  for (const auto& entry : fit.extra) units.push_back(entry.unit);
  return units;
}

json fit_json(const ModelFit& fit) {
  const std::vector<std::string> names = fit.parameter_names();
  const std::size_t k = names.size();
  json parameters = {{"c", estimate_json(fit.stiffness, "N/m^n", fit.stiffness_fixed)},
                     {"n", estimate_json(fit.exponent, "1", fit.exponent_fixed)},
                     {fit.parameter_name,
                      estimate_json(fit.parameter, fit.parameter_unit, fit.parameter_fixed)}};
  for (const auto& entry : fit.extra)
    parameters[entry.name] = estimate_json(entry.estimate, entry.unit, false);
  json correlation = json::object(), covariance = json::array();
  for (std::size_t i = 0; i < k; ++i) {
    json row = json::array();
    for (std::size_t j = 0; j < k; ++j) {
      row.push_back(number(fit.covariance.size() == k * k ? fit.covariance[i * k + j] : nan));
      if (j > i)
        correlation[names[i] + "," + names[j]] =
            number(fit.correlation.size() == k * k ? fit.correlation[i * k + j] : nan);
    }
    covariance.push_back(row);
  }
  json result = {{"model", fit.model},
                 {"parameters", parameters},
                 {"parameter_order", names},
                 {"free_parameters", fit.free_parameters()},
                 {"correlation", correlation},
                 {"covariance", {{"order", names}, {"matrix", covariance}}},
                 {"reference_approach", {{"value", number(fit.reference_approach)}, {"unit", "m"}}},
                 {"force_at_reference_approach", estimate_json(fit.force_at_reference, "N", false)},
                 {"converged", fit.converged},
                 {"iterations", fit.iterations},
                 {"solver_message", fit.solver_message}};
  result.update(quality_json(fit.quality));
  return result;
}

json parameter_values_json(const std::vector<std::string>& names,
                           const std::vector<double>& values) {
  json result = json::object();
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
    result[names[i]] = number(values[i]);
  return result;
}

json campaign_fit_json(const CampaignModelFit& campaign_fit) {
  json result = fit_json(campaign_fit.fit);
  const auto names = campaign_fit.fit.parameter_names();
  result["key"] = campaign_fit.key;
  result["label"] = campaign_fit.label;
  result["formula"] = campaign_fit.formula;
  result["reference"] = campaign_fit.reference;
  result["damping"] = {{"name", campaign_fit.damping_name}, {"unit", campaign_fit.damping_unit}};
  result["energy_weight"] = campaign_fit.energy_weight;
  result["intervals"] =
      "parameters[].interval: s^2 (J^T J)^-1, conditional on the model (residuals taken as "
      "independent noise); jackknife: over the fits with one velocity left out";
  json runs = json::array();
  for (const auto& run : campaign_fit.runs) {
    json entry = {{"source", run.source}, {"impact_velocity", number(run.velocity)}};
    entry.update(quality_json(run.quality));
    entry["prediction"] = prediction_json(run.prediction);
    entry["out_of_sample"] =
        run.out_of_sample ? prediction_json(*run.out_of_sample) : json(nullptr);
    runs.push_back(entry);
  }
  result["runs"] = runs;
  json held_out = json::array();
  for (const auto& fit : campaign_fit.held_out)
    held_out.push_back({{"velocity", number(fit.velocity)},
                        {"parameters", parameter_values_json(names, fit.parameters)},
                        {"converged", fit.converged}});
  result["held_out"] = held_out;
  if (campaign_fit.jackknife.empty()) {
    result["jackknife"] = nullptr;
  } else {
    json jackknife = json::object();
    const auto units = units_of(campaign_fit.fit);
    for (std::size_t i = 0; i < names.size() && i < campaign_fit.jackknife.size(); ++i) {
      json entry = estimate_json(campaign_fit.jackknife[i], units[i], false);
      entry.erase("fixed");
      jackknife[names[i]] = entry;
    }
    result["jackknife"] = jackknife;
  }
  return result;
}

json reference_json(const ReferenceModel& reference) {
  json parameters = {{"c", number(reference.stiffness)}, {"n", number(reference.exponent)}};
  if (!reference.dissipation.empty())
    parameters[reference.parameter_name] = number(reference.dissipation[0]);
  json extra = json::array();
  for (std::size_t i = 0; i < reference.extra_names.size() && i + 1 < reference.dissipation.size();
       ++i) {
    parameters[reference.extra_names[i]] = number(reference.dissipation[i + 1]);
    extra.push_back({{"name", reference.extra_names[i]},
                     {"unit", i < reference.extra_units.size() ? reference.extra_units[i] : ""}});
  }
  json runs = json::array();
  for (const auto& run : reference.runs) {
    json entry = {{"source", run.source}, {"impact_velocity", number(run.velocity)}};
    entry.update(quality_json(run.quality));
    entry["prediction"] = prediction_json(run.prediction);
    runs.push_back(entry);
  }
  return {{"key", reference.key},
          {"label", reference.label},
          {"model", reference.model},
          {"basis", reference.basis},
          {"parameters", parameters},
          {"parameter", {{"name", reference.parameter_name}, {"unit", reference.parameter_unit}}},
          {"extra_parameters", extra},
          {"runs", runs}};
}

json run_json(const RunCalibration& run) {
  return {{"source", run.source},
          {"impact_velocity", number(run.velocity)},
          {"mass", number(run.mass)},
          {"measured", quantities_json(run.measured)},
          {"restitution_fit",
           {{"b", {{"value", number(run.damping_from_restitution)}, {"unit", "s/m"}}},
            {"beta", number(run.impact_parameter)},
            {"method",
             "exact inverse of k(beta) (impact_parameter_from_restitution), b = beta / V; "
             "no interval: exact for the measured restitution"}}},
          {"loading_fit", run.loading ? fit_json(*run.loading) : json(nullptr)},
          {"history_fit", run.history ? fit_json(*run.history) : json(nullptr)},
          {"history_prediction",
           run.history_prediction ? prediction_json(*run.history_prediction) : json(nullptr)}};
}

json ranking_json(const CampaignCalibration& campaign) {
  json ranking = json::array();
  for (const auto& entry : campaign.ranking) {
    json parameter = nullptr;
    if (const CampaignModelFit* fit = campaign.find(entry.key))
      parameter = {{"name", fit->fit.parameter_name},
                   {"value", number(fit->fit.parameter.value)},
                   {"unit", fit->fit.parameter_unit}};
    for (const auto& reference : campaign.reference_models)
      if (reference.key == entry.key)
        parameter = {{"name", reference.parameter_name},
                     {"value",
                      number(reference.dissipation.empty() ? nan : reference.dissipation[0])},
                     {"unit", reference.parameter_unit}};
    ranking.push_back({{"model", entry.key},
                       {"free_parameters", entry.free_parameters},
                       {"score", number(entry.score)},
                       {"out_of_sample", entry.out_of_sample},
                       {"worst_error", number(entry.worst_error)},
                       {"in_sample_score", number(entry.in_sample_score)},
                       {"rms_residual", number(entry.rms_residual)},
                       {"converged", entry.converged},
                       {"family", entry.family},
                       {"parameter", parameter}});
  }
  return ranking;
}

json multibody_json(const Calibration& calibration) {
  json multibody = nullptr;
  std::string basis;
  if (const ModelFit* recommended = recommended_hunt_crossley(calibration, &basis))
    multibody = {{"model", std::string(model_keys::hunt_crossley)},
                 {"force_law", "F = c x^n (1 + b dx/dt) for approach x > 0, else F = 0"},
                 {"c", number(recommended->stiffness.value)},
                 {"n", number(recommended->exponent.value)},
                 {"b", number(recommended->parameter.value)},
                 {"units", {{"c", "N/m^n"}, {"n", "1"}, {"b", "s/m"}}},
                 {"basis", basis},
                 {"converged", recommended->converged}};

  return multibody;
}

// b(V): one line more in a multibody code, and what the campaign shows the FEM needs.
json velocity_damping_json(const CampaignCalibration& campaign) {
  json velocity_damping = nullptr;
  if (const auto& fit = campaign.hunt_crossley_velocity_damping)
    velocity_damping = {
        {"model", std::string(model_keys::hunt_crossley_velocity_damping)},
        {"force_law",
         "F = c x^n (1 + b dx/dt) for approach x > 0, else F = 0, with "
         "b = b_1 (V_0 / 1 m/s)^(-q), V_0 the approach speed at first contact"},
        {"c", number(fit->fit.stiffness.value)},
        {"n", number(fit->fit.exponent.value)},
        {"b_1", number(fit->fit.parameter.value)},
        {"q", number(fit->fit.extra.empty() ? nan : fit->fit.extra.front().estimate.value)},
        {"units", {{"c", "N/m^n"}, {"n", "1"}, {"b_1", "s/m"}, {"q", "1"}}},
        {"basis", "campaign fit of " + fit->label},
        {"converged", fit->fit.converged}};

  return velocity_damping;
}

json restitution_maps_json(const CampaignCalibration& campaign) {
  json maps = json::array();
  for (const auto& map : campaign.restitution_maps) {
    json map_runs = json::array();
    for (const auto& run : map.runs)
      map_runs.push_back({{"source", run.source},
                          {"impact_velocity", number(run.velocity)},
                          {"target_restitution", number(run.target)},
                          {"prediction", prediction_json(run.prediction)}});
    maps.push_back({{"law", map.law}, {"formula", map.formula}, {"runs", map_runs}});
  }
  return maps;
}

json units_json() {
  return {{"c", "N/m^n"},
          {"n", "1"},
          {"b", "s/m"},
          {"b_1", "s/m (b at V = 1 m/s)"},
          {"q", "1"},
          {"A", "s"},
          {"e", "1"},
          {"impact_velocity", "m/s"},
          {"mass", "kg"},
          {"restitution", "1"},
          {"contact_time", "s"},
          {"force_max", "N"},
          {"time_force_max", "s (from first contact)"},
          {"approach_max", "m"},
          {"rms_residual", "1 (RMS of (F_model - F_FEM) / peak FEM force of the run)"},
          {"r_squared", "1"},
          {"score", "1 (RMS of the relative errors of 1 - e^2, t_c, F_max, x_max over the runs)"}};
}

json campaign_json(const CampaignCalibration& campaign) {
  const auto optional_fit = [](const std::optional<CampaignModelFit>& fit) {
    return fit ? campaign_fit_json(*fit) : json(nullptr);
  };
  json laws = json::array();
  for (const auto& law : campaign.comparison_laws) laws.push_back(campaign_fit_json(law));
  json references = json::array();
  for (const auto& reference : campaign.reference_models)
    references.push_back(reference_json(reference));
  return {{"fitted", campaign.fitted},
          {"reason", campaign.reason.empty() ? json(nullptr) : json(campaign.reason)},
          {"velocities", campaign.velocities},
          {"energy_weight", campaign.energy_weight},
          {"published_damping", number(campaign.published_damping)},
          {"hertz_stiffness",
           {{"value", number(campaign.hertz_stiffness)},
            {"unit", "N/m^1.5"},
            {"basis", campaign.hertz_basis}}},
          {"material_dissipative_constant",
           {{"value", campaign.material_dissipative_constant
                          ? number(*campaign.material_dissipative_constant)
                          : json(nullptr)},
            {"unit", "s"},
            {"basis", campaign.material_basis}}},
          {"hunt_crossley", optional_fit(campaign.hunt_crossley)},
          {"hunt_crossley_energy", optional_fit(campaign.hunt_crossley_energy)},
          {"hunt_crossley_hertz_exponent", optional_fit(campaign.hunt_crossley_hertz_exponent)},
          {"hunt_crossley_velocity_damping", optional_fit(campaign.hunt_crossley_velocity_damping)},
          {"comparison_laws", laws},
          {"reference_models", references},
          {"restitution_maps", restitution_maps_json(campaign)},
          {"ranking", ranking_json(campaign)}};
}

} // namespace

json to_json(const Calibration& calibration) {
  json problems = json::array();
  for (const auto& problem : calibration.problems)
    problems.push_back({{"source", problem.source},
                        {"kind", std::string(kind_name(problem.kind))},
                        {"message", problem.message}});
  json runs = json::array();
  for (const auto& run : calibration.runs) runs.push_back(run_json(run));
  return {{"format", "impact-calibration"},
          {"format_version", calibration_format_version},
          {"generated_by", "impact-calibrate"},
          {"status", calibration.problems.empty() ? "complete" : "incomplete"},
          {"problems", problems},
          {"confidence_level", calibration.confidence_level},
          {"units", units_json()},
          {"multibody", multibody_json(calibration)},
          {"multibody_velocity_damping", velocity_damping_json(calibration.campaign)},
          {"runs", runs},
          {"campaign", campaign_json(calibration.campaign)}};
}

const ModelFit* recommended_hunt_crossley(const Calibration& calibration, std::string* basis) {
  const CampaignCalibration& campaign = calibration.campaign;
  if (campaign.hunt_crossley) {
    // The constant-b fit with the better rank (out of sample where there is a ranking).
    for (const auto& entry : campaign.ranking)
      if (entry.key == model_keys::hunt_crossley ||
          (entry.key == model_keys::hunt_crossley_energy && campaign.hunt_crossley_energy)) {
        const CampaignModelFit* fit = campaign.find(entry.key);
        if (basis)
          *basis = "campaign fit of hunt-crossley to all runs (" + fit->label +
                   "), the better ranked of the constant-b fits";
        return &fit->fit;
      }
    if (basis) *basis = "campaign fit of hunt-crossley to all runs (force histories)";
    return &campaign.hunt_crossley->fit;
  }
  if (calibration.runs.size() == 1 && calibration.runs.front().history) {
    if (basis) *basis = "force-history fit of the single run " + calibration.runs.front().source;
    return &*calibration.runs.front().history;
  }
  return nullptr;
}

} // namespace impact::postprocess
