#pragma once
/// @file
/// The Jackson–Green elastic-plastic sphere–flat law (J. Tribol. 127:343, 2005;
/// reduced/sphere_flat_fits.hpp) as a comparison model of the calibration: fitted
/// ("jackson-green", c and the yield strength Y free) and from the scenario's material with
/// nothing fitted (the reference model "jackson-green-material").
///
/// The law: Hertz up to 1.9 omega_c, then Jackson & Green's finite-element fit of the load;
/// unloading Hertzian on the radius that keeps the contact radius of the maximum
/// (reduced::JacksonGreenUnloading::contact_radius, the principle of Thornton's R_p and the
/// unloading tmd-lab attributes to Etsion, Kligerman & Kadin 2005). Unlike Thornton's law it
/// cannot be written in c and one approach alone: besides c and omega_c the fit depends on
/// Y/E* (through B and the hardness H_G) and on nu (through C(nu)), so the model takes the
/// sphere radius R and the Poisson ratio nu of the yielding body from the scenario and fits
/// c [N/m^1.5] and Y [Pa], with E* = 3 c / (4 sqrt R) and n = 3/2. Hardening does not enter:
/// the fit is that of an elastic–perfectly-plastic sphere, and a hardening law recorded by
/// the runs is not used (the no-fit model's basis says so).

#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The scenario's constants for the sphere–flat laws, read from the first run's parameters:
/// the sphere radius ("Scenario/Sphere radius"; on a flat the effective radius), and the Poisson
/// ratio nu, yield strength Y and contact modulus E* of the body that yields first
/// (scenario_plastic_contact); without a yield strength, nu of the sphere and no Y.
struct SphereFlatScenario {
  double radius;                         ///< R [m]
  double poisson_ratio;                  ///< nu of the yielding body (else of the sphere)
  std::optional<double> contact_modulus; ///< E* [Pa] (with a yield strength)
  std::optional<double> yield_strength;  ///< Y [Pa] of the body that yields first
  std::string basis;                     ///< where the numbers come from, in words
};

/// None when the runs record no radius or no Poisson ratio (or a body with a strength but
/// without elastic constants).
std::optional<SphereFlatScenario> sphere_flat_scenario(const std::vector<FemRun>& runs);

/// The law in words (ContactModel::formula of jackson_green_model), with the scenario's R [m]
/// and nu when given.
std::string jackson_green_formula(std::optional<double> radius = std::nullopt,
                                  std::optional<double> poisson_ratio = std::nullopt);

/// The fitted model "jackson-green" for sphere radius R > 0 [m] and Poisson ratio nu in
/// (-1, 0.5) of the yielding body; its damping constant is Y [Pa]. Throws
/// reduced::InvalidInput naming "radius" or "poisson_ratio".
ContactModel jackson_green_model(double radius, double poisson_ratio);

/// Jackson–Green from the scenario's material, nothing fitted: c = (4/3) E* sqrt(R), Y of
/// the body that yields first. None without a yield strength (sphere_flat_scenario).
struct MaterialJacksonGreen {
  double stiffness;      ///< c [N/m^1.5]
  double yield_strength; ///< Y [Pa]
  ContactModel model;    ///< jackson_green_model(R, nu)
  std::string basis;     ///< where the numbers come from, and how hardening enters
};
std::optional<MaterialJacksonGreen> material_jackson_green(const std::vector<FemRun>& runs);

} // namespace impact::postprocess
