// calibrate() of calibration.hpp: the per-run fits (run_fits.cpp), the models that fit
// nothing (reference_models.cpp), the campaign fits (campaign_fits.cpp) and the ranking
// (ranking.cpp), on the machinery of fit_model.hpp. Every fit works on the internal parameters
//     theta = (ln F_ref, n, p / p_scale, extra...),   F_ref = c x_ref^n,
// with x_ref a typical approach of the data: ln c and n are almost perfectly correlated
// (ln F = ln c + n ln x with ln x ~ -10), ln F_ref and n are not, so the solver and the
// covariance work on a well-conditioned problem; the covariance is mapped back to
// (c, n, p, ...) by the Jacobian of that change of variables.

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "fit_model.hpp"
#include "ranking.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <algorithm>
#include <functional>
#include <cmath>

namespace impact::postprocess {

namespace detail {

FitQuality combine(const std::vector<FitQuality>& parts) {
  double squares = 0, weights = 0;
  std::size_t samples = 0;
  double r_squared = 0;
  for (const auto& part : parts) {
    squares += part.rms_residual * part.rms_residual * double(part.samples);
    samples += part.samples;
    r_squared += part.r_squared * double(part.samples);
    weights += double(part.samples);
  }
  return {std::sqrt(squares / double(samples)), r_squared / weights, samples};
}

} // namespace detail

// The fit machinery (fit_model.hpp), combine and the ranking (ranking.hpp).
using namespace detail;

std::vector<double> ModelFit::dissipation() const {
  std::vector<double> values{parameter.value};
  for (const auto& entry : extra) values.push_back(entry.estimate.value);
  return values;
}

std::vector<double> ModelFit::parameter_values() const {
  std::vector<double> values{stiffness.value, exponent.value};
  for (double p : dissipation()) values.push_back(p);
  return values;
}

std::vector<std::string> ModelFit::parameter_names() const {
  std::vector<std::string> names{"c", "n", parameter_name};
  for (const auto& entry : extra) names.push_back(entry.name);
  return names;
}

std::size_t ModelFit::free_parameters() const {
  return (stiffness_fixed ? 0 : 1) + (exponent_fixed ? 0 : 1) + (parameter_fixed ? 0 : 1) +
         extra.size();
}

std::vector<const CampaignModelFit*> CampaignCalibration::models() const {
  std::vector<const CampaignModelFit*> all;
  for (const auto* fit : {&hunt_crossley, &hunt_crossley_energy, &hunt_crossley_hertz_exponent,
                          &hunt_crossley_velocity_damping})
    if (*fit) all.push_back(&**fit);
  for (const auto& law : comparison_laws) all.push_back(&law);
  return all;
}

const CampaignModelFit* CampaignCalibration::find(const std::string& key) const {
  for (const CampaignModelFit* model : models())
    if (model->key == key) return model;
  return nullptr;
}

namespace {

void check_options(const CalibrationOptions& options) {
  if (!(options.confidence_level > 0 && options.confidence_level < 1))
    throw reduced::InvalidInput("confidence_level", "the confidence level must be in (0, 1)");
  if (options.max_iterations < 1)
    throw reduced::InvalidInput("max_iterations", "the iteration limit must be at least 1");
  if (!(options.energy_weight >= 0) || !std::isfinite(options.energy_weight))
    throw reduced::InvalidInput("energy_weight", "the energy weight must be a number >= 0");
  if (!(options.published_damping >= 0) || !std::isfinite(options.published_damping))
    throw reduced::InvalidInput("published_damping", "the published damping must be >= 0 s/m");
}

// The campaign fits' start: typical approach, velocity, mass and restitution of the runs, and
// the median of the per-run fits of F_ref and n; `damping` the median per-run b.
CampaignStart campaign_start(const std::vector<FemRun>& runs,
                             const std::vector<RunCalibration>& calibrated, double& damping) {
  CampaignStart start;
  std::vector<double> approaches, velocities, masses, restitutions;
  for (const auto& run : runs) {
    approaches.push_back(run.approach_max);
    velocities.push_back(run.impact_velocity);
    masses.push_back(run.mass);
    restitutions.push_back(run.restitution);
  }
  start.reference_approach = geometric_mean(approaches);
  start.velocity = geometric_mean(velocities);
  start.mass = median(masses);
  start.restitution = std::min(median(restitutions), 1.0);
  std::vector<double> log_forces, exponents, dampings;
  for (const auto& run : calibrated) {
    const auto& fit = run.history ? run.history : run.loading;
    if (!fit) continue;
    log_forces.push_back(std::log(fit->stiffness.value) +
                         fit->exponent.value * std::log(start.reference_approach));
    exponents.push_back(fit->exponent.value);
    dampings.push_back(run.history ? run.history->parameter.value : run.damping_from_restitution);
  }
  start.log_reference_force = median(log_forces);
  start.exponent = median(exponents);
  if (!std::isfinite(start.log_reference_force)) {
    start.exponent = 1.5;
    start.log_reference_force = std::log(median(std::vector<double>{runs.front().force_max}));
  }

  damping = median(dampings);
  return start;
}

// The campaign fit of a damped elastic-plastic model (damped_plastic_models.hpp): c held at
// the Hertz value of the runs' materials when they record them (else, or when the options say
// so, free); the force
// histories and the energy loss (the damping term is about 1 % of the force at low V, so the
// histories alone leave the viscous loss there to the fast runs); started from the fitted
// rate-independent twin's yield parameter (else the material's, else the restitution map),
// and from the b that the material's A gives at the campaign's typical velocity (else
// 0.01 s/m).
CampaignFitRequest damped_plastic_request(const ContactModel& law, const std::vector<FemRun>& runs,
                                          const CampaignCalibration& campaign,
                                          const CampaignStart& start,
                                          const CalibrationOptions& options) {
  const ScenarioMaterials materials = scenario_materials(runs);
  CampaignFitRequest request{law.name, law.name, std::nullopt, options.energy_weight,
                             nan,      {},       std::nullopt};
  request.label +=
      options.energy_weight > 0 ? ", force histories and energy loss" : ", force histories";
  if (materials.hertz_from_runs && options.damped_plastic_hertz_stiffness) {
    request.stiffness = materials.hertz_stiffness;
    request.label += ", c at Hertz";
  }
  const bool thornton_spring = !damped_plastic_needs_scenario(law.name);
  const std::string twin(thornton_spring ? model_keys::thornton : model_keys::jackson_green);
  if (const CampaignModelFit* fitted = campaign.find(twin); fitted && fitted->fit.converged) {
    request.initial_damping = fitted->fit.parameter.value;
  } else if (thornton_spring) {
    if (const auto material = material_thornton(runs))
      request.initial_damping = material->yield_approach;
  } else if (const auto material = material_jackson_green(runs)) {
    request.initial_damping = material->yield_strength;
  }
  const double a = materials.dissipative_constant.value_or(0.0);
  const bool matched = law.extra_parameters.front().name == "A";
  if (matched)
    request.initial_extra = {a > 0 ? a : law.extra_parameters.front().initial};
  else
    request.initial_extra = {
        a > 0 ? matched_hunt_crossley_damping(
                    a, start.velocity,
                    {start.mass, request.stiffness.value_or(materials.hertz_stiffness), 1.5})
              : 0.01};
  return request;
}

// Fits one model to the campaign (and without each velocity), saying so on the progress.
using CampaignFit =
    std::function<CampaignModelFit(const ContactModel& model, const CampaignFitRequest& request)>;

// Every run prepared and fitted on its own: restitution, loading and force history.
std::vector<PreparedRun> calibrate_runs(const std::vector<FemRun>& runs,
                                        const CalibrationOptions& options, Calibration& calibration,
                                        Progress& progress) {
  std::vector<PreparedRun> prepared;
  for (const auto& run : runs) prepared.push_back(prepare(run));
  for (std::size_t i = 0; i < prepared.size(); ++i) {
    progress.start();
    calibration.runs.push_back(calibrate_run(prepared[i], options, calibration.problems));
    progress("run " + std::to_string(i + 1) + "/" + std::to_string(runs.size()) +
             " (V = " + significant(runs[i].impact_velocity, 6) +
             " m/s): restitution, loading and "
             "force-history fits done in " +
             progress.elapsed());
  }
  return prepared;
}

// The campaign's distinct velocities, increasing.
std::vector<double> distinct_velocities(const std::vector<FemRun>& runs) {
  std::vector<double> velocities;
  for (const auto& run : runs) {
    const bool known = std::any_of(velocities.begin(), velocities.end(),
                                   [&](double v) { return same_velocity(v, run.impact_velocity); });
    if (!known) velocities.push_back(run.impact_velocity);
  }
  std::sort(velocities.begin(), velocities.end());
  return velocities;
}

// Hunt–Crossley on the force histories; then, from its elastic part and damping, with the
// energy loss, with n at the Hertz value and with b(V).
void fit_hunt_crossley_family(const CampaignFit& fit, CampaignCalibration& campaign,
                              CampaignStart& start, double damping,
                              const CalibrationOptions& options) {
  const ContactModel hunt_crossley = hunt_crossley_model();
  campaign.hunt_crossley = fit(hunt_crossley, {std::string(model_keys::hunt_crossley),
                                               "Hunt–Crossley, force histories",
                                               std::nullopt,
                                               0,
                                               damping,
                                               {},
                                               std::nullopt});
  // The other fits start from the Hunt–Crossley elastic part and damping.
  const ModelFit& hc = campaign.hunt_crossley->fit;
  const double hc_damping = hc.parameter.value;
  if (hc.stiffness.value > 0 && std::isfinite(hc.exponent.value)) {
    start.exponent = hc.exponent.value;
    start.log_reference_force =
        std::log(hc.stiffness.value) + hc.exponent.value * std::log(start.reference_approach);
  }
  if (options.energy_weight > 0)
    campaign.hunt_crossley_energy =
        fit(hunt_crossley, {std::string(model_keys::hunt_crossley_energy),
                            "Hunt–Crossley, force histories and energy loss",
                            std::nullopt,
                            options.energy_weight,
                            hc_damping,
                            {},
                            std::nullopt});
  // Hunt–Crossley with n at the Hertz value: its c (N/m^1.5) is the one to compare with the
  // Hertz stiffness.
  campaign.hunt_crossley_hertz_exponent =
      fit(hunt_crossley, {std::string(model_keys::hunt_crossley_hertz_exponent),
                          "Hunt–Crossley with n = 3/2, force histories",
                          hertz_exponent,
                          0,
                          hc_damping,
                          {},
                          std::nullopt});
  campaign.hunt_crossley_velocity_damping =
      fit(velocity_damped_hunt_crossley_model(),
          {std::string(model_keys::hunt_crossley_velocity_damping),
           options.energy_weight > 0 ? "Hunt–Crossley with b(V), force histories and energy loss"
                                     : "Hunt–Crossley with b(V), force histories",
           std::nullopt,
           options.energy_weight,
           hc_damping,
           {0.0},
           std::nullopt});
}

// The comparison laws, each from its own start; a law whose fit throws is a problem, not the
// end of the campaign.
void fit_comparison_laws(const CampaignFit& fit, const std::vector<ContactModel>& laws,
                         const std::vector<FemRun>& runs, Calibration& calibration,
                         const CampaignStart& start, const CalibrationOptions& options) {
  CampaignCalibration& campaign = calibration.campaign;
  for (const auto& law : laws) {
    try {
      CampaignFitRequest request{law.name,     law.name + ", force histories",
                                 std::nullopt, 0,
                                 nan,          {},
                                 std::nullopt};
      if (law.damped_plastic())
        request = damped_plastic_request(law, runs, campaign, start, options);
      campaign.comparison_laws.push_back(fit(law, request));
    } catch (const std::exception& error) {
      calibration.problems.push_back(
          {law.name, ProblemKind::convergence,
           "the campaign fit of " + law.name + " failed: " + error.what()});
    }
  }
}

} // namespace

Calibration calibrate(const std::vector<FemRun>& runs, const CalibrationOptions& options) {
  check_options(options);
  std::vector<std::string> left_out;
  const std::vector<ContactModel> laws = comparison_models(options.laws, runs, left_out);

  Calibration calibration;
  calibration.confidence_level = options.confidence_level;
  Progress progress(options.progress);
  for (const auto& name : left_out)
    progress("law " + name + " left out: " +
             (runs_can_yield(runs) ? "the runs do not record the sphere radius and Poisson "
                                     "ratio it needs"
                                   : "no material of the runs can yield, so its yield parameter "
                                     "would only stand in for the viscous loss"));

  const std::vector<PreparedRun> prepared = calibrate_runs(runs, options, calibration, progress);

  // The campaign needs two distinct velocities to tell a constant b from a constant e.
  CampaignCalibration& campaign = calibration.campaign;
  campaign.energy_weight = options.energy_weight;
  add_reference_models(campaign, runs, prepared, options);
  campaign.velocities = distinct_velocities(runs);
  if (campaign.velocities.size() < 2) {
    campaign.reason = runs.empty()
                          ? "no usable run"
                          : "the runs have a single impact velocity (" +
                                significant(campaign.velocities.front(), 6) +
                                " m/s); a campaign fit needs at least two distinct velocities to "
                                "tell how the damping depends on the velocity";
    return calibration;
  }

  double damping = nan;
  CampaignStart start = campaign_start(runs, calibration.runs, damping);

  const CampaignFit fit = [&](const ContactModel& model, const CampaignFitRequest& request) {
    progress.start();
    CampaignModelFit result = fit_campaign_model(model, request, prepared, campaign.velocities,
                                                 start, options, calibration.problems);
    progress("campaign: " + request.key + " fitted to " + std::to_string(runs.size()) + " runs" +
             (result.held_out.empty()
                  ? std::string()
                  : " and once without each of the " + std::to_string(result.held_out.size()) +
                        " velocities") +
             " in " + progress.elapsed());
    return result;
  };
  fit_hunt_crossley_family(fit, campaign, start, damping, options);
  fit_comparison_laws(fit, laws, runs, calibration, start, options);
  campaign.ranking = rank_campaign(campaign, calibration.runs);
  campaign.fitted = true;
  return calibration;
}

} // namespace impact::postprocess
