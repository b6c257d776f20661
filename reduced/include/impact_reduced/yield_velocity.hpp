#pragma once
/// @file
/// First yield of a Hertz contact and the impact velocity that reaches it.
///
/// A Hertz contact of two elastic bodies (effective radius R, contact modulus E*) carries
/// F = (4/3) E* sqrt(R) x^(3/2) at approach x, with contact radius a = sqrt(R x) and peak
/// pressure p0 = (2 E* / pi) sqrt(x / R). It yields when p0 reaches a limiting pressure p_y.
/// Two criteria are in use:
///   - Johnson (Contact Mechanics, CUP 1985, sec. 4.2 and 11.4): first yield below the surface
///     when p0 = 1.6 Y (von Mises, nu ~ 0.3), Y the uniaxial yield strength; Thornton (1997)
///     takes this p_y as the limiting contact pressure of his impact law.
///   - Jackson & Green (J. Tribol. 127:343, 2005): critical interference
///     omega_c = (pi C Y / (2 E*))^2 R with C(nu) = 1.295 exp(0.736 nu), nu the Poisson ratio
///     of the yielding body. This is the Hertz approach at which p0 = C Y, i.e. the same
///     criterion with p_y = C(nu) Y (C(0.3) = 1.61). Read in tmd-lab/microslip-rough-contact,
///     ROUTINES/FRIC_MODELS/PLASTIC/SPHERE_PLASTIC_PRE.m and UTS_CRIT.m (C and delta_y), and in
///     a Jackson-Green rough-surface script (JG.m, same C and omega_c): two consistent readings.
///
/// The yield velocity V_y is the impact velocity whose Hertz impact just reaches x_y:
///     (1/2) m V_y^2 = (8/15) E* sqrt(R) x_y^(5/2),  x_y = R (pi p_y / (2 E*))^2
///     =>  V_y = sqrt(pi^5 R^3 p_y^5 / (30 m E*^4)).
/// For a sphere of density rho on a half-space (m = 4/3 pi R^3 rho) this is Johnson's and
/// Thornton's V_y = (pi^2 / sqrt(40)) sqrt(p_y^5 / (E*^4 rho)) = 1.5605 sqrt(p_y^5/(E*^4 rho)),
/// the "1.56" of the literature. For two spheres use the effective radius
/// R = R1 R2 / (R1 + R2), the effective mass m = m1 m2 / (m1 + m2), E* of both bodies, and
/// V the relative velocity of approach.
///
/// All functions: SI units, accuracy a few ulps; they throw InvalidInput naming the
/// parameter for a non-positive or non-finite modulus, radius, mass, density or strength,
/// and for a Poisson ratio outside (-1, 0.5).

namespace impact::reduced {

/// The two yield criteria.
enum class YieldCriterion {
  johnson,      ///< p_y = 1.6 Y
  jackson_green ///< p_y = C(nu) Y, C = 1.295 exp(0.736 nu)
};

/// Contact modulus E* [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. E > 0, -1 < nu < 0.5;
/// one of the two moduli may be +infinity, a rigid body (rigid_body() of hertz_stiffness.hpp),
/// whose term vanishes.
double contact_modulus(double youngs_modulus_1, double poisson_ratio_1, double youngs_modulus_2,
                       double poisson_ratio_2);

/// Effective radius R1 R2 / (R1 + R2) [m]; R > 0, one of the two may be infinite (a flat).
double effective_radius(double radius_1, double radius_2);

/// Effective mass m1 m2 / (m1 + m2) [kg]; m > 0, one of the two may be infinite (a fixed body).
double effective_mass(double mass_1, double mass_2);

/// Johnson's limiting pressure 1.6 Y [Pa], Y > 0 [Pa].
double johnson_yield_pressure(double yield_strength);

/// Jackson-Green's C(nu) = 1.295 exp(0.736 nu) [-], -1 < nu < 0.5.
double jackson_green_yield_coefficient(double poisson_ratio);

/// The limiting pressure p_y [Pa] of a criterion: 1.6 Y or C(nu) Y. The Poisson ratio is
/// that of the yielding body (unused by Johnson's criterion, but still validated).
double yield_pressure(YieldCriterion criterion, double yield_strength, double poisson_ratio);

/// Approach at first yield x_y = R (pi p_y / (2 E*))^2 [m] (Jackson-Green's omega_c when
/// p_y = C Y). p_y, E*, R > 0.
double yield_approach(double yield_pressure, double contact_modulus, double radius);

/// Force at first yield F_y = pi^3 R^2 p_y^3 / (6 E*^2) [N] (Jackson-Green's P_c when
/// p_y = C Y).
double yield_force(double yield_pressure, double contact_modulus, double radius);

/// V_y = sqrt(pi^5 R^3 p_y^5 / (30 m E*^4)) [m/s] for effective mass m and radius R.
double yield_velocity(double yield_pressure, double contact_modulus, double radius, double mass);

/// Half-space form: V_y = (pi^2/sqrt(40)) sqrt(p_y^5 / (E*^4 rho)) for a solid sphere of
/// density rho [kg/m^3] on a fixed flat (equal to yield_velocity with m = 4/3 pi R^3 rho).
double half_space_yield_velocity(double yield_pressure, double contact_modulus, double density);

} // namespace impact::reduced
