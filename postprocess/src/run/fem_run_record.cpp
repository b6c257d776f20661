#include "impact_postprocess/run/fem_run_record.hpp"

#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

fs::path summary_of(const fs::path& file) {
  if (file.filename() == fem_format::history_file)
    return file.parent_path() / fem_format::summary_file;
  return file.parent_path() / (file.stem().string() + ".summary.json");
}

double median_step(const std::vector<double>& time) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < time.size(); ++i) steps.push_back(time[i] - time[i - 1]);
  if (steps.empty()) return nan;
  std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
  return steps[steps.size() / 2];
}

// The approach at time t, linearly interpolated; NaN outside the history.
double approach_at(const FemRun& run, double t) {
  for (std::size_t i = 1; i < run.time.size(); ++i)
    if (run.time[i - 1] <= t && t <= run.time[i]) {
      const double w = (t - run.time[i - 1]) / (run.time[i] - run.time[i - 1]);
      return (1 - w) * run.approach[i - 1] + w * run.approach[i];
    }
  return nan;
}

bool has_plastic_material(const FemRun& run) {
  for (const char* key : {"Sphere/Material model", "Plate/Material model"}) {
    const auto model = run.text_attributes.find(key);
    if (model != run.text_attributes.end() && model->second == "elastic-plastic") return true;
  }
  return false;
}

} // namespace

FemRunRecord read_fem_run_record(const FemRun& run) {
  json summary = json::object();
  try {
    std::ifstream in(summary_of(run.source));
    if (in) summary = json::parse(in);
  } catch (const json::exception&) {
    summary = json::object(); // the run reader has already accepted or rejected it
  }
  const auto value = [&](const std::string& key) -> std::optional<double> {
    if (summary.is_object() && summary.contains(key) && summary[key].is_number())
      return summary[key].get<double>();
    const auto attribute = run.numeric_attributes.find(fem_format::result_attribute_prefix + key);
    if (attribute != run.numeric_attributes.end() && std::isfinite(attribute->second))
      return attribute->second;
    return std::nullopt;
  };
  FemRunRecord record;
  record.energy_error = value(fem_format::energy_error_key);
  record.lost_energy_fraction = value(fem_format::lost_energy_fraction_key);
  record.dissipated_energy_fraction = value(fem_format::dissipated_energy_fraction_key);
  record.radiated_energy_fraction = value(fem_format::radiated_energy_fraction_key);

  // Stresses and yield strengths: impact-fem records them per body; a generic
  // "max_von_mises" / "yield_strength" pair is read too. The parameters
  // "<Body>/Yield strength" (0 = none) give the strength when the summary does not.
  const std::string sphere = "sphere", plate = "plate"; // impact-fem's body names
  for (const std::string& key :
       {std::string(fem_format::max_von_mises_key), fem_format::von_mises_max_prefix + sphere,
        fem_format::von_mises_max_prefix + plate})
    if (const auto stress = value(key))
      record.max_von_mises = std::max(record.max_von_mises.value_or(0.0), *stress);
  const auto consider = [&](const std::string& key, std::optional<double> strength) {
    if (!strength || !(*strength > 0)) return;
    if (!record.yield_strength || *strength < *record.yield_strength) {
      record.yield_strength = strength;
      record.yield_source = key;
    }
  };
  // "yield_strength": the generic key of a summary written by another tool.
  for (const std::string& key :
       {std::string("yield_strength"), fem_format::yield_strength_prefix + sphere,
        fem_format::yield_strength_prefix + plate})
    consider(key, value(key));
  for (const char* body : {fem_format::sphere_body, fem_format::plate_body}) {
    const std::string key = fem_format::body_parameter(body, fem_format::yield_strength);
    consider(key, text_number(run, key));
    // An elastic-plastic body's initial yield strength (its material's constant).
    const auto model = run.text_attributes.find(fem_format::material_model_parameter(body));
    if (model != run.text_attributes.end() && model->second == fem_format::elastic_plastic_model)
      consider(fem_format::material_parameter(body, fem_format::elastic_plastic_model,
                                              fem_format::yield_strength),
               material_constant(run, body, fem_format::yield_strength));
  }
  if (summary.is_object() && summary.contains(fem_format::yield_exceeded_key) &&
      summary[fem_format::yield_exceeded_key].is_boolean())
    record.yields = summary[fem_format::yield_exceeded_key].get<bool>();
  else if (record.yield_strength && record.max_von_mises)
    record.yields = *record.max_von_mises > *record.yield_strength;

  record.plastic_material = has_plastic_material(run);
  if (record.plastic_material) {
    record.permanent_approach = value("permanent_approach"); // impact-fem's plasticity summary
    if (!record.permanent_approach) {
      const double measured = approach_at(run, run.first_contact_time + run.contact_time);
      if (std::isfinite(measured)) record.permanent_approach = std::max(measured, 0.0);
    }
  }

  const auto oscillation = value(fem_format::force_oscillation_key);
  const auto after_release = value(fem_format::force_after_release_key);
  if (oscillation && after_release) {
    record.smoothness = {*oscillation, *after_release};
    record.smoothness_source = "summary.json";
  } else {
    record.smoothness = force_smoothness(run.contact_force);
    record.smoothness_source = "measured on the force history";
  }
  record.time_step = value(fem_format::time_step_key).value_or(median_step(run.time));
  record.release_span = release_span(run.time, run.contact_force);
  try {
    record.verification = read_verification(run.source);
  } catch (const RunInputError& error) {
    record.verification_problem = error.what();
  }
  return record;
}

