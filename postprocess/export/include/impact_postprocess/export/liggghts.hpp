#pragma once
/// @file
/// The DEM export: Thornton's elastic-plastic law as LIGGGHTS 3.8's normal model
/// `thornton_ning` on a flat wall (fix wall/gran ... primitive), read in LIGGGHTS' source
/// (src/normal_model_thornton_ning.h; the model has no documentation page). The law LIGGGHTS
/// integrates is reduced::LiggghtsThorntonImpact (Thornton's loading; its own unloading
/// branch, see liggghts_thornton.hpp and postprocess/README.md, "Exports").

#include "impact_postprocess/export/simulator_export.hpp"
#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <optional>
#include <vector>

namespace impact::postprocess {

/// LIGGGHTS' input for the sphere on the wall.
///   - youngsModulus, poissonsRatio per atom type (1: the sphere, 2: the wall), from which
///     LIGGGHTS forms E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2). A rigid plate cannot be
///     given a finite modulus; then both types get the one fictitious material E = 2 E*
///     (1 - nu_s^2), nu_s, which gives the same E*.
///   - coefficientYieldRatio = a_y / R: LIGGGHTS yields when the contact radius sqrt(R x)
///     reaches a_y = ratio x R (R the particle's radius, the effective radius at a wall) and its
///     limiting pressure is 2 E* a_y / (pi R). Thornton's limiting contact radius
///     a_y = pi p_y R / (2 E*) gives ratio = pi p_y / (2 E*) (reduced::liggghts_yield_ratio).
///   - surfaceEnergy 0 (no adhesion: Thornton 1997, not Thornton & Ning 1998);
///   - density = m / ((4/3) pi R^3), so that LIGGGHTS' particle has the campaign's mass.
struct LiggghtsContact {
  double sphere_youngs_modulus; ///< Pa, atom type 1
  double sphere_poisson_ratio;
  double wall_youngs_modulus; ///< Pa, atom type 2 (the wall)
  double wall_poisson_ratio;
  double yield_ratio;    ///< coefficientYieldRatio a_y / R [-]
  double density;        ///< kg/m^3
  double yield_velocity; ///< V_y [m/s] of Thornton's law (reduced::yield_velocity)
};
LiggghtsContact liggghts_contact(const PlasticContact& contact, double mass, double radius);

/// (scenario_plastic_contact, the plastic contact of the runs: run/scenario_plastic_contact.hpp.)

/// The impact of Thornton's law as LIGGGHTS integrates it (reduced::LiggghtsThorntonImpact) and
/// as Thornton's paper states it (reduced::ThorntonImpact, unloading on R_p), at velocity V.
ImpactFigures liggghts_thornton_impact(const PlasticContact& contact, double mass, double radius,
                                       double velocity);
ImpactFigures thornton_impact(const PlasticContact& contact, double mass, double radius,
                              double velocity);

} // namespace impact::postprocess
