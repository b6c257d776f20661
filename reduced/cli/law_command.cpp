// impact-reduced law: a comparison contact law, the damping its own formula assigns to a
// target restitution, and the restitution it really produces (reference ODE integration).

#include "commands.hpp"
#include "output.hpp"

#include "impact_reduced/comparison_laws.hpp"

namespace impact::cli {

int run_law_command(CommandLine& options, std::ostream& out) {
  using namespace impact::reduced;
  const std::string model = options.choice("model", comparison_law_names());
  const ComparisonLaw& law = comparison_law(model);
  const double restitution = options.real("restitution", Range{0.0, 1.0, false, true});
  const double velocity = options.real("velocity", Range::positive());
  const double mass = options.real("mass", Range::positive());
  const double stiffness = options.real("stiffness", Range::positive());
  const double exponent =
      options.real("exponent", Range::positive(), law.required_exponent.value_or(1.5));
  options.finish();

  const ContactSetup setup{mass, stiffness, exponent};
  const auto evaluation = evaluate_comparison_law(law, setup, restitution, velocity);
  const auto& impact = evaluation.impact;
  Json result;
  result["model"] = law.name;
  result["formula"] = law.formula;
  result["reference"] = law.reference;
  result["restitution"] = restitution;
  result["velocity"] = velocity;
  result["mass"] = mass;
  result["stiffness"] = stiffness;
  result["exponent"] = exponent;
  result["damping"] = evaluation.damping;
  result["damping_name"] = law.damping_name;
  result["damping_unit"] = law.damping_unit;
  result["restitution_produced"] = impact.restitution;
  result["restitution_error"] = evaluation.restitution_error;
  result["rebound_velocity"] = impact.rebound_velocity;
  result["force_at_separation"] = impact.force_at_separation;
  result["contact_time"] = impact.contact_time;
  result["compression_time"] = impact.compression_time;
  result["force_max"] = impact.force_max;
  result["time_force_max"] = impact.time_force_max;
  result["approach_max"] = impact.approach_max;
  print_json(out, result);
  return 0;
}

} // namespace impact::cli
