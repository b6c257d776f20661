// The compared models in words (model_words.hpp): the assessment says which basis and which
// reason (compared_models.hpp, no_value.hpp), the page says them here.

#include "model_words.hpp"

#include "impact_postprocess/report/verdict_words.hpp"

#include "impact_postprocess/number_format.hpp"

namespace impact::postprocess::detail {

std::string parameters_words(ModelBasis basis, const std::vector<ModelParameter>& parameters) {
  if (basis == ModelBasis::per_run_fits)
    return "c, n, b of each run's force-history fit (table of runs)";
  if (basis == ModelBasis::no_calibration || basis == ModelBasis::no_comparison_law) return "n/a";
  std::string text;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    text += (i ? ", " : "") + parameters[i].name + " = " + short_number(parameters[i].value) +
            (parameters[i].unit == "1" ? "" : " " + parameters[i].unit);
  return text;
}

std::string basis_words(const ReportModel& model, const std::optional<Calibration>& calibration) {
  const CampaignModelFit* fit =
      calibration ? calibration->campaign.find(model.calibration_key) : nullptr;
  const auto reference_basis = [&]() -> std::string {
    if (calibration)
      for (const auto& reference : calibration->campaign.reference_models)
        if (reference.key == model.calibration_key) return reference.basis;
    return "";
  };
  switch (model.basis) {
    case ModelBasis::campaign_fit:
      return "campaign fit of the calibration to the force histories of all runs: one (c, n, b) "
             "for all runs";
    case ModelBasis::per_run_fits:
      return "no campaign fit (" +
             (!calibration || calibration->campaign.reason.empty()
                  ? std::string("the campaign was not fitted")
                  : calibration->campaign.reason) +
             "): each run is compared with its own force-history fit, which says nothing about "
             "other velocities";
    case ModelBasis::force_and_energy_fit:
      return "campaign fit to the force histories and the energy loss of every run (energy "
             "weight " +
             short_number(fit ? fit->energy_weight : 0.0) + ")";
    case ModelBasis::velocity_damping_fit:
      return "b(V) = b_1 (V / 1 m/s)^-q, " + (fit ? fit->label : model.calibration_key);
    case ModelBasis::best_law:
      return "the comparison law ranked first by out-of-sample error, fitted to the force "
             "histories of all runs";
    case ModelBasis::best_law_in_sample:
      return "the comparison law ranked first among the fitted laws by its in-sample error "
             "(fewer than three velocities: no out-of-sample error; a fit ranks after every law "
             "that fits nothing), fitted to the force histories of all runs";
    case ModelBasis::damped_plastic_fit:
      return (fit ? fit->label : model.calibration_key) +
             ": the spring's yield parameter and b fitted to all runs";
    case ModelBasis::nothing_fitted:
      return reference_basis();
    case ModelBasis::no_calibration:
      return "no calibration";
    case ModelBasis::no_comparison_law:
      return "the calibration has no fitted comparison law";
  }
  return "";
}

std::string no_value_words(const std::optional<NoValue>& missing) {
  if (!missing) return "";
  const std::string& detail = missing->detail;
  switch (missing->reason) {
    case NoValueReason::no_calibration:
      return "no calibration";
    case NoValueReason::no_comparison_law:
      return "the calibration has no fitted comparison law";
    case NoValueReason::prediction_incomplete:
      return "the calibration's prediction of " + detail + " is incomplete";
    case NoValueReason::no_prediction_for_run:
      return "the calibration has no prediction of " + detail + " for this run";
    case NoValueReason::not_evaluable:
      return "the model cannot be evaluated at this run";
    case NoValueReason::no_run_fit:
      return "the calibration has no force-history fit of this run";
    case NoValueReason::no_run_fit_prediction:
      return "the calibration has no prediction of this run's fit";
    case NoValueReason::no_history:
      return "no history: " + detail;
    case NoValueReason::no_comparison_law_on_row:
      return "the row's calibration has no comparison law";
    case NoValueReason::no_model_on_row:
      return "the row's calibration has no such model";
    case NoValueReason::no_verdict:
      return missing->verdict ? no_verdict_sentence(*missing->verdict) : detail;
    case NoValueReason::no_run_at_value:
      return "no run at this value";
    case NoValueReason::no_fem_result_on_row:
      return "no FEM run of this value has a result (each run's reason below)";
    case NoValueReason::thickness_not_recorded:
      return "the runs do not record 'Scenario/Plate thickness', so the plate is not known";
    case NoValueReason::no_prediction:
      return "no prediction";
    case NoValueReason::no_fem_result:
      return "the FEM run has no result: " + detail;
    case NoValueReason::no_reference_run:
      return "the row of the most massive plate has no run at this velocity whose restitution "
             "the model reproduces";
    case NoValueReason::plate_not_recorded:
      return "the run does not record the plate's material (Plate/<Model>/Young's modulus, "
             "Poisson's ratio, Density), its thickness (Scenario/Plate thickness) or the "
             "sphere's (Sphere/..., Scenario/Sphere radius)";
    case NoValueReason::thin_plate_failed:
      return "the thin-plate model cannot be evaluated: " + detail;
  }
  return "";
}

} // namespace impact::postprocess::detail
