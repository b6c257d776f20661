#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"

#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/invalid_input.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

reduced::ContactForceLaw hunt_crossley_force(double b, const reduced::ContactSetup& setup) {
  const double c = setup.stiffness;
  const double n = setup.exponent;
  return [=](double x, double rate) { return c * std::pow(x, n) * (1 + b * rate); };
}

double damping_at(const ContactModel& model, double mass, double velocity, double stiffness,
                  double exponent, const std::vector<double>& dissipation) {
  return model.damping(dissipation, velocity, {mass, stiffness, exponent});
}

} // namespace

std::string ContactModel::parameter_name() const {
  return parameter == DissipationParameter::restitution ? "e" : damping_name;
}

std::string ContactModel::parameter_unit() const {
  return parameter == DissipationParameter::restitution ? "1" : damping_unit;
}

bool ContactModel::hunt_crossley_force() const {
  return name == model_keys::hunt_crossley || name == model_keys::hunt_crossley_velocity_damping ||
         std::find(restitution_parametrised_laws().begin(), restitution_parametrised_laws().end(),
                   name) != restitution_parametrised_laws().end();
}

const std::vector<std::string>& restitution_parametrised_laws() {
  // The Hunt–Crossley family of the library: damping maps b = g(e) / V, applied by
  // multibody codes with a constant e (reduced/src/law_hertz_damped.cpp).
  static const std::vector<std::string> names = {"lankarani-nikravesh", "flores", "gonthier",
                                                 "hu-guo", "zhiying-qishao"};
  return names;
}

ContactModel hunt_crossley_model() {
  ContactModel model;
  model.name = std::string(model_keys::hunt_crossley);
  model.formula = "F = c x^n (1 + b x'), b constant; restitution k(b V) exact (Lambert W)";
  model.reference = "Hunt and Crossley, J. Appl. Mech. 42 (1975) 440-445";
  model.damping_name = "b";
  model.damping_unit = "s/m";
  model.parameter = DissipationParameter::damping;
  model.damping = [](const std::vector<double>& p, double, const reduced::ContactSetup&) {
    return p.at(0);
  };
  model.damping_for_restitution = [](double e, double velocity, const reduced::ContactSetup&) {
    return reduced::damping_from_restitution(std::min(e, 1.0), velocity);
  };
  model.force_law = hunt_crossley_force;
  return model;
}

ContactModel velocity_damped_hunt_crossley_model() {
  ContactModel model = hunt_crossley_model();
  model.name = std::string(model_keys::hunt_crossley_velocity_damping);
  model.formula =
      "F = c x^n (1 + b(V) x'), b(V) = b_1 (V / 1 m/s)^(-q), V the speed at first "
      "contact; q = 0 is Hunt-Crossley, q = 1 a constant restitution";
  model.reference =
      "Hunt and Crossley (1975); velocity-dependent damping as in the "
      "restitution-based maps (b ~ 1/V, e.g. Lankarani and Nikravesh 1990)";
  model.damping_name = "b_1";
  // q in [-1, 3]: from a b growing with V to faster than any published map falls.
  model.extra_parameters = {{"q", "1", 0.0, -1.0, 3.0}};
  model.damping = [](const std::vector<double>& p, double velocity, const reduced::ContactSetup&) {
    return p.at(0) * std::pow(velocity, -p.at(1));
  };
  return model;
}

ContactModel comparison_model(const std::string& name) {
  if (is_plastic_model(name)) return plastic_model(name);
  if (is_damped_plastic_model(name)) return damped_plastic_model(name);
  const reduced::ComparisonLaw& law = reduced::comparison_law(name);
  ContactModel model;
  model.name = law.name;
  model.formula = law.formula;
  model.reference = law.reference;
  model.damping_name = law.damping_name;
  model.damping_unit = law.damping_unit;
  model.required_exponent = law.required_exponent;
  model.contact_end = law.contact_end;
  const auto& by_restitution = restitution_parametrised_laws();
  model.parameter =
      std::find(by_restitution.begin(), by_restitution.end(), name) != by_restitution.end()
          ? DissipationParameter::restitution
          : DissipationParameter::damping;
  model.damping_for_restitution = law.damping_for_restitution;
  if (model.parameter == DissipationParameter::restitution)
    model.damping = [map = law.damping_for_restitution](const std::vector<double>& p,
                                                        double velocity,
                                                        const reduced::ContactSetup& setup) {
      return map(p.at(0), velocity, setup);
    };
  else
    model.damping = [](const std::vector<double>& p, double, const reduced::ContactSetup&) {
      return p.at(0);
    };
  model.force_law = law.force_law;
  return model;
}