FemUncertainty fem_uncertainty(const FemRunRecord& record, const ImpactFigures& fem) {
  FemUncertainty uncertainty;
  for (auto& entry : uncertainty) entry = {nan, "not known (no verification of the run)"};
  const auto set = [&](Quantity quantity, double relative, std::string source) {
    uncertainty[std::size_t(quantity)] = {relative, std::move(source)};
  };
  if (record.verification) {
    const auto& quantities = record.verification->quantities;
    const std::string source = "GCI of the verification (" + record.verification->source + ")";
    const auto gci = [&](const char* key) {
      const auto found = quantities.find(key);
      return found == quantities.end() ? nan : found->second.gci_fine;
    };
    set(Quantity::contact_time, gci(fem_format::contact_time_key), source);
    set(Quantity::force_max, gci(fem_format::force_max_key), source);
    set(Quantity::time_force_max, gci(fem_format::time_force_max_key), source);
    set(Quantity::approach_max, gci(fem_format::approach_max_key), source);
    const auto restitution = quantities.find(fem_format::restitution_key);
    if (restitution != quantities.end()) {
      double absolute = restitution->second.gci_fine_absolute;
      if (!std::isfinite(absolute))
        absolute = restitution->second.gci_fine * std::abs(fem.restitution);
      const double e = fem.restitution;
      set(Quantity::restitution, absolute / e, source);
      set(Quantity::restitution_deficit, absolute / (1 - e), source);
      set(Quantity::energy_loss, 2 * e * absolute / (1 - e * e), source);
    }
    return uncertainty;
  }
  if (std::isfinite(record.smoothness.oscillation))
    set(Quantity::force_max, record.smoothness.oscillation,
        "step-to-step oscillation of the force history (" + record.smoothness_source + ")");
  if (std::isfinite(record.time_step) && fem.contact_time > 0) {
    const bool chatter = record.release_span > record.time_step;
    set(Quantity::contact_time, std::max(record.time_step, record.release_span) / fem.contact_time,
        chatter ? "the release chatter (force after the first zero that follows the peak)"
                : "one time step (the contact time is bound to the steps)");
  }
  if (std::isfinite(record.time_step) && fem.time_force_max > 0)
    set(Quantity::time_force_max, record.time_step / fem.time_force_max, "one time step");
  return uncertainty;
}

} // namespace impact::postprocess
