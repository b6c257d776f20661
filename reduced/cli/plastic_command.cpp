// impact-reduced plastic: elastic-plastic impacts of a sphere on a flat (or of two spheres,
// given by their effective radius and mass) under Thornton's law or the Jackson-Green loading
// with the radius-preserving Hertzian unloading, for a list of velocities; or, with --loop N,
// the force-approach loop of one impact with its times (CSV, N points per branch). Beside
// either law, the restitution of Jackson, Green & Marghitu's (2010) fit for the same contact.

#include "commands.hpp"
#include "output.hpp"
#include "ranges.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/jackson_green_marghitu.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "impact_reduced/thornton.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace impact::cli {

namespace {

// The options of the command, checked.
struct PlasticOptions {
  std::string model;
  double radius, mass, modulus, poisson_ratio, flat_modulus, flat_poisson;
  bool rigid_flat;
  double yield_strength;
  std::string criterion_name, unloading_rule;
  std::vector<double> velocities;
  long loop_points;
  std::string format;
};

PlasticOptions parse_plastic_options(CommandLine& options) {
  using namespace impact::reduced;
  const std::string model = options.choice("model");
  const double radius = options.real("radius");
  if (options.has("mass") && options.has("density"))
    throw UsageError(
        "--mass and --density exclude each other: give the mass either directly "
        "or as the density of a solid sphere of --radius");
  if (!options.has("mass") && !options.has("density"))
    throw UsageError(
        "--mass or --density is required: the (effective) mass directly, or the "
        "density of a solid sphere of --radius");
  const double mass = options.has("mass") ? options.real("mass")
                                          : solid_sphere_mass(radius, options.real("density"));
  if (!options.has("mass"))
    options.require_within("mass", mass,
                           "the solid sphere of --radius and --density has a mass of");
  const double modulus = options.real("modulus");
  const double poisson_ratio = options.real("poisson");
  if (options.has("flat") && (options.has("flat-modulus") || options.has("flat-poisson")))
    throw UsageError(std::string("--flat rigid and --") +
                     (options.has("flat-modulus") ? "flat-modulus" : "flat-poisson") +
                     " exclude each other: the flat is either rigid or has a modulus and a "
                     "Poisson's ratio");
  const bool rigid_flat = options.has("flat") && options.choice("flat") == "rigid";
  const ElasticBody flat = rigid_flat ? rigid_body()
                                      : ElasticBody{options.real("flat-modulus", modulus),
                                                    options.real("flat-poisson", poisson_ratio)};
  const double yield_strength = options.real("yield-strength");
  if (model == "jackson-green")
    options.require_absent("criterion",
                           "applies to --model thornton only (jackson-green uses "
                           "its own critical interference, p_y = C(nu) Y)");
  const std::string criterion_name =
      model == "thornton" ? options.choice("criterion") : "jackson-green";
  if (model == "thornton")
    options.require_absent("unloading",
                           "applies to --model jackson-green only (Thornton's law "
                           "unloads on its own R_p)");
  const std::string unloading_rule =
      model == "jackson-green" ? options.choice("unloading") : "thornton";
  const std::vector<double> velocities = options.reals("velocity");
  const long loop_points = options.integer("loop", 0);
  if (loop_points > 0 && velocities.size() != 1)
    throw UsageError(
        "--loop prints the force-approach loop of one impact: give one --velocity "
        "(received " +
        std::to_string(velocities.size()) + ")");
  const std::string format = options.choice("format");
  options.finish();
  return {model,
          radius,
          mass,
          modulus,
          poisson_ratio,
          flat.youngs_modulus,
          flat.poisson_ratio,
          rigid_flat,
          yield_strength,
          criterion_name,
          unloading_rule,
          velocities,
          loop_points,
          format};
}

// The law in words, for the JSON.
std::string law_text(const std::string& model, const std::string& unloading_rule) {
  if (model == "thornton")
    return "Thornton (1997): Hertz to p0 = p_y, then F = F_y + pi p_y R (x - x_y); Hertzian "
           "unloading on R_p = 4 E* a_p^3 / (3 F*), a_p^2 = (2 F* + F_y) / (2 pi p_y)";
  return std::string(
             "Jackson & Green (2005) loading (Hertz up to 1.9 omega_c, their fit "
             "beyond); ") +
         (unloading_rule == "brake"
              ? "Hertzian unloading of Brake (2015): recovery x_max P_m / P_Hertz(x_max)"
              : "Hertzian unloading keeping the contact radius of the maximum");
}

std::string text_of(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

// The laws hold for small strains: refuses a yield strain Y/E* or an impact whose approach
// would exceed the limits of ranges.hpp (checked by energy: the impact's kinetic energy
// against the law's loading work up to that approach), naming the options.
void require_small_strains(double yield_strength, double e_star, double radius, double mass,
                           const std::vector<double>& velocities,
                           const reduced::ElasticPlasticContact& contact) {
  if (yield_strength / e_star > ranges::largest_yield_strain)
    throw UsageError("--yield-strength " + text_of(yield_strength) + " is " +
                     text_of(yield_strength / e_star) +
                     " times the contact modulus E* = " + text_of(e_star) +
                     " Pa of --modulus, --poisson and the flat: the yield "
                     "strain Y/E* must be at most " +
                     text_of(ranges::largest_yield_strain));
  const double approach = ranges::largest_approach_ratio * radius;
  const double work = contact.loading_work(approach);
  for (const double velocity : velocities)
    if (!(0.5 * mass * velocity * velocity <= work))
      throw UsageError("--velocity " + text_of(velocity) +
                       " carries the contact beyond an "
                       "approach of " +
                       text_of(ranges::largest_approach_ratio) + " --radius: its kinetic energy " +
                       text_of(0.5 * mass * velocity * velocity) +
                       " J exceeds the loading work up to there, " + text_of(work) +
                       " J; the laws hold for approaches small against the radius (a lower "
                       "--velocity or --mass, or a larger --radius)");
}

int run_plastic(CommandLine& command_line, std::ostream& out) {
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
  const YieldCriterion criterion =
      criterion_name == "johnson" ? YieldCriterion::johnson : YieldCriterion::jackson_green;
  const double p_y = yield_pressure(criterion, yield_strength, poisson_ratio);
  const SphereFlatContact sphere_flat{radius, e_star, yield_strength, poisson_ratio};
  const double v_y = yield_velocity(p_y, e_star, radius, mass);

  std::unique_ptr<ElasticPlasticContact> contact;
  if (model == "thornton")
    contact = std::make_unique<ThorntonContact>(radius, e_star, p_y);
  else
    contact = std::make_unique<JacksonGreenContact>(sphere_flat,
                                                    unloading_rule == "brake"
                                                        ? JacksonGreenUnloading::brake
                                                        : JacksonGreenUnloading::contact_radius);

  require_small_strains(yield_strength, e_star, radius, mass, velocities, *contact);

  if (loop_points > 0) {
    std::vector<std::vector<double>> rows;
    for (const auto& state : elastic_plastic_impact_loop(mass, velocities.front(), *contact,
                                                         static_cast<std::size_t>(loop_points)))
      rows.push_back({state.time, state.approach, state.approach_rate, state.force});
    print_csv(out, {"time", "approach", "approach_rate", "force"}, rows);
    return 0;
  }

  const std::vector<std::string> keys = {"velocity",          "velocity_ratio",
                                         "restitution",       "contact_time",
                                         "compression_time",  "force_max",
                                         "approach_max",      "residual_approach",
                                         "dissipated_energy", "restitution_jackson_green_marghitu"};
  std::vector<std::vector<double>> rows;
  for (const double velocity : velocities) {
    const ElasticPlasticImpactResponse r =
        model == "thornton" ? ThorntonImpact({mass, radius, e_star, p_y}, velocity).response()
                            : elastic_plastic_impact(mass, velocity, *contact);
    // The fit gives e <= 0 far above its range: no value there (null in JSON, an empty field
    // in CSV), not refused, since the law's own figures are still valid there.
    double jgm = std::numeric_limits<double>::quiet_NaN();
    try {
      jgm = jackson_green_marghitu_restitution(velocity, sphere_flat, mass);
    } catch (const InvalidInput&) {
    }
    rows.push_back({velocity, velocity / v_y, r.restitution, r.contact_time, r.compression_time,
                    r.force_max, r.approach_max, r.residual_approach, r.dissipated_energy, jgm});
  }
  if (format == "csv") {
    print_csv(out, keys, rows, {"restitution_jackson_green_marghitu"});
    return 0;
  }
  Json result = Json::object();
  result["model"] = model;
  result["law"] = law_text(model, unloading_rule);
  result["yield_criterion"] = criterion_name;
  result["unloading"] = unloading_rule;
  result["radius"] = radius;
  result["mass"] = mass;
  result["flat"] = options.rigid_flat ? "rigid" : "elastic";
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
    for (std::size_t k = 0; k < keys.size(); ++k)
      entry[keys[k]] = std::isnan(row[k]) ? Json(nullptr) : Json(row[k]);
    impacts.push_back(entry);
  }
  result["impacts"] = impacts;
  print_json(out, result);
  return 0;
}

} // namespace

