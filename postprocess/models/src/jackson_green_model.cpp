// The Jackson–Green comparison models (jackson_green_model.hpp).

#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>
#include <impact_reduced/contact_formulas.hpp>

#include <cmath>
#include <memory>

namespace impact::postprocess {

namespace {

// E* of the law for stiffness c: c = (4/3) E* sqrt(R).
double contact_modulus_of(double stiffness, double radius) {
  return 0.75 * stiffness / std::sqrt(radius);
}

double restitution_of(double yield_strength, double velocity, double radius, double poisson_ratio,
                      const reduced::ContactSetup& setup) {
  const reduced::JacksonGreenContact contact(
      {radius, contact_modulus_of(setup.stiffness, radius), yield_strength, poisson_ratio});
  return reduced::elastic_plastic_impact(setup.mass, velocity, contact).restitution;
}

// The Y with which the law gives restitution e at V (for starting values and scales):
// bisection in ln Y below the Y whose Jackson–Green yield velocity is V (e = 1 above it).
// e grows with Y except next to the fit's jump at 1.9 omega_c, where the bisection still
// returns a Y of the right size.
double yield_strength_for_restitution(double restitution, double velocity, double radius,
                                      double poisson_ratio, const reduced::ContactSetup& setup) {
  const double e_star = contact_modulus_of(setup.stiffness, radius);
  const double coefficient = reduced::jackson_green_yield_coefficient(poisson_ratio);
  // V_y grows as p_y^(5/2): the p_y of V_y = V from the V_y of p_y = 1 GPa.
  const double reference = 1e9;
  const double v_reference = reduced::yield_velocity(reference, e_star, radius, setup.mass);
  const double upper_pressure = reference * std::pow(velocity / v_reference, 0.4);
  double upper = std::log(upper_pressure / coefficient);
  if (!(restitution < 1)) return std::exp(upper);
  double lower = upper - std::log(1e4);
  for (int i = 0; i < 60 && upper - lower > 1e-10; ++i) {
    const double middle = 0.5 * (lower + upper);
    double e = 0;
    try {
      e = restitution_of(std::exp(middle), velocity, radius, poisson_ratio, setup);
    } catch (const std::exception&) {
      e = 0;
    }
    (e < restitution ? lower : upper) = middle;
  }
  return std::exp(0.5 * (lower + upper));
}

} // namespace

std::string jackson_green_formula(std::optional<double> radius,
                                  std::optional<double> poisson_ratio) {
  const std::string scenario = radius && poisson_ratio
                                   ? "R = " + significant(*radius, 6) +
                                         " m and nu = " + significant(*poisson_ratio, 6) +
                                         " of the scenario"
                                   : "R and nu of the scenario";
  return "F = c x^(3/2) up to 1.9 omega_c, then Jackson & Green's fit P/P_c = "
         "exp(-w^(5/12)/4) w^(3/2) + (4 H_G/(C Y)) (1 - exp(-w^(5/9)/25)) w, w = x/omega_c, "
         "P_c = c omega_c^(3/2), H_G/Y = 2.84 (1 - exp(-0.82 (a/R)^-0.7)), E* = 3 c/(4 sqrt R), "
         "omega_c = (pi C Y/(2 E*))^2 R, C = 1.295 exp(0.736 nu), with " +
         scenario +
         "; unloading Hertzian on the radius that keeps the contact radius of the maximum; "
         "no rate dependence, no hardening";
}

ContactModel jackson_green_model(double radius, double poisson_ratio) {
  reduced::require_positive("radius", radius);
  reduced::require_open_interval("poisson_ratio", poisson_ratio, -1.0, 0.5);
  ContactModel model = plastic_model_base(
      std::string(model_keys::jackson_green), jackson_green_formula(radius, poisson_ratio),
      "Jackson & Green, J. Tribol. 127 (2005) 343-354 (loading, elastic-perfectly-plastic "
      "sphere on a rigid flat); unloading on the radius of the maximum contact, after Etsion, "
      "Kligerman & Kadin, Int. J. Solids Struct. 42 (2005) 3716 (their own fits not "
      "implemented)",
      "Y", "Pa");
  model.damping_for_restitution = [radius, poisson_ratio](double e, double velocity,
                                                          const reduced::ContactSetup& setup) {
    return yield_strength_for_restitution(e, velocity, radius, poisson_ratio, setup);
  };
  model.plastic_contact = [radius, poisson_ratio](double yield_strength,
                                                  const reduced::ContactSetup& setup) {
    return std::make_shared<reduced::JacksonGreenContact>(
        reduced::SphereFlatContact{radius, contact_modulus_of(setup.stiffness, radius),
                                   yield_strength, poisson_ratio});
  };
  return model;
}

std::optional<SphereFlatScenario> sphere_flat_scenario(const std::vector<FemRun>& runs) {
  if (runs.empty()) return std::nullopt;
  const auto radius = text_number(runs.front(), fem_format::sphere_radius.path);
  if (!radius || !(*radius > 0)) return std::nullopt;
  std::optional<PlasticContact> contact;
  try {
    contact = scenario_plastic_contact(runs);
  } catch (const PlasticContactError&) {
    return std::nullopt;
  }
  if (contact)
    return SphereFlatScenario{*radius, contact->yield_poisson_ratio, contact->contact_modulus,
                              contact->yield_strength,
                              "R = " + significant(*radius, 6) +
                                  " m ('Scenario/Sphere radius'), E* = " +
                                  significant(contact->contact_modulus, 6) +
                                  " Pa, nu = " + significant(contact->yield_poisson_ratio, 6) +
                                  " and Y = " + significant(contact->yield_strength, 6) +
                                  " Pa of the body that "
                                  "yields first (" +
                                  contact->yield_basis + ")"};
  const auto nu =
      material_constant(runs.front(), fem_format::sphere_body, fem_format::poissons_ratio);
  if (!nu || !(*nu > -1 && *nu < 0.5)) return std::nullopt;
  return SphereFlatScenario{*radius, *nu, std::nullopt, std::nullopt,
                            "R = " + significant(*radius, 6) +
                                " m ('Scenario/Sphere radius'), nu = " + significant(*nu, 6) +
                                " of the sphere (no yield strength recorded)"};
}

std::optional<MaterialJacksonGreen> material_jackson_green(const std::vector<FemRun>& runs) {
  const auto scenario = sphere_flat_scenario(runs);
  if (!scenario || !scenario->yield_strength || !scenario->contact_modulus) return std::nullopt;
  return MaterialJacksonGreen{
      reduced::hertz_coefficient(*scenario->contact_modulus, scenario->radius),
      *scenario->yield_strength, jackson_green_model(scenario->radius, scenario->poisson_ratio),
      "no fit: " + scenario->basis + "; c = (4/3) E* sqrt(R); " + hardening_note(runs.front())};
}

} // namespace impact::postprocess
