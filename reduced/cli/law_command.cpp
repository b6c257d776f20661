// impact-reduced law: a comparison contact law, the damping its own formula assigns to a
// target restitution, and the restitution it really produces (reference ODE integration).

#include "commands.hpp"
#include "output.hpp"
#include "ranges.hpp"
#include "sphere_flat_options.hpp"

#include "impact_reduced/comparison_laws.hpp"

namespace impact::cli {

namespace {

int run_law(CommandLine& options, std::ostream& out) {
  using namespace impact::reduced;
  const std::string model = options.choice("model");
  const ComparisonLaw& law = comparison_law(model);
  const double restitution = options.real("restitution");
  const double velocity = options.real("velocity");
  const SphereFlat body = read_sphere_flat(options, "--model " + model, law.required_exponent);
  const double mass = body.mass, stiffness = body.stiffness, exponent = body.exponent;
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
  result["contact"] = body.contact_basis;
  result["mass_from"] = body.mass_basis;
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

} // namespace

Command law_command() {
  std::vector<Option> options = {
      choice_option("model", reduced::comparison_law_names(), "the contact law"),
      real_option("restitution", "E", ranges::restitution(),
                  "target coefficient of restitution e [-], mapped to the law's damping by the "
                  "law's own formula"),
      real_option("velocity", "V", ranges::velocity(), "impact velocity [m/s]")};
  for (const auto& option : sphere_flat_options(
           "exponent n of the elastic force c x^n [-]; a law defined for one n only "
           "(kelvin-voigt: 1; tsuji, kuwabara-kono: 3/2) takes that n by default and refuses "
           "another"))
    options.push_back(option);
  return {"law",
          "a comparison contact law: the damping its own formula assigns and the restitution it "
          "really produces",
          "A comparison contact law of the literature: the damping its own formula assigns to a "
          "target restitution at the impact velocity, and the impact it then really produces "
          "(reference ODE integration): restitution, its error against the target, contact "
          "time, peak force, maximum approach.",
          std::move(options),
          sphere_flat_notes(),
          run_law};
}

} // namespace impact::cli
