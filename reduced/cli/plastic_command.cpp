// impact-reduced plastic: elastic-plastic impacts of a sphere on a flat (or of two spheres,
// given by their effective radius and mass) under Thornton's law or the Jackson-Green loading
// with the radius-preserving Hertzian unloading, for a list of velocities; or, with --loop N,
// the force-approach loop of one impact with its times (CSV, N points per branch). Beside
// either law, the restitution of Jackson, Green & Marghitu's (2010) fit for the same contact.

#include "commands.hpp"
#include "output.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/jackson_green_marghitu.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "impact_reduced/thornton.hpp"
#include "impact_reduced/yield_velocity.hpp"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace impact::cli {

namespace {

constexpr double pi = 3.14159265358979323846;

// The options of the command, checked.
struct PlasticOptions {
  std::string model;
  double radius, mass, modulus, poisson_ratio, flat_modulus, flat_poisson, yield_strength;
  std::string criterion_name, unloading_rule;
  std::vector<double> velocities;
  long loop_points;
  std::string format;
};

PlasticOptions parse_plastic_options(CommandLine& options) {
  const std::string model = options.choice("model", {"thornton", "jackson-green"});
  const Range poisson = Range::open(-1.0, 0.5);
  const double radius = options.real("radius", Range::positive());
  if (options.has("mass") && options.has("density"))
    throw UsageError("--mass and --density exclude each other: give the mass either directly "
                     "or as the density of a solid sphere of --radius");
  if (!options.has("mass") && !options.has("density"))
    throw UsageError("--mass or --density is required: the (effective) mass directly, or the "
                     "density of a solid sphere of --radius");
  const double mass = options.has("mass") ? options.real("mass", Range::positive())
                                          : 4.0 / 3.0 * pi * radius * radius * radius *
                                                options.real("density", Range::positive());
  const double modulus = options.real("modulus", Range::positive());
  const double poisson_ratio = options.real("poisson", poisson);
  const double flat_modulus = options.real("flat-modulus", Range::positive(), modulus);
  const double flat_poisson = options.real("flat-poisson", poisson, poisson_ratio);
  const double yield_strength = options.real("yield-strength", Range::positive());
  if (model == "jackson-green" && options.has("criterion"))
    throw UsageError("--criterion applies to --model thornton only (jackson-green uses its own "
                     "critical interference, p_y = C(nu) Y)");
  const std::string criterion_name =
      model == "thornton" ? options.choice("criterion", {"johnson", "jackson-green"}, "johnson")
                          : "jackson-green";
  if (model == "thornton" && options.has("unloading"))
    throw UsageError("--unloading applies to --model jackson-green only (Thornton's law unloads "
                     "on its own R_p)");
  const std::string unloading_rule =
      model == "jackson-green"
          ? options.choice("unloading", {"contact-radius", "brake"}, "contact-radius")
          : "thornton";
  const std::vector<double> velocities = options.reals("velocity", Range::positive());
  const long loop_points = options.integer("loop", 2, 1'000'000, 0);
  if (loop_points > 0 && velocities.size() != 1)
    throw UsageError("--loop prints the force-approach loop of one impact: give one --velocity "
                     "(received " + std::to_string(velocities.size()) + ")");
  const std::string format = options.choice("format", {"json", "csv"}, "json");
  options.finish();
  return {model,          radius,         mass,       modulus,     poisson_ratio,
          flat_modulus,   flat_poisson,   yield_strength, criterion_name, unloading_rule,
          velocities,     loop_points,    format};
}

// The law in words, for the JSON.
std::string law_text(const std::string& model, const std::string& unloading_rule) {
  if (model == "thornton")
    return "Thornton (1997): Hertz to p0 = p_y, then F = F_y + pi p_y R (x - x_y); Hertzian "
           "unloading on R_p = 4 E* a_p^3 / (3 F*), a_p^2 = (2 F* + F_y) / (2 pi p_y)";
  return std::string("Jackson & Green (2005) loading (Hertz up to 1.9 omega_c, their fit "
                     "beyond); ") +
         (unloading_rule == "brake"
              ? "Hertzian unloading of Brake (2015): recovery x_max P_m / P_Hertz(x_max)"
              : "Hertzian unloading keeping the contact radius of the maximum");
}

} // namespace

