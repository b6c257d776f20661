#include "impact_postprocess/calibration_json.hpp"

#include <algorithm>
#include <cmath>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;

json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

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

json fit_json(const ModelFit& fit) {
  const std::string p = fit.parameter_name;
  const std::array<std::string, 3> names = {"c", "n", p};
  json covariance = json::array();
  for (int i = 0; i < 3; ++i) {
    json row = json::array();
    for (int j = 0; j < 3; ++j) row.push_back(number(fit.covariance[i * 3 + j]));
    covariance.push_back(row);
  }
  json result = {
      {"model", fit.model},
      {"parameters",
       {{"c", estimate_json(fit.stiffness, "N/m^n", false)},
        {"n", estimate_json(fit.exponent, "1", fit.exponent_fixed)},
        {p, estimate_json(fit.parameter, fit.parameter_unit, fit.parameter_fixed)}}},
      {"correlation",
       {{"c," + p, number(fit.correlation[2])},
        {"c,n", number(fit.correlation[1])},
        {"n," + p, number(fit.correlation[5])}}},
      {"covariance", {{"order", names}, {"matrix", covariance}}},
      {"reference_approach", {{"value", number(fit.reference_approach)}, {"unit", "m"}}},
      {"force_at_reference_approach", estimate_json(fit.force_at_reference, "N", false)},
      {"converged", fit.converged},
      {"iterations", fit.iterations},
      {"solver_message", fit.solver_message}};
  result.update(quality_json(fit.quality));
  return result;
}

json campaign_fit_json(const CampaignModelFit& campaign_fit) {
  json result = fit_json(campaign_fit.fit);
  result["formula"] = campaign_fit.formula;
  result["reference"] = campaign_fit.reference;
  result["damping"] = {{"name", campaign_fit.damping_name}, {"unit", campaign_fit.damping_unit}};
  json runs = json::array();
  for (const auto& run : campaign_fit.runs) {
    json entry = {{"source", run.source}, {"impact_velocity", number(run.velocity)}};
    entry.update(quality_json(run.quality));
    entry["prediction"] = prediction_json(run.prediction);
    runs.push_back(entry);
  }
  result["runs"] = runs;
  return result;
}

json run_json(const RunCalibration& run) {
  return {{"source", run.source},
          {"impact_velocity", number(run.velocity)},
          {"mass", number(run.mass)},
          {"measured",
           {{"restitution", number(run.measured.restitution)},
            {"contact_time", number(run.measured.contact_time)},
            {"force_max", number(run.measured.force_max)},
            {"time_force_max", number(run.measured.time_force_max)},
            {"approach_max", number(run.measured.approach_max)}}},
          {"restitution_fit",
           {{"b", {{"value", number(run.damping_from_restitution)}, {"unit", "s/m"}}},
            {"beta", number(run.impact_parameter)},
            {"method", "exact inverse of k(beta) (impact_parameter_from_restitution), b = beta / V; "
                       "no interval: exact for the measured restitution"}}},
          {"loading_fit", run.loading ? fit_json(*run.loading) : json(nullptr)},
          {"history_fit", run.history ? fit_json(*run.history) : json(nullptr)},
          {"history_prediction",
           run.history_prediction ? prediction_json(*run.history_prediction) : json(nullptr)}};
}

} // namespace

json to_json(const Calibration& calibration) {
  json problems = json::array();
  for (const auto& problem : calibration.problems)
    problems.push_back(
        {{"source", problem.source}, {"kind", problem.kind}, {"message", problem.message}});

  json runs = json::array();
  for (const auto& run : calibration.runs) runs.push_back(run_json(run));

  const CampaignCalibration& campaign = calibration.campaign;
  json laws = json::array();
  json ranking = json::array();
  std::vector<const CampaignModelFit*> ranked;
  if (campaign.hunt_crossley) ranked.push_back(&*campaign.hunt_crossley);
  for (const auto& law : campaign.comparison_laws) {
    laws.push_back(campaign_fit_json(law));
    ranked.push_back(&law);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto* a, const auto* b) {
    const double ra = a->fit.quality.rms_residual, rb = b->fit.quality.rms_residual;
    if (std::isnan(ra)) return false;
    if (std::isnan(rb)) return true;
    return ra < rb;
  });
  for (const auto* fit : ranked)
    ranking.push_back({{"model", fit->fit.model},
                       {"rms_residual", number(fit->fit.quality.rms_residual)},
                       {"r_squared", number(fit->fit.quality.r_squared)},
                       {"parameter",
                        {{"name", fit->fit.parameter_name},
                         {"value", number(fit->fit.parameter.value)},
                         {"unit", fit->fit.parameter_unit}}},
                       {"converged", fit->fit.converged}});

  // The recommendation for a multibody code: the campaign fit, else a single run's.
  json multibody = nullptr;
  const ModelFit* recommended = nullptr;
  std::string basis;
  if (campaign.hunt_crossley) {
    recommended = &campaign.hunt_crossley->fit;
    basis = "campaign fit of hunt-crossley to all runs";
  } else if (calibration.runs.size() == 1 && calibration.runs.front().history) {
    recommended = &*calibration.runs.front().history;
    basis = "force-history fit of the single run " + calibration.runs.front().source;
  }
  if (recommended)
    multibody = {{"model", "hunt-crossley"},
                 {"force_law", "F = c x^n (1 + b dx/dt) for approach x > 0, else F = 0"},
                 {"c", number(recommended->stiffness.value)},
                 {"n", number(recommended->exponent.value)},
                 {"b", number(recommended->parameter.value)},
                 {"units", {{"c", "N/m^n"}, {"n", "1"}, {"b", "s/m"}}},
                 {"basis", basis},
                 {"converged", recommended->converged}};

  return {
      {"format", "impact-calibration"},
      {"format_version", calibration_format_version},
      {"generated_by", "impact-calibrate"},
      {"status", calibration.problems.empty() ? "complete" : "incomplete"},
      {"problems", problems},
      {"confidence_level", calibration.confidence_level},
      {"units",
       {{"c", "N/m^n"},
        {"n", "1"},
        {"b", "s/m"},
        {"e", "1"},
        {"impact_velocity", "m/s"},
        {"mass", "kg"},
        {"restitution", "1"},
        {"contact_time", "s"},
        {"force_max", "N"},
        {"time_force_max", "s (from first contact)"},
        {"approach_max", "m"},
        {"rms_residual", "1 (RMS of (F_model - F_FEM) / peak FEM force of the run)"},
        {"r_squared", "1"}}},
      {"multibody", multibody},
      {"runs", runs},
      {"campaign",
       {{"fitted", campaign.fitted},
        {"reason", campaign.reason.empty() ? json(nullptr) : json(campaign.reason)},
        {"velocities", campaign.velocities},
        {"hunt_crossley",
         campaign.hunt_crossley ? campaign_fit_json(*campaign.hunt_crossley) : json(nullptr)},
        {"hunt_crossley_hertz_exponent",
         campaign.hunt_crossley_hertz_exponent
             ? campaign_fit_json(*campaign.hunt_crossley_hertz_exponent)
             : json(nullptr)},
        {"comparison_laws", laws},
        {"ranking", ranking}}}};
}

} // namespace impact::postprocess
