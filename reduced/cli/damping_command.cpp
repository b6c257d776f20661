// impact-reduced damping: the Hunt-Crossley damping constant that gives a restitution.

#include "commands.hpp"
#include "output.hpp"
#include "ranges.hpp"

#include "impact_reduced/hunt_crossley.hpp"

namespace impact::cli {

namespace {

int run_damping(CommandLine& options, std::ostream& out) {
  const double restitution = options.real("restitution");
  const double velocity = options.real("velocity");
  options.finish();

  const double beta = reduced::impact_parameter_from_restitution(restitution);
  Json result = Json::object();
  result["restitution"] = restitution;
  result["velocity"] = velocity;
  result["damping"] = beta / velocity;
  result["beta"] = beta;
  print_json(out, result);
  return 0;
}

} // namespace

Command damping_command() {
  return {"damping",
          "damping constant b of Hunt-Crossley from a restitution",
          "The damping constant b = beta / V of the Hunt-Crossley law F = c x^n (1 + b dx/dt) "
          "that gives the coefficient of restitution e at impact velocity V (beta = b V depends "
          "on e alone, whatever c, n and the mass).",
          {real_option("restitution", "E", ranges::restitution(),
                       "coefficient of restitution e [-]"),
           real_option("velocity", "V", ranges::velocity(), "impact velocity [m/s]")},
          "",
          run_damping};
}

} // namespace impact::cli