ContactModel contact_model(const std::string& name) {
  if (name == model_keys::hunt_crossley) return hunt_crossley_model();
  if (name == model_keys::hunt_crossley_velocity_damping)
    return velocity_damped_hunt_crossley_model();
  return comparison_model(name);
}

ImpactPrediction predict_impact(const ContactModel& model, double mass, double velocity,
                                double stiffness, double exponent,
                                const std::vector<double>& dissipation, double tolerance) {
  ImpactPrediction prediction{{nan, nan, nan, nan, nan}, nan};
  try {
    if (model.damped_plastic()) {
      // The damping constant of a damped elastic-plastic model is its rate term's (b at V).
      prediction.damping =
          model.spring_damping_constant(dissipation, velocity, {mass, stiffness, exponent});
      static_cast<ImpactFigures&>(prediction) =
          damped_plastic_impact(model, mass, velocity, stiffness, dissipation)->figures();
      return prediction;
    }
    prediction.damping = damping_at(model, mass, velocity, stiffness, exponent, dissipation);
    if (model.plastic_contact) {
      const auto response = reduced::elastic_plastic_impact(
          mass, velocity, *model.plastic_contact(prediction.damping, {mass, stiffness, exponent}));
      static_cast<ImpactFigures&>(prediction) = response.figures();
    } else if (model.hunt_crossley_force()) {
      const reduced::HuntCrossleyImpact impact(mass, stiffness, exponent, prediction.damping,
                                               velocity);
      const auto response = impact.response();
      static_cast<ImpactFigures&>(prediction) = response.figures();
    } else {
      const auto impact = reduced::integrate_impact(mass, velocity,
                                                    model.force_law(prediction.damping,
                                                                    {mass, stiffness, exponent}),
                                                    tolerance, model.contact_end);
      static_cast<ImpactFigures&>(prediction) = impact.figures();
    }
  } catch (const std::exception&) {
  }
  return prediction;
}

double predict_restitution(const ContactModel& model, double mass, double velocity,
                           double stiffness, double exponent,
                           const std::vector<double>& dissipation, double tolerance) {
  try {
    if (model.damped_plastic())
      return damped_plastic_impact(model, mass, velocity, stiffness, dissipation)->restitution();
    const double damping = damping_at(model, mass, velocity, stiffness, exponent, dissipation);
    if (model.plastic_contact)
      return reduced::elastic_plastic_impact(mass, velocity,
                                             *model.plastic_contact(damping,
                                                                    {mass, stiffness, exponent}))
          .restitution;
    if (model.hunt_crossley_force()) {
      if (!(damping >= 0 && std::isfinite(damping))) return nan;
      return reduced::restitution_from_impact_parameter(damping * velocity);
    }
    return reduced::integrate_impact(mass, velocity,
                                     model.force_law(damping, {mass, stiffness, exponent}),
                                     tolerance, model.contact_end)
        .restitution;
  } catch (const std::exception&) {
    return nan;
  }
}

std::vector<reduced::ImpactSample> predict_history(const ContactModel& model, double mass,
                                                   double velocity, double stiffness,
                                                   double exponent,
                                                   const std::vector<double>& dissipation,
                                                   std::size_t points) {
  if (model.damped_plastic())
    return damped_plastic_impact(model, mass, velocity, stiffness, dissipation)->history(points);
  const double damping = damping_at(model, mass, velocity, stiffness, exponent, dissipation);
  if (model.plastic_contact)
    return reduced::elastic_plastic_impact_loop(mass, velocity,
                                                *model.plastic_contact(damping,
                                                                       {mass, stiffness, exponent}),
                                                std::max<std::size_t>(2, (points + 1) / 2));
  if (model.hunt_crossley_force()) {
    std::vector<reduced::ImpactSample> samples;
    for (const auto& state :
         reduced::HuntCrossleyImpact(mass, stiffness, exponent, damping, velocity).history(points))
      samples.push_back({state.time, state.approach, state.approach_rate, state.force});
    return samples;
  }
  return reduced::integrate_impact_history(mass, velocity,
                                           model.force_law(damping, {mass, stiffness, exponent}),
                                           points, 1e-10, model.contact_end);
}

} // namespace impact::postprocess