Command plastic_command() {
  return {"plastic",
          "elastic-plastic impact of a sphere on a flat (or two spheres: effective radius and "
          "mass): restitution, contact time, peak force, maximum and permanent approach, V/V_y",
          "Elastic-plastic impacts of a sphere on a flat (or of two spheres, given by their "
          "effective radius and mass) under Thornton's law or the Jackson-Green loading with a "
          "Hertzian unloading, for a list of velocities: restitution, contact and compression "
          "times, peak force, maximum and residual approach, dissipated energy, V/V_y; beside "
          "either law, the restitution of Jackson, Green & Marghitu's (2010) fit for the same "
          "contact. With --loop N, the force-approach loop of one impact instead.",
          {choice_option("model", {"thornton", "jackson-green"}, "the elastic-plastic contact law"),
           heading("The sphere:"),
           real_option("radius", "R", ranges::radius(), "(effective) radius [m]"),
           real_option("mass", "M", ranges::mass(), "(effective) mass [kg]"),
           real_option("density", "RHO", ranges::density(),
                       "density [kg/m^3] of a solid sphere of --radius, instead of --mass"),
           real_option("modulus", "E", ranges::modulus(), "Young's modulus of the sphere [Pa]"),
           real_option("poisson", "NU", ranges::poisson(), "Poisson's ratio of the sphere [-]"),
           real_option("yield-strength", "Y", ranges::yield_strength(),
                       "uniaxial yield strength of the sphere [Pa]"),
           heading("The flat:"),
           real_option("flat-modulus", "E", ranges::modulus(), "Young's modulus of the flat [Pa]")
               .with_default_note("--modulus"),
           real_option("flat-poisson", "NU", ranges::poisson(), "Poisson's ratio of the flat [-]")
               .with_default_note("--poisson"),
           choice_option("flat", {"rigid"},
                         "a rigid flat, instead of --flat-modulus and --flat-poisson"),
           heading("The laws:"),
           choice_option("criterion", {"johnson", "jackson-green"},
                         "first yield of --model thornton: p_y = 1.6 Y (johnson) or C(nu) Y")
               .with_default("johnson"),
           choice_option("unloading", {"contact-radius", "brake"},
                         "Hertzian unloading of --model jackson-green: keeping the contact radius "
                         "of the maximum, or Brake's (2015) recovery")
               .with_default("contact-radius"),
           heading("The impacts and the output:"),
           reals_option("velocity", "V[,V...]", ranges::velocity(), "impact velocities [m/s]"),
           integer_option("loop", "N", 2, 1'000'000,
                          "print instead the force-approach loop of one impact (one --velocity), "
                          "N points per branch, CSV time,approach,approach_rate,force"),
           choice_option("format", {"json", "csv"}, "output format").with_default("json")},
          "Give the mass either by --mass or by --density. The laws hold for small strains: the "
          "yield strain Y/E* must be at most 0.05, and every impact must stay below an approach of "
          "half the radius. The restitution of Jackson, Green & "
          "Marghitu's fit is null (JSON) or empty (CSV) where the fit gives e <= 0, far above the "
          "range it was made for.\n",
          run_plastic};
}

} // namespace impact::cli
