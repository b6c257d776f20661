#pragma once
/// @file
/// Thornton's elastic-perfectly-plastic impact law (C. Thornton, "Coefficient of restitution
/// for collinear collisions of elastic-perfectly plastic spheres", J. Appl. Mech. 64:383-386,
/// 1997). The paper could not be read here; the law is the one implemented as the normal
/// model `thornton_ning` of LIGGGHTS (CFDEMproject/LIGGGHTS-PUBLIC,
/// src/normal_model_thornton_ning.h, read with zero surface energy), whose loading branches
/// agree with the formulas below, and every closed form below is derived here from them
/// (README "Elastic-plastic impact laws" gives the derivation).
///
/// Contact of effective radius R and contact modulus E* (contact_formulas.hpp), limiting
/// contact pressure p_y (Johnson's 1.6 Y, or C(nu) Y):
///   - Hertz loading F = (4/3) E* sqrt(R) x^(3/2) until the peak pressure reaches p_y at
///     x_y = R (pi p_y / (2 E*))^2, F_y = pi^3 R^2 p_y^3 / (6 E*^2);
///   - then the pressure is truncated at p_y and the load grows linearly,
///     F = F_y + pi p_y R (x - x_y)  (LIGGGHTS: dF/dx = 2 E* a_y = pi p_y R);
///   - unloading is Hertzian on the enlarged radius R_p that keeps the contact radius of the
///     maximum, a_p^2 = (2 F* + F_y) / (2 pi p_y):
///       R_p = 4 E* a_p^3 / (3 F*),  F = (4/3) E* sqrt(R_p) (x - x_p)^(3/2),
///     with F* = F(x_max) and the permanent approach x_p = x_max - 3 F* / (4 E* a_p).
///     (LIGGGHTS with zero surface energy keeps the radius R and unloads along
///     F* - (4/3) E* sqrt(R) (x_max^(3/2) - x^(3/2)) instead: liggghts_thornton.hpp.)
///
/// Closed forms (derived from the above), with r = V_y / V < 1 and delta = (x_max - x_y)/x_y:
///   delta = 2 (1/r^2 - 1) / (5/2 + sqrt(15/(2 r^2) - 5/4)),
///   x_max = x_y (1 + delta),  F_max = F_y (1 + 3 delta / 2),
///   e = r (1 + 3 delta / 2) / (1 + delta)^(1/4),
///   x_p = x_y ((1 + delta)^(3/2) - 1 - 3 delta / 2) / sqrt(1 + delta),
/// and the contact time is the sum of three closed-form phase times (Hertz phase: an
/// incomplete Beta function; plastic phase: a harmonic arc; unloading: Hertz on R_p).
/// For V <= V_y the impact is Hertz's (e = 1, no dent). Far above V_y, e ~ 1.185 r^(1/4):
/// the (V/V_y)^(-1/4) law.

#include "impact_reduced/elastic_plastic_impact.hpp"

namespace impact::reduced {

/// The contact and the impacting body of Thornton's law. SI units.
struct ThorntonParameters {
  double mass;            ///< effective mass m [kg], > 0
  double radius;          ///< effective radius R [m], > 0
  double contact_modulus; ///< E* [Pa], > 0
  double yield_pressure;  ///< limiting contact pressure p_y [Pa], > 0 (1.6 Y or C(nu) Y)
};

/// Thornton's loading/unloading law as an ElasticPlasticContact (for elastic_plastic_impact
/// and for force-approach curves). Throws InvalidInput naming "radius", "contact_modulus" or
/// "yield_pressure".
class ThorntonContact final : public ElasticPlasticContact {
public:
  ThorntonContact(double radius, double contact_modulus, double yield_pressure);
  double loading_force(double approach) const override;
  double loading_work(double approach) const override;
  double loading_stiffness(double approach) const override;
  /// Both at once (the same values as the two calls).
  std::pair<double, double> loading_force_and_stiffness(double approach) const override;
  /// In closed form: Hertz's inverse below W_L(x_y), the root of the quadratic above.
  double loading_approach(double work) const override;
  /// In closed form, without cancellation for small d.
  double loading_work_below(double approach_max, double distance) const override;
  std::vector<double> loading_breakpoints() const override { return {yield_approach_}; }
  /// Hertz's up to the yield approach.
  std::optional<PowerLawCoefficients> loading_power_law() const override {
    return PowerLawCoefficients{hertz_stiffness_, 1.5};
  }
  HertzianUnloading unloading(double approach_max) const override;

  double yield_approach() const { return yield_approach_; }
  double yield_force() const { return yield_force_; }
  /// pi p_y R [N/m], the slope of the plastic branch.
  double plastic_stiffness() const { return plastic_stiffness_; }
  /// (4/3) E* sqrt(R) [N/m^1.5].
  double hertz_stiffness() const { return hertz_stiffness_; }
  /// The unloading radius R_p [m] after loading to x_max (R for x_max <= x_y).
  double unloading_radius(double approach_max) const;

private:
  double radius_;
  double contact_modulus_;
  double yield_pressure_;
  double yield_approach_;
  double yield_force_;
  double plastic_stiffness_;
  double hertz_stiffness_;
};

/// One impact under Thornton's law, all in closed form.
///
/// Accuracy (tests/reduced/test_thornton.cpp): against an independent long-double
/// Runge-Kutta-Fehlberg 7(8) integration of m x'' = -F(x) with exact event location, and
/// against the quadrature of elastic_plastic_impact: e, x_max, F_max, x_p, compression and
/// contact time agree within 8.5e-13 relative with the integration (V/V_y in [0.5, 300]) and
/// within 1e-13 with the quadrature (V/V_y in [0.3, 1e4]).
class ThorntonImpact {
public:
  /// Throws InvalidInput naming "mass", "radius", "contact_modulus", "yield_pressure" or
  /// "velocity" (V > 0 [m/s]).
  ThorntonImpact(const ThorntonParameters& parameters, double velocity);

  double yield_velocity() const { return yield_velocity_; }
  /// V / V_y [-].
  double velocity_ratio() const { return velocity_ / yield_velocity_; }
  const ThorntonContact& contact() const { return contact_; }
  /// e, x_max, F_max, x_p, times, rebound velocity, dissipated energy.
  ElasticPlasticImpactResponse response() const { return response_; }
  /// The unloading radius R_p [m].
  double unloading_radius() const { return contact_.unloading_radius(response_.approach_max); }

private:
  ThorntonParameters parameters_;
  double velocity_;
  ThorntonContact contact_;
  double yield_velocity_;
  ElasticPlasticImpactResponse response_;
};

/// Thornton's restitution in the form quoted from the paper (its Eq. for e, as reproduced in
/// later reviews), with r = V_y / V in (0, 1]:
///   e = sqrt(6 sqrt(3) / 5) sqrt(1 - r^2 / 6) (r / (r + 2 sqrt(6/5 - r^2/5)))^(1/4).
/// It is algebraically identical to r (1 + 3 delta/2) (1 + delta)^(-1/4) above (shown to
/// 1e-15 in the tests), which is how the quoted form is confirmed here. r >= 1 gives 1.
/// Throws InvalidInput("velocity_ratio") for r <= 0 or non-finite r.
double thornton_restitution_formula(double yield_velocity_ratio);

} // namespace impact::reduced
