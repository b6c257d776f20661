#pragma once
/// @file
/// The restitution of an elastic-perfectly-plastic sphere impacting a rigid flat, fitted to
/// finite-element impacts by Jackson, Green & Marghitu, "Predicting the coefficient of
/// restitution of impacting elastic-perfectly plastic spheres", Nonlinear Dyn. 60:217-229
/// (2010).
///
/// The paper could not be read here (only its first page and abstract are stored: "Empirical
/// fits to the results are provided"). The formula was read in ONE public implementation, a
/// Python script in the stored code index that estimates boulder impacts on bridge piers with
/// Thornton's and Jackson-Green's laws (its repository could not be identified by the search
/// tools; it labels the line with the title of Jackson & Green's 2005 paper, not of JGM 2010):
///   e = 1 - 0.0361 eps_y^(-0.114) ln(V*) (V* - 1)^(9.5 eps_y),   V* = V / V_c,
/// with V_c the impact velocity whose Hertz impact reaches Jackson-Green's critical interference
/// omega_c = (pi C Y / (2 E*))^2 R, C = C(nu) = 1.295 exp(0.736 nu) (contact_formulas.hpp,
/// criterion jackson_green), and eps_y = C Y / E*. THE CONSTANTS 0.0361, -0.114 AND 9.5 COULD
/// NOT BE CONFIRMED against the paper or a second source, nor could the definition of eps_y
/// (the script divides C Y, not Y, by E*; it hard-codes C = 1.6 beside a commented-out C(nu),
/// which is used here, 1.615 for nu = 0.3). Evidence that the reading is right, not proof:
/// the project's own finite-element impacts of an elastic-perfectly-plastic sphere on a rigid
/// flat (fem/README.md, "Dynamic elastic-plastic impact") lie within 0.018 in e of this
/// formula from 2 to 50 V_y, where Thornton's law is 0.02-0.18 below them.
///
/// e = 1 at V* <= 1 (no plastic work below the critical velocity: the fit's e is 1 there, as
/// ln 1 = 0). The formula falls below 0 at large V* (e.g. V* of about 500 for eps_y = 0.015);
/// the range of velocities the fit was made for could not be read.
///
/// Accuracy: a few ulps of the formula as written (std::log, std::pow).

#include "impact_reduced/sphere_flat_fits.hpp"

namespace impact::reduced {

/// e [-] at V* = V / V_c >= 0 and eps_y = C(nu) Y / E* in (0, 1). Throws InvalidInput naming
/// "velocity_ratio" (negative, non-finite, or so large that the formula gives e <= 0) or
/// "yield_strain".
double jackson_green_marghitu_restitution(double velocity_ratio, double yield_strain);

/// The yield strain eps_y = C(nu) Y / E* [-] of the contact (the reading's definition, above).
double jackson_green_marghitu_yield_strain(const SphereFlatContact& contact);

/// The critical velocity V_c [m/s] of the contact (R, E*, Y, nu) for the effective mass m > 0
/// [kg]: yield_velocity(C(nu) Y, E*, R, m).
double jackson_green_marghitu_critical_velocity(const SphereFlatContact& contact, double mass);

/// e [-] of the impact at V >= 0 [m/s] of the effective mass m > 0 [kg] on the contact:
/// jackson_green_marghitu_restitution(V / V_c, jackson_green_marghitu_yield_strain(contact)).
double jackson_green_marghitu_restitution(double velocity, const SphereFlatContact& contact,
                                          double mass);

} // namespace impact::reduced
