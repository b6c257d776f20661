#pragma once
/// @file
/// Thornton's elastic-plastic impact as LIGGGHTS 3.8 implements it: the normal model
/// `thornton_ning` (CFDEMproject/LIGGGHTS-PUBLIC, src/normal_model_thornton_ning.h, release
/// 3.8.0) with zero surface energy, the model of the DEM export (postprocess, impact-export).
/// Read in that source; LIGGGHTS has no documentation page for the model.
///
/// LIGGGHTS integrates the force in increments of the overlap, dF = (dF/dx) dx, with
///   - loading below yield: dF/dx = 2 E* a, a = sqrt(R x) (Hertz: F = (4/3) E* sqrt(R) x^(3/2));
///   - loading once a >= a_y (a_y = coefficientYieldRatio x particle radius):
///     dF/dx = 2 E* a_y, the linear plastic branch of Thornton (1997) with p_y = 2 E* a_y / (pi R)
///     (thornton.hpp: dF/dx = pi p_y R);
///   - unloading (x < x_max): dF/dx = 2 E* a on an effective radius that it scales by
///     F_L(F_max) / F_max, which is 1 without surface energy: the radius stays R and a = sqrt(R x)
///     is taken at the total overlap x. Integrated, the unloading branch is the Hertz curve of R
///     moved down to pass through the peak,
///       F_U(x) = F* - (4/3) E* sqrt(R) (x_max^(3/2) - x^(3/2)),
///     not Thornton's Hertz curve on the enlarged radius R_p about the permanent approach
///     (thornton.hpp) and not a Hertz curve on R about a permanent approach either;
///   - the force is clipped at 0 (no adhesion): the bodies part at x_s with F_U(x_s) = 0,
///     x_s = (x_max^(3/2) - F* / ((4/3) E* sqrt(R)))^(2/3) > 0.
/// The loading is Thornton's, so x_max, F_max and the compression time are those of
/// ThorntonImpact. The rebound energy is the work of F_U from x_max to x_s, in closed form:
///   W_U = (F* - k x_max^(3/2)) (x_max - x_s) + (2/5) k (x_max^(5/2) - x_s^(5/2)),  k = (4/3) E* sqrt(R),
/// e = sqrt(2 W_U / (m V^2)); the unloading time is integral dx / |x'| from x_max to x_s,
/// evaluated by Gauss-Kronrod quadrature in u = sqrt(x_max - x), in which the integrand is
/// smooth. For V <= V_y the impact is Hertz's (e = 1), as in ThorntonImpact.
///
/// Accuracy (tests/reduced/test_liggghts_thornton.cpp, against an independent long-double
/// Runge-Kutta-Fehlberg 7(8) integration of m x'' = -F with the law written again there):
/// e, x_max, x_s, compression and contact time within 1e-10 relative for V/V_y in [0.5, 300]
/// (measured worst 8.5e-13).

#include "impact_reduced/elastic_plastic_impact.hpp"
#include "impact_reduced/thornton.hpp"

namespace impact::reduced {

/// One impact under LIGGGHTS' thornton_ning law without surface energy. SI units.
class LiggghtsThorntonImpact {
public:
  /// Throws InvalidInput naming "mass", "radius", "contact_modulus", "yield_pressure" or
  /// "velocity" (V > 0 [m/s]).
  LiggghtsThorntonImpact(const ThorntonParameters& parameters, double velocity);

  double yield_velocity() const { return thornton_.yield_velocity(); }
  double velocity_ratio() const { return thornton_.velocity_ratio(); }
  /// The loading law (Thornton's, shared with ThorntonImpact).
  const ThorntonContact& contact() const { return thornton_.contact(); }
  /// e, x_max, F_max, the separation approach x_s (as residual_approach), the times, the
  /// rebound velocity and the dissipated energy.
  ElasticPlasticImpactResponse response() const { return response_; }
  /// F_U(x) [N] on the unloading branch of this impact, for x_s <= x <= x_max (clipped at 0
  /// below x_s). Throws InvalidInput("approach") outside [0, x_max].
  double unloading_force(double approach) const;

private:
  ThorntonImpact thornton_;
  ElasticPlasticImpactResponse response_;
};

/// LIGGGHTS' coefficientYieldRatio a_y / R_i for a sphere of radius R_i on a flat wall (the
/// effective radius is then R_i), so that its limiting pressure 2 E* a_y / (pi R) is p_y:
/// a_y = pi p_y R / (2 E*) (Thornton's limiting contact radius), hence the ratio
/// pi p_y / (2 E*) [-]. LIGGGHTS accepts ratios in [0, 1]. Throws InvalidInput naming
/// "yield_pressure" or "contact_modulus" (> 0, finite), or "yield_pressure" when the ratio
/// exceeds 1 (p_y > 2 E* / pi).
double liggghts_yield_ratio(double yield_pressure, double contact_modulus);

} // namespace impact::reduced
