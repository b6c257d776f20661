#pragma once
/// @file
/// The rate-independent elastic-plastic laws of the reduced library as comparison models of
/// the calibration (contact_models.hpp): a loading curve while the approach grows and a
/// Hertzian unloading branch from the maximum approach (reduced/elastic_plastic_impact.hpp).
/// They have no force law F(x, x') (the unloading depends on the maximum approach), so a model
/// carries its ElasticPlasticContact (ContactModel::plastic_contact) and its impacts come from
/// reduced::elastic_plastic_impact.
///
/// "thornton": Thornton (J. Appl. Mech. 64:383, 1997; reduced/thornton.hpp), with n = 3/2 and
/// two free parameters: c = (4/3) E* sqrt(R) [N/m^1.5] and the yield approach
/// x_y = R (pi p_y / (2 E*))^2 [m] (the law's "damping constant"). The law depends on R only
/// through c and x_y (F_y = c x_y^(3/2), plastic slope pi p_y R = (3/2) c sqrt(x_y), and the
/// R_p unloading leaves x_max - x_p and F* unchanged when R varies at fixed c and x_y), so it
/// is fitted without the radius; the limiting pressure follows with the sphere radius R:
/// p_y = 3 c sqrt(x_y) / (2 pi R) (thornton_yield_pressure), and the yield velocity from the
/// Hertz energy at x_y: V_y = sqrt(4 c x_y^(5/2) / (5 m)). Hardening does not enter the law.

#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <optional>

#include <string>
#include <vector>

namespace impact::postprocess {

/// What the plastic models share: n = 3/2 fixed, one dissipation parameter (the law's yield
/// parameter `symbol` [`unit`]) used as the damping constant itself, no force law F(x, x').
/// The caller sets damping_for_restitution and plastic_contact.
ContactModel plastic_model_base(std::string name, std::string formula, std::string reference,
                                std::string symbol, std::string unit);

/// The plastic models' names ("thornton", "jackson-green": jackson_green_model.hpp).
const std::vector<std::string>& plastic_model_names();

/// True for a name of plastic_model_names().
bool is_plastic_model(const std::string& name);

/// The plastic model `name`; throws reduced::InvalidInput("model") for another name and for
/// a model that needs the scenario (needs_scenario).
ContactModel plastic_model(const std::string& name);

/// Whether the model needs constants of the scenario beyond c (jackson-green and the damped
/// models on its spring, damped_plastic_models.hpp: the sphere radius and the Poisson ratio of
/// the yielding body).
bool needs_scenario(const std::string& name);

/// The comparison model `name` (contact_models.hpp, comparison_model) with the constants of
/// the runs' scenario where it needs them (sphere_flat_scenario); throws
/// reduced::InvalidInput("model") naming what the runs do not record.
ContactModel comparison_model(const std::string& name, const std::vector<FemRun>& runs);

/// The formula of any model by name (contact_model(name).formula), also of those that need
/// the scenario.
std::string model_formula(const std::string& name);

/// Whether the FEM of the runs can yield: some run has an elastic-plastic sphere or plate.
bool runs_can_yield(const std::vector<FemRun>& runs);

/// The comparison models `names` for the runs, leaving out (and naming in `left_out`) those
/// that need the scenario when the runs do not record it, and the plastic and damped plastic
/// models when no material of the runs can yield (runs_can_yield): their yield parameter
/// would then only stand in for the viscous loss, a fit with no material meaning (and the
/// costliest of the calibration). Throws reduced::InvalidInput for an unknown name.
std::vector<ContactModel> comparison_models(const std::vector<std::string>& names,
                                            const std::vector<FemRun>& runs,
                                            std::vector<std::string>& left_out);

/// The comparison models impact-calibrate fits: the reduced library's comparison laws, then
/// the plastic models, then the damped elastic-plastic models (damped_plastic_models.hpp).
std::vector<std::string> comparison_model_names();

/// Thornton's limiting contact pressure p_y = 3 c sqrt(x_y) / (2 pi R) [Pa] from c
/// [N/m^1.5], the yield approach x_y [m] and the sphere radius R [m] (effective radius).
double thornton_yield_pressure(double stiffness, double yield_approach, double radius);

/// Thornton's yield approach x_y = (5 m V_y^2 / (4 c))^(2/5) [m] for the yield velocity V_y,
/// and its inverse V_y = sqrt(4 c x_y^(5/2) / (5 m)): the Hertz impact that just reaches x_y.
double thornton_yield_approach(double yield_velocity, double mass, double stiffness);
double thornton_yield_velocity(double yield_approach, double mass, double stiffness);

/// Thornton's law from the scenario's material, nothing fitted (the calibration's reference
/// model "thornton-material"): E* and p_y of scenario_plastic_contact (run/, Johnson's
/// p_y = 1.6 Y of the body that yields first) and the sphere radius R ("Scenario/Sphere
/// radius"), c = (4/3) E* sqrt(R), x_y = R (pi p_y / (2 E*))^2. None when the runs record no
/// yield strength, no radius, or a body with a strength but without elastic constants.
struct MaterialThornton {
  double stiffness;      ///< c [N/m^1.5]
  double yield_approach; ///< x_y [m]
  std::string basis;     ///< where the numbers come from, in words
};
std::optional<MaterialThornton> material_thornton(const std::vector<FemRun>& runs);

} // namespace impact::postprocess
