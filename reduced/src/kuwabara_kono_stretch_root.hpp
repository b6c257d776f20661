#pragma once
// The Kuwabara-Kono impact on an elastic-plastic spring (kuwabara_kono_elastic_plastic.hpp)
// integrated in the square root of the spring's stretch, for a spring that is Hertz's
// c x^(3/2) from x = 0 to its first breakpoint (loading_power_law: every spring of the
// library). Internal to the library.
//
// Why: in x and t the law F = c x^(1/2) (x + (3/2) A x') makes the solution non-analytic
// where the stretch vanishes (x ~ V t - k t^(5/2) at first contact; likewise the unloading
// branch k_u s^(1/2) (s + (3/2) A x'), s = x - x_r, near separation), and the law has a kink
// at the spring's breakpoint (yield) and at x_max (loading to unloading stiffness). An
// explicit Runge-Kutta pair then needs small steps at each of them and cannot use a high
// order. With
//     sigma = sqrt(s)   (s = x while loading, x - x_r while unloading),   dt = 2 sigma dtau,
// the equations read
//     d sigma/dtau = x',   dx'/dtau = -2 sigma F / m,   dt/dtau = 2 sigma,
// and on the Hertzian pieces F = c sigma (sigma^2 + (3/2) A x') is a polynomial: the
// right-hand side is analytic (above the breakpoint F is the spring's smooth fit and sigma is
// bounded away from 0). Each piece ends at an event located exactly (the breakpoint
// sigma^2 = x_b, the maximum x' = 0, the separation F = 0): the step ends there and the next
// piece starts from it in its own variables, so that no step holds a kink. Fehlberg 7(8)'s
// error estimate is then honest (event_stepping.hpp): about 20 steps per impact at 1e-10,
// against 90 Cash-Karp steps in x and t.

#include "impact_reduced/elastic_plastic_impact.hpp"
#include "impact_reduced/impact_ode.hpp"

#include <cstddef>
#include <vector>

namespace impact::reduced::detail {

/// Whether the spring's loading is c x^(3/2) from x = 0 to its first breakpoint (or
/// everywhere), the condition of the two functions below.
bool has_hertz_start(const ElasticPlasticContact& spring);

/// The impact of kuwabara_kono_elastic_plastic_impact (arguments validated there except the
/// tolerance: InvalidInput naming "relative_tolerance" outside [1e-14, 1e-3]).
OdeImpactResult kuwabara_kono_stretch_root_impact(double mass, double velocity,
                                                  const ElasticPlasticContact& spring,
                                                  double dissipative_constant,
                                                  double relative_tolerance);

/// Its history at `points` >= 2 equally spaced instants, each sample re-stepped from the
/// start of the step that holds it (the integration's accuracy, no interpolation).
std::vector<ImpactSample> kuwabara_kono_stretch_root_history(double mass, double velocity,
                                                             const ElasticPlasticContact& spring,
                                                             double dissipative_constant,
                                                             std::size_t points,
                                                             double relative_tolerance);

} // namespace impact::reduced::detail
