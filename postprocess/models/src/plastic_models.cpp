// The elastic-plastic comparison models (plastic_models.hpp).

#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/contact_formulas.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/thornton.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

namespace impact::postprocess {

namespace {

// Thornton's law for c and x_y: any radius gives the same law (plastic_models.hpp); R = 1 m,
// E* = 3 c / 4, p_y = 3 c sqrt(x_y) / (2 pi).
std::shared_ptr<const reduced::ElasticPlasticContact> thornton_contact(
    double yield_approach, const reduced::ContactSetup& setup) {
  const double c = setup.stiffness;
  return std::make_shared<reduced::ThorntonContact>(1.0, 0.75 * c,
                                                    thornton_yield_pressure(c, yield_approach,
                                                                            1.0));
}

// V_y / V that gives restitution e under Thornton's law (e rises from 0 to 1 with V_y / V).
double thornton_velocity_ratio(double restitution) {
  if (!(restitution > 0)) return 0;
  if (restitution >= 1) return 1;
  double lower = 0, upper = 1;
  for (int i = 0; i < 200 && upper - lower > 1e-15; ++i) {
    const double middle = 0.5 * (lower + upper);
    (reduced::thornton_restitution_formula(middle) < restitution ? lower : upper) = middle;
  }
  return 0.5 * (lower + upper);
}

ContactModel thornton_model() {
  ContactModel model = plastic_model_base(
      std::string(model_keys::thornton),
      "F = c x^(3/2) to the yield approach x_y, then F = F_y + (3/2) c sqrt(x_y) "
      "(x - x_y) (pi p_y R); unloading Hertzian on the enlarged radius R_p about the "
      "permanent approach; p_y = 3 c sqrt(x_y) / (2 pi R); no rate dependence, "
      "no hardening",
      "Thornton, J. Appl. Mech. 64 (1997) 383-386 (elastic-perfectly-plastic "
      "spheres; limiting pressure p_y = 1.6 Y after Johnson, Contact Mechanics, 1985)",
      "x_y", "m");
  model.damping_for_restitution = [](double e, double velocity,
                                     const reduced::ContactSetup& setup) {
    return thornton_yield_approach(thornton_velocity_ratio(e) * velocity, setup.mass,
                                   setup.stiffness);
  };
  model.plastic_contact = thornton_contact;
  return model;
}

} // namespace

ContactModel plastic_model_base(std::string name, std::string formula, std::string reference,
                                std::string symbol, std::string unit) {
  ContactModel model;
  model.name = std::move(name);
  model.formula = std::move(formula);
  model.reference = std::move(reference);
  model.damping_name = std::move(symbol);
  model.damping_unit = std::move(unit);
  model.parameter = DissipationParameter::damping;
  model.required_exponent = 1.5;
  model.damping = [](const std::vector<double>& p, double, const reduced::ContactSetup&) {
    return p.at(0);
  };
  return model;
}

const std::vector<std::string>& plastic_model_names() {
  static const std::vector<std::string> names = {std::string(model_keys::thornton),
                                                 std::string(model_keys::jackson_green)};
  return names;
}

bool is_plastic_model(const std::string& name) {
  const auto& names = plastic_model_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

ContactModel plastic_model(const std::string& name) {
  if (name == model_keys::thornton) return thornton_model();
  if (name == model_keys::jackson_green)
    throw reduced::InvalidInput("model",
                                "the model jackson-green needs the scenario's sphere "
                                "radius and Poisson ratio: build it from the runs "
                                "(comparison_model(name, runs))");
  throw reduced::InvalidInput("model",
                              "model must be one of the plastic models (thornton, "
                              "jackson-green), got '" +
                                  name + "'");
}

std::string model_formula(const std::string& name) {
  if (name == model_keys::jackson_green) return jackson_green_formula();
  if (damped_plastic_needs_scenario(name)) {
    // Any scenario builds the model; the formula names R and nu of none.
    ContactModel spring = jackson_green_model(1.0, 0.3);
    spring.formula = jackson_green_formula();
    return damped_plastic_model(name, spring).formula;
  }
  return contact_model(name).formula;
}

bool needs_scenario(const std::string& name) {
  return name == model_keys::jackson_green || damped_plastic_needs_scenario(name);
}

ContactModel comparison_model(const std::string& name, const std::vector<FemRun>& runs) {
  if (!needs_scenario(name)) return comparison_model(name);
  const auto scenario = sphere_flat_scenario(runs);
  if (!scenario)
    throw reduced::InvalidInput("model",
                                "the model " + name +
                                    " needs the sphere radius "
                                    "('Scenario/Sphere radius') and the Poisson ratio of the "
                                    "yielding body, which the runs do not record");
  const ContactModel spring = jackson_green_model(scenario->radius, scenario->poisson_ratio);
  return damped_plastic_needs_scenario(name) ? damped_plastic_model(name, spring) : spring;
}

bool runs_can_yield(const std::vector<FemRun>& runs) {
  return std::any_of(runs.begin(), runs.end(), [](const FemRun& run) {
    for (const char* key : {"Sphere/Material model", "Plate/Material model"}) {
      const auto model = run.text_attributes.find(key);
      if (model != run.text_attributes.end() && model->second == "elastic-plastic") return true;
    }
    return false;
  });
}

std::vector<ContactModel> comparison_models(const std::vector<std::string>& names,
                                            const std::vector<FemRun>& runs,
                                            std::vector<std::string>& left_out) {
  std::vector<ContactModel> models;
  const bool scenario = sphere_flat_scenario(runs).has_value();
  const bool yielding = runs_can_yield(runs);
  for (const auto& name : names) {
    const bool plastic = is_plastic_model(name) || is_damped_plastic_model(name);
    if ((needs_scenario(name) && !scenario) || (plastic && !yielding)) {
      left_out.push_back(name);
      continue;
    }
    models.push_back(comparison_model(name, runs));
  }
  return models;
}

std::vector<std::string> comparison_model_names() {
  std::vector<std::string> names = reduced::comparison_law_names();
  for (const auto& name : plastic_model_names()) names.push_back(name);
  for (const auto& name : damped_plastic_model_names()) names.push_back(name);
  return names;
}

double thornton_yield_pressure(double stiffness, double yield_approach, double radius) {
  reduced::require_positive("yield_approach", yield_approach);
  return reduced::hertz_peak_pressure(stiffness, radius, yield_approach);
}

double thornton_yield_approach(double yield_velocity, double mass, double stiffness) {
  return reduced::hertz_peak_approach(stiffness, mass, yield_velocity);
}

double thornton_yield_velocity(double yield_approach, double mass, double stiffness) {
  return reduced::hertz_impact_velocity(stiffness, mass, yield_approach);
}

std::optional<MaterialThornton> material_thornton(const std::vector<FemRun>& runs) {
  if (runs.empty()) return std::nullopt;
  std::optional<PlasticContact> contact;
  try {
    contact = scenario_plastic_contact(runs);
  } catch (const PlasticContactError&) {
    return std::nullopt;
  }
  const auto radius = text_number(runs.front(), fem_format::sphere_radius.path);
  if (!contact || !radius || !(*radius > 0)) return std::nullopt;
  const double e_star = contact->contact_modulus;
  std::ostringstream basis;
  basis << "no fit: E* = " << significant(e_star, 6) << " Pa, R = " << significant(*radius, 6)
        << " m, p_y = " << significant(contact->yield_pressure, 6) << " Pa from "
        << contact->yield_basis << "; c = (4/3) E* sqrt(R), x_y = R (pi p_y / (2 E*))^2; "
        << hardening_note(runs.front());
  return MaterialThornton{reduced::hertz_coefficient(e_star, *radius),
                          reduced::yield_approach(contact->yield_pressure, e_star, *radius),
                          basis.str()};
}

} // namespace impact::postprocess
