// impact-reduced hc: the Hunt-Crossley impact in closed form.

#include "commands.hpp"
#include "output.hpp"
#include "ranges.hpp"
#include "sphere_flat_options.hpp"

#include "impact_reduced/hunt_crossley.hpp"

namespace impact::cli {

namespace {

int run_hc(CommandLine& options, std::ostream& out) {
  const SphereFlat body = read_sphere_flat(options);
  const double mass = body.mass, stiffness = body.stiffness, exponent = body.exponent;
  const double damping = options.real("damping");
  const double velocity = options.real("velocity");
  if (damping * velocity > ranges::largest_impact_parameter)
    throw UsageError("--damping and --velocity give an impact parameter b V = " +
                     std::to_string(damping * velocity) + ", above the largest accepted, " +
                     std::to_string(ranges::largest_impact_parameter) +
                     " (where the restitution is about 1e-3)");
  const long history_points = options.integer("history", 0);
  const std::string format = options.choice("format");
  options.finish();

  const reduced::HuntCrossleyImpact impact(mass, stiffness, exponent, damping, velocity);

  if (history_points > 0) {
    std::vector<std::vector<double>> rows;
    for (const auto& state : impact.history(static_cast<std::size_t>(history_points)))
      rows.push_back({state.time, state.approach, state.approach_rate, state.force});
    print_csv(out, {"time", "approach", "velocity", "force"}, rows);
    return 0;
  }

  const reduced::ImpactResponse response = impact.response();
  const std::vector<std::pair<std::string, double>> fields = {
      {"mass", mass},
      {"stiffness", stiffness},
      {"exponent", exponent},
      {"damping", damping},
      {"velocity", velocity},
      {"impact_parameter", impact.impact_parameter()},
      {"x_max", response.approach_max},
      {"force_max", response.force_max},
      {"time_force_max", response.time_force_max},
      {"compression_time", response.compression_time},
      {"contact_time", response.contact_time},
      {"rebound_velocity", response.rebound_velocity},
      {"restitution", response.restitution},
      {"energy_loss", response.energy_loss},
  };
  if (format == "csv") {
    std::vector<std::string> columns;
    std::vector<double> row;
    for (const auto& [key, value] : fields) {
      columns.push_back(key);
      row.push_back(value);
    }
    print_csv(out, columns, {row});
    return 0;
  }
  Json result = Json::object();
  for (const auto& [key, value] : fields) result[key] = value;
  result["contact"] = body.contact_basis;
  result["mass_from"] = body.mass_basis;
  print_json(out, result);
  return 0;
}

} // namespace

Command hc_command() {
  std::vector<Option> options = sphere_flat_options("exponent n of F = c x^n [-]");
  options.push_back(heading("The impact:"));
  options.push_back(real_option("damping", "B", ranges::damping(),
                                "damping constant b of F = c x^n (1 + b dx/dt) [s/m]; b V at "
                                "most 1e3"));
  options.push_back(real_option("velocity", "V", ranges::velocity(), "impact velocity [m/s]"));
  options.push_back(heading("Output:"));
  options.push_back(integer_option("history", "P", 2, 10'000'000,
                                   "print instead the time history at P instants over the "
                                   "contact, CSV time,approach,velocity,force"));
  options.push_back(choice_option("format", {"json", "csv"}, "output format").with_default("json"));
  return {"hc",
          "Hunt-Crossley impact in closed form (x_max, peak force, contact time, restitution, ...)",
          "The impact of a sphere (mass m) on a fixed flat under the Hunt-Crossley law "
          "F = c x^n (1 + b dx/dt), in closed form (Lambert W): maximum approach, peak force and "
          "its time, compression and contact times, rebound velocity, restitution, energy loss.",
          std::move(options),
          sphere_flat_notes(),
          run_hc};
}

} // namespace impact::cli
