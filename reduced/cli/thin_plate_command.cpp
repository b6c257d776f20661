// impact-reduced thin-plate: a sphere on an infinite thin (Kirchhoff) plate, Zener's model.
//
// The contact is given either directly (--stiffness, --exponent) or by the sphere's
// material and radius (Hertz stiffness on the plate's material); the sphere's mass either
// directly (--mass) or by its density and radius.

#include "commands.hpp"
#include "output.hpp"
#include "ranges.hpp"
#include "sphere_flat_options.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/thin_plate.hpp"

#include <sstream>

namespace impact::cli {

namespace {

std::string text_of(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

// The sphere's side of the impact: the contact law's c and n and the sphere's mass, given
// directly or from the sphere's material and radius (Hertz on the plate's material).
struct Sphere {
  double stiffness = 0;
  double exponent = 1.5;
  double mass = 0;
};

Sphere read_sphere(CommandLine& options, const reduced::KirchhoffPlate& plate) {
  using namespace impact::reduced;
  require_one_of(options, "stiffness", "sphere-modulus",
                 "the contact either by --stiffness [--exponent] or by --sphere-modulus, "
                 "--sphere-poisson and --radius");
  require_one_of(options, "mass", "sphere-density",
                 "the sphere's mass either by --mass or by --sphere-density and --radius");
  const bool needs_radius = options.has("sphere-modulus") || options.has("sphere-density");
  const double radius = needs_radius ? options.real("radius") : 0.0;
  Sphere sphere;
  if (options.has("stiffness")) {
    sphere.stiffness = options.real("stiffness");
    sphere.exponent = options.real("exponent");
  } else {
    options.require_absent("exponent",
                           "applies to --stiffness only (the Hertz contact of "
                           "--sphere-modulus and the plate has n = 3/2)");
    const ElasticBody body{options.real("sphere-modulus"), options.real("sphere-poisson"), radius};
    sphere.stiffness = hertz_stiffness(body, {plate.youngs_modulus, plate.poisson_ratio});
    options.require_within("stiffness", sphere.stiffness,
                           "the Hertz contact of --sphere-modulus, --sphere-poisson, --radius "
                           "and the plate has a stiffness c of");
  }
  sphere.mass = options.has("mass") ? options.real("mass")
                                    : solid_sphere_mass(radius, options.real("sphere-density"));
  if (!options.has("mass"))
    options.require_within("mass", sphere.mass,
                           "the solid sphere of --radius and --sphere-density has a mass of");
  return sphere;
}

// Zener's model holds for a plate stiff enough that lambda stays in the validated range.
void require_stiff_enough_plate(const reduced::ThinPlateImpact& model,
                                const std::vector<double>& velocities) {
  for (const double velocity : velocities)
    if (model.zener_lambda(velocity) > ranges::largest_zener_lambda)
      throw UsageError("--velocity " + text_of(velocity) +
                       " gives Zener's lambda = " + text_of(model.zener_lambda(velocity)) +
                       ", above " + text_of(ranges::largest_zener_lambda) +
                       ", the largest accepted: the plate is too compliant for this sphere "
                       "(lambda grows with --mass, --stiffness and the velocity, falls with "
                       "--thickness and --plate-modulus)");
}

const std::vector<std::string> result_keys = {"velocity",
                                              "zener_lambda",
                                              "restitution",
                                              "contact_time",
                                              "force_max",
                                              "time_force_max",
                                              "approach_max",
                                              "time_approach_max",
                                              "plate_energy_fraction",
                                              "damping_energy_fraction",
                                              "plate_deflection",
                                              "number_of_contacts"};

std::vector<double> result_values(double velocity, const reduced::ThinPlateImpactResult& r) {
  return {velocity,
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
}

int run_thin_plate(CommandLine& options, std::ostream& out) {
  using namespace impact::reduced;
  const KirchhoffPlate plate{options.real("plate-modulus"), options.real("plate-poisson"),
                             options.real("plate-density"), options.real("thickness")};
  const Sphere sphere = read_sphere(options, plate);
  const double damping = options.real("damping");
  const std::vector<double> velocities = options.reals("velocity");
  const double tolerance = options.real("tolerance");
  const std::string format = options.choice("format");
  options.finish();

  const double impedance = plate_point_impedance(plate);
  const ThinPlateImpact model(sphere.stiffness, sphere.exponent, damping, sphere.mass, impedance);
  require_stiff_enough_plate(model, velocities);
  std::vector<ThinPlateImpactResult> results;
  for (const double velocity : velocities) results.push_back(model.impact(velocity, tolerance));

  if (format == "csv") {
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < velocities.size(); ++i)
      rows.push_back(result_values(velocities[i], results[i]));
    print_csv(out, result_keys, rows);
    return 0;
  }
  Json result = Json::object();
  result["model"] = "Zener: sphere on an infinite Kirchhoff plate, Hunt-Crossley contact";
  result["stiffness"] = sphere.stiffness;
  result["exponent"] = sphere.exponent;
  result["damping"] = damping;
  result["mass"] = sphere.mass;
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
    const auto row = result_values(velocities[i], results[i]);
    for (std::size_t k = 0; k < result_keys.size(); ++k) entry[result_keys[k]] = row[k];
    entry["number_of_contacts"] = results[i].number_of_contacts;
    impacts.push_back(entry);
  }
  result["impacts"] = impacts;
  print_json(out, result);
  return 0;
}

} // namespace

Command thin_plate_command() {
  return {
      "thin-plate",
      "a sphere on an infinite thin (Kirchhoff) plate, Zener's model: restitution, contact "
      "time, peaks, energy into the plate, Zener's lambda",
      "A sphere hitting an infinite thin (Kirchhoff) plate, Zener's model: a Hunt-Crossley "
      "contact F = c x^n (1 + b dx/dt) in series with the plate's point impedance. For each "
      "velocity: restitution, contact time, peak force and approach, the energy fractions into "
      "the plate and the damping, the plate's deflection, Zener's lambda.",
      {heading("The plate:"),
       real_option("plate-modulus", "E", ranges::modulus(), "Young's modulus of the plate [Pa]"),
       real_option("plate-poisson", "NU", ranges::poisson(), "Poisson's ratio of the plate [-]"),
       real_option("plate-density", "RHO", ranges::density(), "density of the plate [kg/m^3]"),
       real_option("thickness", "H", ranges::thickness(), "thickness of the plate [m]"),
       heading("The contact, given directly:"),
       real_option("stiffness", "C", ranges::stiffness(), "stiffness c of F = c x^n [N/m^n]"),
       real_option("exponent", "N", ranges::plate_exponent(), "exponent n [-]").with_default("1.5"),
       heading("or by Hertz from the sphere's material on the plate's (n = 3/2):"),
       real_option("sphere-modulus", "E", ranges::modulus(), "Young's modulus of the sphere [Pa]"),
       real_option("sphere-poisson", "NU", ranges::poisson(), "Poisson's ratio of the sphere [-]"),
       real_option("radius", "R", ranges::radius(),
                   "radius of the sphere [m] (also for --sphere-density)"),
       heading("The mass of the sphere, given directly:"),
       real_option("mass", "M", ranges::mass(), "mass of the sphere [kg]"),
       heading("or that of a solid sphere, (4/3) pi R^3 rho:"),
       real_option("sphere-density", "RHO", ranges::density(),
                   "density of the sphere [kg/m^3], with --radius"),
       heading("The impacts:"),
       real_option("damping", "B", ranges::damping(), "damping constant b [s/m]").with_default("0"),
       reals_option("velocity", "V[,V...]", ranges::velocity(), "impact velocities [m/s]"),
       real_option("tolerance", "TOL", Range::closed(1e-14, 1e-3),
                   "relative tolerance of the integration [-]")
           .with_default("1e-11"),
       choice_option("format", {"json", "csv"}, "output format").with_default("json")},
      "Give the contact either by --stiffness [--exponent] or by --sphere-modulus, "
      "--sphere-poisson and --radius; and the mass either by --mass or by --sphere-density and "
      "--radius. Zener's lambda, m / (Z t0), must be at most 200 at every velocity (the range "
      "over which the model's integration is verified).\n",
      run_thin_plate};
}

} // namespace impact::cli