int run_plastic_command(CommandLine& command_line, std::ostream& out) {
  using namespace impact::reduced;
  const PlasticOptions options = parse_plastic_options(command_line);
  const std::string& model = options.model;
  const double radius = options.radius, mass = options.mass, modulus = options.modulus;
  const double poisson_ratio = options.poisson_ratio, yield_strength = options.yield_strength;
  const double flat_modulus = options.flat_modulus, flat_poisson = options.flat_poisson;
  const std::string &criterion_name = options.criterion_name,
                    &unloading_rule = options.unloading_rule, &format = options.format;
  const std::vector<double>& velocities = options.velocities;
  const long loop_points = options.loop_points;

  const double e_star = contact_modulus(modulus, poisson_ratio, flat_modulus, flat_poisson);
  const YieldCriterion criterion = criterion_name == "johnson" ? YieldCriterion::johnson
                                                               : YieldCriterion::jackson_green;
  const double p_y = yield_pressure(criterion, yield_strength, poisson_ratio);
  const SphereFlatContact sphere_flat{radius, e_star, yield_strength, poisson_ratio};
  const double v_y = yield_velocity(p_y, e_star, radius, mass);

  std::unique_ptr<ElasticPlasticContact> contact;
  if (model == "thornton")
    contact = std::make_unique<ThorntonContact>(radius, e_star, p_y);
  else
    contact = std::make_unique<JacksonGreenContact>(
        sphere_flat,
        unloading_rule == "brake" ? JacksonGreenUnloading::brake
                                  : JacksonGreenUnloading::contact_radius);

  if (loop_points > 0) {
    std::vector<std::vector<double>> rows;
    for (const auto& state : elastic_plastic_impact_loop(mass, velocities.front(), *contact,
                                                         static_cast<std::size_t>(loop_points)))
      rows.push_back({state.time, state.approach, state.approach_rate, state.force});
    print_csv(out, {"time", "approach", "approach_rate", "force"}, rows);
    return 0;
  }

  const std::vector<std::string> keys = {
      "velocity",        "velocity_ratio",   "restitution",      "contact_time",
      "compression_time", "force_max",       "approach_max",     "residual_approach",
      "dissipated_energy", "restitution_jackson_green_marghitu"};
  std::vector<std::vector<double>> rows;
  for (const double velocity : velocities) {
    const ElasticPlasticImpactResponse r =
        model == "thornton" ? ThorntonImpact({mass, radius, e_star, p_y}, velocity).response()
                            : elastic_plastic_impact(mass, velocity, *contact);
    // The fit gives e <= 0 far above its range: printed as NaN (null in JSON), not refused,
    // since the law's own figures are still valid there.
    double jgm = std::numeric_limits<double>::quiet_NaN();
    try {
      jgm = jackson_green_marghitu_restitution(velocity, sphere_flat, mass);
    } catch (const InvalidInput&) {
    }
    rows.push_back({velocity, velocity / v_y, r.restitution, r.contact_time, r.compression_time,
                    r.force_max, r.approach_max, r.residual_approach, r.dissipated_energy, jgm});
  }
  if (format == "csv") {
    print_csv(out, keys, rows);
    return 0;
  }
  Json result = Json::object();
  result["model"] = model;
  result["law"] = law_text(model, unloading_rule);
  result["yield_criterion"] = criterion_name;
  result["unloading"] = unloading_rule;
  result["radius"] = radius;
  result["mass"] = mass;
  result["contact_modulus"] = e_star;
  result["yield_strength"] = yield_strength;
  result["yield_pressure"] = p_y;
  result["yield_approach"] = yield_approach(p_y, e_star, radius);
  result["yield_force"] = yield_force(p_y, e_star, radius);
  result["yield_velocity"] = v_y;
  result["jackson_green_marghitu_critical_velocity"] =
      jackson_green_marghitu_critical_velocity(sphere_flat, mass);
  result["jackson_green_marghitu"] =
      "Jackson, Green & Marghitu (2010) restitution fit, e = 1 - 0.0361 eps^-0.114 ln(V/V_c) "
      "(V/V_c - 1)^(9.5 eps), eps = C(nu) Y / E*, as read in one public implementation; its "
      "constants could not be confirmed (reduced/include/impact_reduced/"
      "jackson_green_marghitu.hpp)";
  Json impacts = Json::array();
  for (const auto& row : rows) {
    Json entry = Json::object();
    for (std::size_t k = 0; k < keys.size(); ++k) entry[keys[k]] = row[k];
    impacts.push_back(entry);
  }
  result["impacts"] = impacts;
  print_json(out, result);
  return 0;
}

} // namespace impact::cli
