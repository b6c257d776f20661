#pragma once
/// @file
/// Kuwabara-Kono damping on an elastic-plastic spring: the viscous force of a viscoelastic
/// contact scaled by the current contact stiffness of the branch,
///     F = F_s(x) + A k_t(x) x',   k_t = dF_s/dx,
/// with F_s the loading branch F_L of an ElasticPlasticContact while the approach grows and
/// its Hertzian unloading branch F_U(x) = k_u (x - x_r)^(3/2) from the maximum approach on
/// (k_t = (3/2) k_u (x - x_r)^(1/2) there). A [s] is the dissipative constant. On a Hertz
/// spring k_t = (3/2) c x^(1/2) = 2 E* a, so below yield this is exactly the library's
/// Kuwabara-Kono law F = c x^(3/2) + (3/2) A c x^(1/2) x' (comparison_laws.hpp; Kuwabara &
/// Kono, Jpn. J. Appl. Phys. 26 (1987) 1230; Brilliantov et al., Phys. Rev. E 53 (1996)
/// 5382), in the form of LAMMPS's granular `damping viscoelastic` (damping force
/// proportional to the contact radius, i.e. to 2 E* a = dF_Hertz/dx).
///
/// The material's A for two Kelvin-Voigt bodies follows from their retardation times (the
/// calibration's "Kuwabara-Kono from the material", postprocess/); the law itself takes A.
///
/// There is no closed form: the impact m x'' = -F, x(0) = 0, x'(0) = V is integrated by
/// integrate_impact (impact_ode.hpp) with the contact ending where F returns to 0
/// (ContactEnd::zero_force: a contact cannot pull; the approach at separation is then
/// above x_r). The unloading branch depends on x_max: the impact is integrated once, on the
/// loading branch until the step in which x' = 0 (an event the integrator locates exactly),
/// where the branch of that x_max takes over and the step is re-taken from its start with
/// it, which is the integration of the switched law from t = 0.
///
/// Accuracy (tests/reduced/test_kuwabara_kono_elastic_plastic.cpp, against an independent
/// long-double Runge-Kutta-Fehlberg 7(8) integration with exact event location, Hertz and
/// Thornton springs, V/V_y in [0.5, 100], A in [1e-9, 2e-6] s): e, x_max, F_max and the
/// contact time within 1e-8 relative at the default tolerance 1e-10 (worst measured 3.7e-9)
/// and within 1e-10 at 1e-13 (worst 6.3e-12); the x^(1/2) factors cost the integrator about
/// 30 x its tolerance (impact_ode.hpp).

#include "impact_reduced/elastic_plastic_impact.hpp"
#include "impact_reduced/impact_ode.hpp"

#include <cstddef>
#include <vector>

namespace impact::reduced {

/// The contact force of the law at (x, x') on the branch of an impact whose maximum approach
/// is `approach_max` (x' >= 0 or approach_max <= 0: the loading branch). For the ODE and for
/// simulators that carry x_max as their history variable. Tension is not clipped here.
double kuwabara_kono_elastic_plastic_force(const ElasticPlasticContact& spring,
                                           double dissipative_constant, double approach,
                                           double approach_rate, double approach_max);

/// One impact: mass m > 0 [kg], velocity V > 0 [m/s], A >= 0 [s], `relative_tolerance` of
/// integrate_impact in [1e-14, 1e-3]. approach_at_separation of the result is where F
/// returned to 0. Throws InvalidInput naming "mass", "velocity", "dissipative_constant" or
/// "relative_tolerance"; ContactDoesNotEnd as integrate_impact.
OdeImpactResult kuwabara_kono_elastic_plastic_impact(double mass, double velocity,
                                                     const ElasticPlasticContact& spring,
                                                     double dissipative_constant,
                                                     double relative_tolerance = 1e-10);

/// The force history of the same impact at `points` >= 2 instants equally spaced from first
/// contact to separation (integrate_impact_history).
std::vector<ImpactSample> kuwabara_kono_elastic_plastic_history(double mass, double velocity,
                                                                const ElasticPlasticContact& spring,
                                                                double dissipative_constant,
                                                                std::size_t points,
                                                                double relative_tolerance = 1e-10);

} // namespace impact::reduced
