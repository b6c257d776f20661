// The registry of comparison contact laws and their evaluation (see comparison_laws.hpp).

#include "impact_reduced/comparison_laws.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "law_catalogue.hpp"

#include <sstream>

namespace impact::reduced {

const std::vector<ComparisonLaw>& comparison_laws() {
  static const std::vector<ComparisonLaw> registry = {
      laws::kelvin_voigt(),  laws::lankarani_nikravesh(),
      laws::flores(),        laws::gonthier(),
      laws::hu_guo(),        laws::zhiying_qishao(),
      laws::tsuji(),         laws::tsuji_clamped(),
      laws::kuwabara_kono(), laws::kuwabara_kono_no_tension(),
  };
  return registry;
}

std::vector<std::string> comparison_law_names() {
  std::vector<std::string> names;
  for (const auto& law : comparison_laws()) names.push_back(law.name);
  return names;
}

const ComparisonLaw& comparison_law(const std::string& name) {
  std::string known;
  for (const auto& law : comparison_laws()) {
    if (law.name == name) return law;
    known += (known.empty() ? "" : "|") + law.name;
  }
  throw InvalidInput("model", "model must be one of " + known + " (got '" + name + "')");
}

double comparison_law_damping(const ComparisonLaw& law, const ContactSetup& setup,
                              double restitution, double velocity) {
  if (!(restitution > 0 && restitution <= 1)) {
    std::ostringstream message;
    message.precision(17);
    message << "restitution must be a number in (0, 1] (got " << restitution << ")";
    throw InvalidInput("restitution", message.str());
  }
  require_positive("velocity", velocity);
  require_positive("mass", setup.mass);
  require_positive("stiffness", setup.stiffness);
  require_positive("exponent", setup.exponent);
  if (law.required_exponent && setup.exponent != *law.required_exponent) {
    std::ostringstream message;
    message.precision(17);
    message << "exponent must be " << *law.required_exponent << " for the " << law.name
            << " law (got " << setup.exponent << ")";
    throw InvalidInput("exponent", message.str());
  }
  return law.damping_for_restitution(restitution, velocity, setup);
}

ComparisonLawImpact evaluate_comparison_law(const ComparisonLaw& law, const ContactSetup& setup,
                                            double restitution, double velocity,
                                            double relative_tolerance) {
  const double damping = comparison_law_damping(law, setup, restitution, velocity);
  try {
    const auto impact = integrate_impact(setup.mass, velocity, law.force_law(damping, setup),
                                         relative_tolerance, law.contact_end);
    return {damping, impact, (impact.restitution - restitution) / restitution};
  } catch (const ContactDoesNotEnd& error) {
    std::ostringstream message;
    message.precision(10);
    message << "restitution " << restitution << " gives the " << law.name << " law the damping "
            << law.damping_name << " = " << damping << " " << law.damping_unit
            << ", with which it holds the body (mass " << setup.mass << " kg, stiffness "
            << setup.stiffness << ", exponent " << setup.exponent << ", velocity " << velocity
            << " m/s): " << error.what() << "; choose a larger restitution";
    throw InvalidInput("restitution", message.str());
  }
}

} // namespace impact::reduced
