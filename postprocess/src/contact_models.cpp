#include "impact_postprocess/contact_models.hpp"

#include <impact_reduced/hunt_crossley.hpp>

#include <algorithm>
#include <cmath>

namespace impact::postprocess {

std::string ContactModel::parameter_name() const {
  return parameter == DissipationParameter::restitution ? "e" : damping_name;
}

std::string ContactModel::parameter_unit() const {
  return parameter == DissipationParameter::restitution ? "1" : damping_unit;
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
  model.name = "hunt-crossley";
  model.formula = "F = c x^n (1 + b x'), b constant; restitution k(b V) exact (Lambert W)";
  model.reference = "Hunt and Crossley, J. Appl. Mech. 42 (1975) 440-445";
  model.damping_name = "b";
  model.damping_unit = "s/m";
  model.parameter = DissipationParameter::damping;
  model.damping = [](double b, double, const reduced::ContactSetup&) { return b; };
  model.damping_for_restitution = [](double e, double velocity, const reduced::ContactSetup&) {
    return reduced::damping_from_restitution(std::min(e, 1.0), velocity);
  };
  model.force_law = [](double b, const reduced::ContactSetup& setup) -> reduced::ContactForceLaw {
    const double c = setup.stiffness;
    const double n = setup.exponent;
    return [=](double x, double rate) { return c * std::pow(x, n) * (1 + b * rate); };
  };
  return model;
}

ContactModel comparison_model(const std::string& name) {
  const reduced::ComparisonLaw& law = reduced::comparison_law(name);
  ContactModel model;
  model.name = law.name;
  model.formula = law.formula;
  model.reference = law.reference;
  model.damping_name = law.damping_name;
  model.damping_unit = law.damping_unit;
  model.required_exponent = law.required_exponent;
  const auto& by_restitution = restitution_parametrised_laws();
  model.parameter = std::find(by_restitution.begin(), by_restitution.end(), name) !=
                            by_restitution.end()
                        ? DissipationParameter::restitution
                        : DissipationParameter::damping;
  model.damping_for_restitution = law.damping_for_restitution;
  if (model.parameter == DissipationParameter::restitution)
    model.damping = law.damping_for_restitution;
  else
    model.damping = [](double damping, double, const reduced::ContactSetup&) { return damping; };
  model.force_law = law.force_law;
  return model;
}

} // namespace impact::postprocess
