#pragma once
/// @file
/// The contact-mechanics formulas of the project, in one place: the contact modulus,
/// effective radius and mass of two bodies, Hertz's coefficient, the peak approach, peak force
/// and contact time of a Hertz impact, the yield criteria and the impact velocity at first
/// yield. Every other part of the project (the reduced laws, the calibration and report, the
/// FEM's estimates) takes them from here.
///
/// Hertz (J. reine angew. Math. 92, 1882; Johnson, Contact Mechanics, CUP 1985, sec. 4.2 and
/// 11.4): two elastic bodies of effective radius R and contact modulus E* carry
/// F = c x^(3/2), c = (4/3) E* sqrt(R), at approach x, with contact radius a = sqrt(R x) and
/// peak pressure p0 = (2 E* / pi) sqrt(x / R). A sphere of (effective) mass m hitting at V
/// reaches x_max = (5 m V^2 / (4 c))^(2/5) and leaves after t_c = 2 (2/5) B(2/5, 1/2) x_max / V
/// = 2.9432 x_max / V (the quasi-static impact: energy m V^2 / 2 = (2/5) c x_max^(5/2)).
///
/// The contact yields when p0 reaches a limiting pressure p_y. Two criteria are in use:
///   - Johnson (Contact Mechanics, sec. 4.2 and 11.4): first yield below the surface
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
/// All functions: SI units, accuracy a few ulps (the contact time: a few ulps of the exact
/// Beta-function constant); they throw InvalidInput naming the parameter for a non-positive
/// or non-finite modulus, radius, mass, density, strength or velocity, and for a Poisson
/// ratio outside (-1, 0.5).

#include <limits>

namespace impact::reduced {

/// The two yield criteria.
enum class YieldCriterion {
  johnson,      ///< p_y = 1.6 Y
  jackson_green ///< p_y = C(nu) Y, C = 1.295 exp(0.736 nu)
};

/// An elastic body at the contact: Young's modulus [Pa], Poisson's ratio [-] and the
/// radius of curvature at the contact point [m] (infinity for a plate or half-space).
/// A rigid body has an infinite modulus: make it with rigid_body().
struct ElasticBody {
  double youngs_modulus;
  double poisson_ratio;
  double radius = std::numeric_limits<double>::infinity();
};

/// A rigid body (no compliance: (1 - nu^2)/E = 0), a flat unless `radius` is given. Its
/// modulus is +infinity, the only infinite modulus hertz_stiffness accepts; its Poisson ratio
/// (0) has no effect.
inline ElasticBody rigid_body(double radius = std::numeric_limits<double>::infinity()) {
  return {std::numeric_limits<double>::infinity(), 0.0, radius};
}

/// Contact compliance 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa]. E > 0 (+infinity for a
/// rigid body, whose term vanishes), -1 < nu < 0.5. Not validated: the callers below are.
double contact_compliance(double youngs_modulus_1, double poisson_ratio_1, double youngs_modulus_2,
                          double poisson_ratio_2);

/// Contact modulus E* [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. E > 0, -1 < nu < 0.5;
/// one of the two moduli may be +infinity, a rigid body (rigid_body()), whose term vanishes.
double contact_modulus(double youngs_modulus_1, double poisson_ratio_1, double youngs_modulus_2,
                       double poisson_ratio_2);

/// Effective radius R1 R2 / (R1 + R2) [m]; R > 0, one of the two may be infinite (a flat).
double effective_radius(double radius_1, double radius_2);

/// Effective mass m1 m2 / (m1 + m2) [kg]; m > 0, one of the two may be infinite (a fixed body).
double effective_mass(double mass_1, double mass_2);

/// Hertz coefficient c = (4/3) E* sqrt(R) [N/m^1.5] of F = c x^(3/2); E*, R > 0 and finite.
double hertz_coefficient(double contact_modulus, double radius);

/// Hertz stiffness c [N/m^1.5] of two bodies, F = c x^(3/2):
///     1/c = (3/4) ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) sqrt(1/R1 + 1/R2),
/// the same c as hertz_coefficient(contact_modulus(...), effective_radius(...)) to a few ulps.
/// Ranges: E > 0 (infinity for a rigid body, rigid_body(); not both), -1 < nu < 0.5, R > 0
/// (infinity allowed for one of the two, not both). Throws InvalidInput naming the offending
/// field ("first.radius"...), also when c overflows (is not finite).
double hertz_stiffness(const ElasticBody& first, const ElasticBody& second);

/// Mass (4/3) pi R^3 rho [kg] of a solid sphere of radius R > 0 [m] and density rho > 0
/// [kg/m^3]. Throws InvalidInput naming "radius", "density", or "mass" when the product
/// overflows or underflows to 0.
double solid_sphere_mass(double radius, double density);

/// Peak approach x_max = (5 m V^2 / (4 c))^(2/5) [m] of a Hertz impact of coefficient
/// c [N/m^1.5] (hertz_coefficient), effective mass m [kg] and impact speed V [m/s]; c, m > 0,
/// V >= 0.
double hertz_peak_approach(double coefficient, double mass, double velocity);

/// Peak force F_max = c x_max^(3/2) [N] of the same impact.
double hertz_peak_force(double coefficient, double mass, double velocity);

/// Contact time t_c = 2 (2/5) B(2/5, 1/2) x_max / V = 2.943 x_max / V [s] of the same impact
/// (the compression and the restitution each take half of it); V > 0.
double hertz_contact_time(double coefficient, double mass, double velocity);

/// The impact speed V = sqrt((4/5) c x^(5/2) / m) [m/s] whose Hertz impact peaks at approach
/// x >= 0 [m] (the inverse of hertz_peak_approach); c, m > 0.
double hertz_impact_velocity(double coefficient, double mass, double approach);

/// Hertz's peak pressure p0 = (2 E* / pi) sqrt(x / R) = 3 c sqrt(x) / (2 pi R) [Pa] at
/// approach x >= 0 [m], written with the coefficient c = (4/3) E* sqrt(R) [N/m^1.5]; c, R > 0.
double hertz_peak_pressure(double coefficient, double radius, double approach);

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
