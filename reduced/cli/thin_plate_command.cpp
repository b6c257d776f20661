// impact-reduced thin-plate: a sphere on an infinite thin (Kirchhoff) plate, Zener's model.
//
// The contact is given either directly (--stiffness, --exponent) or by the sphere's
// material and radius (Hertz stiffness on the plate's material); the sphere's mass either
// directly (--mass) or by its density and radius.

#include "commands.hpp"
#include "output.hpp"

#include "impact_reduced/hertz_stiffness.hpp"
#include "impact_reduced/thin_plate.hpp"

namespace impact::cli {

namespace {

constexpr double pi = 3.14159265358979323846;

// Exactly one of two ways of giving a quantity.
void require_one_of(const CommandLine& options, const std::string& direct,
                    const std::string& derived, const std::string& what) {
  if (options.has(direct) && options.has(derived))
    throw UsageError("--" + direct + " and --" + derived + " exclude each other: give " + what);
  if (!options.has(direct) && !options.has(derived))
    throw UsageError("--" + direct + " or --" + derived + " is required: give " + what);
}

} // namespace

int run_thin_plate_command(CommandLine& options, std::ostream& out) {
  using namespace impact::reduced;
  const Range poisson = Range::open(-1.0, 0.5);
  const KirchhoffPlate plate{options.real("plate-modulus", Range::positive()),
                             options.real("plate-poisson", poisson),
                             options.real("plate-density", Range::positive()),
                             options.real("thickness", Range::positive())};

  require_one_of(options, "stiffness", "sphere-modulus",
                 "the contact either by --stiffness [--exponent] or by --sphere-modulus, "
                 "--sphere-poisson and --radius");
  require_one_of(options, "mass", "sphere-density",
                 "the sphere's mass either by --mass or by --sphere-density and --radius");
  const bool needs_radius = options.has("sphere-modulus") || options.has("sphere-density");
  const double radius = needs_radius ? options.real("radius", Range::positive()) : 0.0;
  double stiffness = 0;
  double exponent = 1.5;
  if (options.has("stiffness")) {
    stiffness = options.real("stiffness", Range::positive());
    exponent = options.real("exponent", Range::positive(), 1.5);
  } else {
    const ElasticBody sphere{options.real("sphere-modulus", Range::positive()),
                             options.real("sphere-poisson", poisson), radius};
    stiffness = hertz_stiffness(sphere, {plate.youngs_modulus, plate.poisson_ratio});
  }
  const double mass = options.has("mass")
                          ? options.real("mass", Range::positive())
                          : 4.0 / 3.0 * pi * radius * radius * radius *
                                options.real("sphere-density", Range::positive());
  const double damping = options.real("damping", Range::non_negative(), 0.0);
  const std::vector<double> velocities = options.reals("velocity", Range::positive());
  const double tolerance = options.real("tolerance", Range::closed(1e-14, 1e-3), 1e-11);
  const std::string format = options.choice("format", {"json", "csv"}, "json");
  options.finish();

  const double impedance = plate_point_impedance(plate);
  const ThinPlateImpact model(stiffness, exponent, damping, mass, impedance);
  std::vector<ThinPlateImpactResult> results;
  for (const double velocity : velocities) results.push_back(model.impact(velocity, tolerance));

  const std::vector<std::string> keys = {
      "velocity",         "zener_lambda",      "restitution",
      "contact_time",     "force_max",         "time_force_max",
      "approach_max",     "time_approach_max", "plate_energy_fraction",
      "damping_energy_fraction", "plate_deflection", "number_of_contacts"};
  const auto values = [](double velocity, const ThinPlateImpactResult& r) {
    return std::vector<double>{velocity,
                               r.zener_lambda,
                               r.restitution,
                               r.contact_time,
                               r.force_max,
                               r.time_force_max,
                               r.approach_max,
                               r.time_approach_max,
                               r.plate_energy_fraction,
                               r.damping_energy_fraction,
                               r.plate_deflection,
                               static_cast<double>(r.number_of_contacts)};
  };
  if (format == "csv") {
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < velocities.size(); ++i)
      rows.push_back(values(velocities[i], results[i]));
    print_csv(out, keys, rows);
    return 0;
  }
  Json result = Json::object();
  result["model"] = "Zener: sphere on an infinite Kirchhoff plate, Hunt-Crossley contact";
  result["stiffness"] = stiffness;
  result["exponent"] = exponent;
  result["damping"] = damping;
  result["mass"] = mass;
  result["plate_modulus"] = plate.youngs_modulus;
  result["plate_poisson"] = plate.poisson_ratio;
  result["plate_density"] = plate.density;
  result["thickness"] = plate.thickness;
  result["flexural_rigidity"] = flexural_rigidity(plate);
  result["impedance"] = impedance;
  result["tolerance"] = tolerance;
  Json impacts = Json::array();
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    Json entry = Json::object();
    const auto row = values(velocities[i], results[i]);
    for (std::size_t k = 0; k < keys.size(); ++k) entry[keys[k]] = row[k];
    entry["number_of_contacts"] = results[i].number_of_contacts;
    impacts.push_back(entry);
  }
  result["impacts"] = impacts;
  print_json(out, result);
  return 0;
}

} // namespace impact::cli
