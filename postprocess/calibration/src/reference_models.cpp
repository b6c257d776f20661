// The models that fit nothing: Hertz, the published Hunt-Crossley b, Kuwabara-Kono, the
// elastic-plastic laws and the damped elastic-plastic laws from the material, evaluated on
// every run.

#include "fit_model.hpp"

#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <impact_reduced/hunt_crossley.hpp>

#include <cmath>

namespace impact::postprocess::detail {

namespace {

ReferenceModel reference_model(std::string key, std::string label, const ContactModel& model,
                               std::string basis, double stiffness, double exponent,
                               std::vector<double> dissipation,
                               const std::vector<PreparedRun>& runs,
                               const CalibrationOptions& options) {
  ReferenceModel reference{std::move(key),
                           std::move(label),
                           model.name,
                           std::move(basis),
                           stiffness,
                           exponent,
                           dissipation,
                           model.parameter_name(),
                           model.parameter_unit(),
                           {},
                           {},
                           {}};
  for (std::size_t i = 0; i + 1 < dissipation.size() && i < model.extra_parameters.size(); ++i) {
    reference.extra_names.push_back(model.extra_parameters[i].name);
    reference.extra_units.push_back(model.extra_parameters[i].unit);
  }
  Parametrisation map{1.0, std::vector<double>(dissipation.size(), 1.0)};
  std::vector<double> theta{map.log_reference_force(stiffness, exponent), exponent};
  theta.insert(theta.end(), dissipation.begin(), dissipation.end());
  for (const auto& run : runs) {
    const FemRun& fem = *run.run;
    const HistoryEvaluator evaluator{&model, &run, map, options.ode_tolerance};
    const ImpactPrediction prediction =
        predict_impact(model, fem.mass, fem.impact_velocity, stiffness, exponent, dissipation,
                       options.ode_tolerance);
    reference.runs.push_back(
        {fem.source, fem.impact_velocity, evaluator.quality(theta.data()), prediction, prediction});
  }
  return reference;
}

} // namespace

void add_reference_models(CampaignCalibration& campaign, const std::vector<FemRun>& fem_runs,
                          const std::vector<PreparedRun>& runs, const CalibrationOptions& options) {
  const ScenarioMaterials materials = scenario_materials(fem_runs);
  campaign.hertz_stiffness = materials.hertz_stiffness;
  campaign.hertz_basis = materials.hertz_basis;
  campaign.material_dissipative_constant = materials.dissipative_constant;
  campaign.material_basis = materials.dissipative_basis;
  campaign.published_damping = options.published_damping;
  const double c = materials.hertz_stiffness;
  const ContactModel hunt_crossley = hunt_crossley_model();
  campaign.reference_models.push_back(
      reference_model(std::string(model_keys::hertz), "Hertz (b = 0)", hunt_crossley,
                      "elastic Hertz impact: n = 3/2, c = " + materials.hertz_basis +
                          ", no damping",
                      c, hertz_exponent, {0.0}, runs, options));
  campaign.reference_models.push_back(
      reference_model(std::string(model_keys::hunt_crossley_published),
                      "Hunt–Crossley (b = " + significant(options.published_damping, 6) + " s/m)",
                      hunt_crossley,
                      "the published example: b = " + significant(options.published_damping, 6) +
                          " s/m, n = 3/2, c = " + materials.hertz_basis,
                      c, hertz_exponent, {options.published_damping}, runs, options));
  if (materials.dissipative_constant)
    campaign.reference_models.push_back(
        reference_model(std::string(model_keys::kuwabara_kono_material),
                        "Kuwabara–Kono, no tension, A from the material (no fit)",
                        comparison_model("kuwabara-kono-no-tension"),
                        "no fit: c = " + materials.hertz_basis +
                            ", n = 3/2, A = " + significant(*materials.dissipative_constant, 6) +
                            " s from " + materials.dissipative_basis,
                        c, hertz_exponent, {*materials.dissipative_constant}, runs, options));

  if (const auto thornton = material_thornton(fem_runs))
    campaign.reference_models.push_back(
        reference_model(std::string(model_keys::thornton_material),
                        "Thornton, p_y = 1.6 Y from the material (no fit)",
                        contact_model("thornton"), thornton->basis, thornton->stiffness,
                        hertz_exponent, {thornton->yield_approach}, runs, options));
  if (const auto jackson_green = material_jackson_green(fem_runs))
    campaign.reference_models.push_back(
        reference_model(std::string(model_keys::jackson_green_material),
                        "Jackson–Green, E*, Y, nu from the material (no fit)", jackson_green->model,
                        jackson_green->basis, jackson_green->stiffness, hertz_exponent,
                        {jackson_green->yield_strength}, runs, options));

  // Damping on the elastic-plastic springs from the material: both losses with nothing
  // fitted (none without a yield strength or with A = 0, where they are the rate-independent
  // laws above).
  for (const auto& damped :
       {material_hunt_crossley_thornton(fem_runs), material_hunt_crossley_jackson_green(fem_runs),
        material_kuwabara_kono_thornton(fem_runs), material_kuwabara_kono_jackson_green(fem_runs)})
    if (damped)
      campaign.reference_models.push_back(
          reference_model(damped->key, damped->label, damped->model, damped->basis,
                          damped->stiffness, hertz_exponent, damped->dissipation, runs, options));

  // The restitution maps as users apply them: the FEM's e at each run, c from Hertz.
  for (const auto& name : restitution_parametrised_laws()) {
    const ContactModel law = comparison_model(name);
    RestitutionMapEvaluation evaluation{name, law.formula, {}};
    for (const auto& run : runs) {
      const FemRun& fem = *run.run;
      evaluation.runs.push_back(
          {fem.source, fem.impact_velocity, fem.restitution,
           fem.restitution > 0 && fem.restitution <= 1
               ? predict_impact(law, fem.mass, fem.impact_velocity, c, hertz_exponent,
                                {fem.restitution}, options.ode_tolerance)
               : ImpactPrediction{{nan, nan, nan, nan, nan}, nan}});
    }
    campaign.restitution_maps.push_back(std::move(evaluation));
  }
}

} // namespace impact::postprocess::detail
