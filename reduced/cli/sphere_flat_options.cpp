#include "sphere_flat_options.hpp"

#include "ranges.hpp"

#include "impact_reduced/contact_formulas.hpp"

#include <sstream>

namespace impact::cli {

namespace {

std::string text_of(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

const char* contact_ways =
    "the contact either by --stiffness [--exponent], or by the materials: --sphere-modulus, "
    "--sphere-poisson, --radius, and --flat-modulus with --flat-poisson or --flat rigid";
const char* mass_ways = "the sphere's mass either by --mass or by --sphere-density and --radius";

} // namespace

void require_one_of(const CommandLine& options, const std::string& direct,
                    const std::string& derived, const std::string& what) {
  if (options.has(direct) && options.has(derived))
    throw UsageError("--" + direct + " and --" + derived + " exclude each other: give " + what);
  if (!options.has(direct) && !options.has(derived))
    throw UsageError("--" + direct + " or --" + derived + " is required: give " + what);
}

std::vector<Option> sphere_flat_options(const std::string& exponent_help) {
  return {
      heading("The contact, given directly:"),
      real_option("stiffness", "C", ranges::stiffness(), "stiffness c of F = c x^n [N/m^n]"),
      real_option("exponent", "N", ranges::exponent(), exponent_help).with_default("1.5"),
      heading("or from the materials (Hertz, n = 3/2):"),
      real_option("sphere-modulus", "E", ranges::modulus(), "Young's modulus of the sphere [Pa]"),
      real_option("sphere-poisson", "NU", ranges::poisson(), "Poisson's ratio of the sphere [-]"),
      real_option("radius", "R", ranges::radius(),
                  "radius of the sphere [m] (also for --sphere-density)"),
      real_option("flat-modulus", "E", ranges::modulus(), "Young's modulus of the flat [Pa]"),
      real_option("flat-poisson", "NU", ranges::poisson(), "Poisson's ratio of the flat [-]"),
      choice_option("flat", {"rigid"},
                    "a rigid flat, instead of --flat-modulus and --flat-poisson"),
      heading("The mass of the sphere, given directly:"),
      real_option("mass", "M", ranges::mass(), "mass of the sphere [kg]"),
      heading("or that of a solid sphere, (4/3) pi R^3 rho:"),
      real_option("sphere-density", "RHO", ranges::density(),
                  "density of the sphere [kg/m^3], with --radius"),
  };
}

std::string sphere_flat_notes() {
  return std::string("Give ") + contact_ways + "; and " + mass_ways + ".\n";
}

SphereFlat read_sphere_flat(CommandLine& options, const std::string& law_name,
                            std::optional<double> required_exponent) {
  using namespace impact::reduced;
  require_one_of(options, "stiffness", "sphere-modulus", contact_ways);
  require_one_of(options, "mass", "sphere-density", mass_ways);
  SphereFlat result{};
  if (options.has("stiffness")) {
    for (const char* material : {"sphere-poisson", "flat-modulus", "flat-poisson", "flat"})
      if (options.has(material))
        throw UsageError(std::string("--stiffness and --") + material +
                         " exclude each other: give " + contact_ways);
    result.stiffness = options.real("stiffness");
    result.exponent =
        required_exponent ? options.real("exponent", *required_exponent) : options.real("exponent");
    result.contact_basis = "given: c and n";
  } else {
    options.require_absent("exponent",
                           "applies to --stiffness only (the Hertz contact of "
                           "--sphere-modulus and the flat has n = 3/2)");
    if (required_exponent && *required_exponent != 1.5)
      throw UsageError("--sphere-modulus gives a Hertz contact (n = 3/2), but " + law_name +
                       " is defined for n = " + text_of(*required_exponent) +
                       " only: give --stiffness");
    if (options.has("flat") && (options.has("flat-modulus") || options.has("flat-poisson")))
      throw UsageError(std::string("--flat rigid and --") +
                       (options.has("flat-modulus") ? "flat-modulus" : "flat-poisson") +
                       " exclude each other: the flat is either rigid or has a modulus and a "
                       "Poisson's ratio");
    if (!options.has("flat") && !options.has("flat-modulus") && !options.has("flat-poisson"))
      throw UsageError(
          "--flat-modulus and --flat-poisson, or --flat rigid, are required with "
          "--sphere-modulus: the flat's material");
    const ElasticBody sphere{options.real("sphere-modulus"), options.real("sphere-poisson"),
                             options.real("radius")};
    const bool rigid = options.has("flat");
    if (rigid) options.choice("flat");
    const ElasticBody flat =
        rigid ? rigid_body()
              : ElasticBody{options.real("flat-modulus"), options.real("flat-poisson")};
    result.stiffness = hertz_stiffness(sphere, flat);
    options.require_within("stiffness", result.stiffness,
                           "the Hertz contact of --sphere-modulus, --sphere-poisson, --radius "
                           "and the flat has a stiffness c of");
    result.exponent = 1.5;
    result.contact_basis = "Hertz: sphere E = " + text_of(sphere.youngs_modulus) +
                           " Pa, nu = " + text_of(sphere.poisson_ratio) +
                           ", R = " + text_of(sphere.radius) + " m on " +
                           (rigid ? std::string("a rigid flat")
                                  : "a flat of E = " + text_of(flat.youngs_modulus) +
                                        " Pa, nu = " + text_of(flat.poisson_ratio));
  }
  if (options.has("mass")) {
    result.mass = options.real("mass");
    result.mass_basis = "given";
  } else {
    const double radius = options.real("radius");
    const double density = options.real("sphere-density");
    result.mass = solid_sphere_mass(radius, density);
    options.require_within("mass", result.mass,
                           "the solid sphere of --radius and --sphere-density has a mass of");
    result.mass_basis =
        "solid sphere: R = " + text_of(radius) + " m, rho = " + text_of(density) + " kg/m^3";
  }
  return result;
}

} // namespace impact::cli
