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
/// There is no closed form. For a spring that is Hertz's c x^(3/2) below its first breakpoint
/// (loading_power_law; every spring of the library) the impact m x'' = -F, x(0) = 0,
/// x'(0) = V is integrated in the square root of the spring's stretch, sigma = sqrt(x) while
/// loading and sqrt(x - x_r) while unloading, with dt = 2 sigma dtau: the equations then
/// have an analytic right-hand side (a polynomial on the Hertzian pieces), where in x and t
/// the x^(1/2) factors make the solution non-analytic at first contact and at separation.
/// Fehlberg 7(8) (Boost.Odeint) takes about 20 steps at 1e-10 (Cash-Karp in x and t took 90).
/// Each piece ends at an event located exactly, where the step ends: the breakpoint (the
/// spring's fit takes over), x' = 0 (x_max: the unloading branch of that x_max takes over,
/// in its own sigma) and F = 0 (separation; a contact cannot pull, so the approach at
/// separation is above x_r), or x = 0 if x_r < 0. Above the breakpoint F_L and dF_L/dx come
/// from loading_force_and_stiffness_from_table (Jackson-Green and Ghaednia: the octave
/// table's series, within 2.2e-15 and 2.4e-13 of the fit). Other springs: integrate_impact
/// (Cash-Karp in x and t) with the law switched at x_max (switched_impact.hpp).
///
/// Accuracy (tests/reduced/test_kuwabara_kono_elastic_plastic.cpp, against an independent
/// long-double Runge-Kutta-Fehlberg 7(8) integration with exact event location; Jackson-Green
/// and Ghaednia springs, V/V_y 0.5 to 100: worst 1.2e-10 at 1e-10 and 4.5e-12 (t(F_max); the
/// other figures 1.5e-13) at 1e-13; Hertz and Thornton springs, V/V_y in [0.5, 100], A in [1e-9, 2e-6] s): e, x_max, F_max, t(F_max)
/// and the contact time within 1e-8 relative at the default tolerance 1e-10 (worst measured
/// 2.1e-10; 3.7e-9 with the former Cash-Karp integration in x and t) and within 1e-10 at 1e-13
/// (worst 1.1e-12, the reference's own error at Thornton's yield kink; 6.3e-12 before). Over
/// 234 impacts (V = 0.05 to 29 m/s, A = 1e-9, 1e-7, 2e-6 s, tolerances 1e-10, 1e-12, 1e-13)
/// every figure was within 30 x the tolerance of the same reference but Thornton at
/// A = 2e-6 s and 1e-13 (1.2e-11, again the reference's: 1.6e-13 with ten times its steps).
/// Cost (bench-reduced, steel ball R = 10 mm at 1.4 m/s, A = 1e-7 s, CPU time on the shared
/// 2-core machine, 2026-12-04): 7.0, 7.6, 19.6 and 19.3 us on Hertz, Thornton, Jackson-Green
/// and Ghaednia springs (25.5-36.5 us and 91-151 us with Cash-Karp in x and t), the last two
/// with the spring's octave table built (a fresh spring first builds the octaves it reaches);
/// the fitted springs' figures vary from 19 to 24 us with the machine's other jobs.

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

/// One impact: mass m > 0 [kg], velocity V > 0 [m/s], A >= 0 [s], `relative_tolerance` in
/// [1e-14, 1e-3] (the local error tolerance of the embedded pair on the scaled state; the
/// figures' accuracy is in the Accuracy paragraph above). approach_at_separation of the
/// result is where F returned to 0; steps counts the accepted steps. Throws InvalidInput
/// naming "mass", "velocity", "dissipative_constant" or "relative_tolerance";
/// ContactDoesNotEnd if the body has not separated after 1e5 characteristic times or 1e6
/// steps.
OdeImpactResult kuwabara_kono_elastic_plastic_impact(double mass, double velocity,
                                                     const ElasticPlasticContact& spring,
                                                     double dissipative_constant,
                                                     double relative_tolerance = 1e-10);

/// The force history of the same impact at `points` >= 2 instants equally spaced from first
/// contact to separation, each re-stepped from the start of the step that holds it (the
/// integration's accuracy; no interpolation). Throws as the impact, and InvalidInput naming
/// "points" for points < 2.
std::vector<ImpactSample> kuwabara_kono_elastic_plastic_history(double mass, double velocity,
                                                                const ElasticPlasticContact& spring,
                                                                double dissipative_constant,
                                                                std::size_t points,
                                                                double relative_tolerance = 1e-10);

} // namespace impact::reduced
