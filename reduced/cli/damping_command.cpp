// impact-reduced damping: the Hunt-Crossley damping constant that gives a restitution.

#include "commands.hpp"
#include "output.hpp"

#include "impact_reduced/hunt_crossley.hpp"

namespace impact::cli {

int run_damping_command(CommandLine& options, std::ostream& out) {
  const double restitution = options.real("restitution", Range{0.0, 1.0, false, true});
  const double velocity = options.real("velocity", Range::positive());
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

} // namespace impact::cli
