// impact-reduced hc: the Hunt-Crossley impact in closed form.

#include "commands.hpp"
#include "output.hpp"

#include "impact_reduced/hunt_crossley.hpp"

namespace impact::cli {

int run_hc_command(CommandLine& options, std::ostream& out) {
  const double mass = options.real("mass", Range::positive());
  const double stiffness = options.real("stiffness", Range::positive());
  const double exponent = options.real("exponent", Range::positive());
  const double damping = options.real("damping", Range::non_negative());
  const double velocity = options.real("velocity", Range::positive());
  const long history_points = options.integer("history", 2, 10'000'000, 0);
  const std::string format = options.choice("format", {"json", "csv"}, "json");
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
  print_json(out, result);
  return 0;
}

} // namespace impact::cli
