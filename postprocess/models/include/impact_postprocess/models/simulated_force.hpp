#pragma once
// The contact force of a reduced-model impact at given times, for fitting to a measured
// force history: the library's reference integration (integrate_impact_history), sampled
// uniformly, and the state interpolated between samples by cubic Hermite polynomials
// (x with x', x' with x'' = -F/m), the force then evaluated from the law. With a few times
// more samples than measured points the interpolation error is far below the integration
// tolerance.

#include "impact_postprocess/models/damped_plastic_models.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/elastic_plastic_impact.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <cstddef>
#include <vector>

namespace impact::postprocess::detail {

/// F at each time in `times` [s since first contact]; 0 before contact and after separation
/// (`end`: the law's end of contact). A force that jumps to 0 at separation (F(0, x') != 0, the
/// linear dashpot) is averaged over the cell of the measured time that holds the separation,
/// so that the sampled force is continuous in the law's parameters.
/// Returns false if the impact cannot be integrated (the law holds the body, non-finite
/// force, invalid parameters).
bool simulate_force(const reduced::ContactForceLaw& law, double mass, double velocity,
                    const std::vector<double>& times, std::size_t points, double tolerance,
                    reduced::ContactEnd end, double* force);

/// The same for the Hunt-Crossley law F = c x^n (1 + b x') (`law`, of `setup`), sampled by
/// the closed-form history (HuntCrossleyImpact::history, about 1e-14 accurate) instead of
/// the integration: no tolerance, and faster at the same number of samples.
bool simulate_hunt_crossley_force(const reduced::ContactForceLaw& law,
                                  const reduced::ContactSetup& setup, double damping,
                                  double velocity, const std::vector<double>& times,
                                  std::size_t points, double* force);

/// The relative tolerance at which to integrate the compression under the elastic-plastic
/// loading curve of `contact`: `tolerance` (the fits' 1e-10) where the curve is continuous,
/// 1e-13 where it jumps at one of its breakpoints (by more than 1e-6 of the force there;
/// Jackson–Green's fit lies 0.5 % above Hertz at 1.9 omega_c). The adaptive stepper steps
/// across such a jump wherever it falls in a step, and the local error it leaves there
/// changes with the law's parameters by jumps, not smoothly. Measured on the plastic study's
/// Jackson–Green fit without V = 5 m/s (the cost of its force residuals against ln c in
/// steps of 2e-7): the second differences scatter by 4e-9 at 1e-10, against a curvature of
/// 6e-12, so that the fit's finite-difference Jacobian (step 1e-6) is noise near the minimum
/// and Levenberg–Marquardt crept for 100 iterations without converging; by 2e-11 at 1e-13,
/// where all seven fits of that law converge in 12 to 25 iterations. Thornton's continuous
/// curve scatters by 3e-14 already at 1e-10.
double compression_tolerance(const reduced::ElasticPlasticContact& contact, double tolerance);

/// The same for a rate-independent elastic-plastic law: the compression integrated
/// (integrate_impact_history at compression_tolerance) under the loading curve up to
/// the maximum approach of elastic_plastic_impact, the restitution as the second half of the
/// Hertz impact of the unloading branch (stiffness k_u, shifted by the permanent approach) at
/// the rebound speed, integrated at `tolerance` (Hertz's smooth law).
bool simulate_plastic_force(const reduced::ElasticPlasticContact& contact, double mass,
                            double velocity, const std::vector<double>& times, std::size_t points,
                            double tolerance, double* force);

/// The same for a damped elastic-plastic impact (damped_plastic_models.hpp): its closed-form
/// history (HuntCrossleyElasticPlasticImpact::history), the force of the branch of the
/// interpolated rate (loading while x' > 0).
bool simulate_damped_plastic_force(const DampedPlasticImpact& impact, double mass,
                                   const std::vector<double>& times, std::size_t points,
                                   double* force);

} // namespace impact::postprocess::detail
