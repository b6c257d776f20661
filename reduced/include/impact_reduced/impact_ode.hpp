#pragma once
/// @file
/// Reference numerical integration of a body hitting a fixed obstacle under an arbitrary
/// contact force law:
///
///     m x'' = -F(x, x'),   x(0) = 0,  x'(0) = V > 0,   until x returns to 0.
///
/// `x` is the approach (indentation, m), `x'` its rate (m/s), `F` the contact force
/// (N, compressive positive). This is the tool for the laws that have no closed form
/// (the comparison laws) and the independent reference for the closed-form Hunt–Crossley
/// code.
///
/// Method: an adaptive embedded Runge–Kutta pair, Cash–Karp 5(4) (Boost.Odeint), on the
/// equation scaled by the impact's own length and time scales, with mixed
/// absolute/relative error control at `relative_tolerance` on the scaled state. The events
/// are located exactly, not by sampling: when the sign of an event function changes within
/// an accepted step, the step is re-taken from its start with a length found by a
/// bracketing root finder (TOMS 748) to machine precision. Events:
///   - x' = 0 (maximum approach, end of compression),
///   - x = 0 with x' < 0 (end of contact),
///   - dF/dt = 0 (maximum force), where dF/dt = grad F . (x', x'') is evaluated by a
///     fourth-order finite difference of F along the flow direction.
///
/// Accuracy (measured, tests/reduced/test_impact_ode.cpp): at the default tolerance 1e-10
/// the approach, velocities, times and forces are within about 2e-10 relative of the closed
/// forms of the linear oscillator, the elastic Hertz impact and Hunt–Crossley; at 1e-13
/// within 1.5e-12 (Hunt–Crossley restitution and x_max). Laws with x^(1/2) or x^(1/4) factors
/// (Kuwabara–Kono, Tsuji) or a kink (a no-tension clamp) converge more slowly: about
/// 30 x the tolerance at 1e-10, 2e-11 at 1e-13. The time of the force maximum carries in
/// addition the finite-difference error of dF/dt, about 1e-11 relative, and is bracketed to
/// 2^-39 of its step (1e-13 of the contact time: the difference's rounding makes dF/dt's sign
/// random closer to the root); the maximum itself, second order in that distance, is not
/// affected.
///
/// No Boost type appears in this header.

#include "impact_reduced/impact_figures.hpp"

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::reduced {

/// A contact force law F(approach, approach_rate): approach x in m (the integrator calls it
/// with x >= 0 only), approach_rate x' in m/s (positive while the bodies approach); returns
/// the force in N, compressive positive. It must be finite; tension (negative values) is
/// allowed and is integrated as given.
using ContactForceLaw = std::function<double(double approach, double approach_rate)>;

/// When the contact ends.
///   - zero_approach: when x returns to 0 (the law as written: a law that can pull, e.g.
///     Kuwabara–Kono or Tsuji, integrates its tension until x = 0);
///   - zero_force: at the first instant after the maximum approach where the force has fallen
///     to 0 (or x has returned to 0): the contact cannot pull, so the bodies separate there, as
///     in a finite-element contact with a non-negative pressure. The approach at separation
///     is then >= 0 (the surfaces have not recovered yet); the body leaves at constant speed.
/// For a law that stays compressive until x = 0 (Hunt–Crossley) both give the same impact.
enum class ContactEnd { zero_approach, zero_force };

/// The body never returns to x = 0 (the law sticks, or holds it for an unbounded time).
/// Thrown by integrate_impact after a bounded effort, with the state reached in the message.
class ContactDoesNotEnd : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The characteristic figures of one impact. SI units.
struct OdeImpactResult {
  double approach_max;           ///< m, maximum approach x_max (where x' = 0)
  double compression_time;       ///< s, time of approach_max
  double force_max;              ///< N, maximum of F along the impact (may be at t = 0)
  double time_force_max;         ///< s, time of force_max
  double contact_time;           ///< s, first return to x = 0
  double rebound_velocity;       ///< m/s, signed: x' at separation (negative, moving away)
  double restitution;            ///< -rebound_velocity / V
  double force_at_separation;    ///< N, F(0, x') at separation: zero for a physically sound law;
                                 ///< the linear Kelvin–Voigt law gives mu x' < 0 (tension), its
                                 ///< known defect
  std::size_t steps;             ///< accepted integration steps
  double approach_at_separation; ///< m, x at the end of contact: 0 for ContactEnd::zero_approach
  /// The figures by which impacts are compared (impact_figures.hpp).
  ImpactFigures figures() const {
    return {restitution, contact_time, force_max, time_force_max, approach_max};
  }
};

/// One point of the time history of an impact.
struct ImpactSample {
  double time;          ///< s
  double approach;      ///< m
  double approach_rate; ///< m/s
  double force;         ///< N
};

/// Integrates the impact of a body of `mass` (kg, > 0) arriving at `velocity` (m/s, > 0)
/// under `force` until the end of contact (`end`, see ContactEnd; the instant F = 0 is
/// located like the other events, to machine precision in the step).
///
/// `relative_tolerance` in [1e-14, 1e-3] (default 1e-10): local error tolerance of the
/// adaptive stepper on the scaled state. With 1e-13 the results agree with exact solutions
/// to about 1e-12 relative.
///
/// Throws InvalidInput (naming the parameter) for invalid mass, velocity or tolerance or an
/// empty law; std::runtime_error if the law returns a non-finite force or offers no
/// resistance to the approach; ContactDoesNotEnd if the body is not back at x = 0 within
/// 1e5 characteristic times of the impact (or 1e6 steps).
OdeImpactResult integrate_impact(double mass, double velocity, const ContactForceLaw& force,
                                 double relative_tolerance = 1e-10,
                                 ContactEnd end = ContactEnd::zero_approach);

/// The time history of the same integration: `points` (>= 2) samples uniformly spaced in
/// time from t = 0 to the end of contact (both included). Each sample is obtained by
/// re-taking the integration step that contains it from that step's start, so the samples
/// carry the accuracy of the integration itself (no interpolation): five force evaluations a
/// sample (the samples in one step share the derivative at its start), and no force-maximum
/// search. The last sample is the separation state (approach 0, or approach_at_separation
/// for ContactEnd::zero_force).
std::vector<ImpactSample> integrate_impact_history(double mass, double velocity,
                                                   const ContactForceLaw& force, std::size_t points,
                                                   double relative_tolerance = 1e-10,
                                                   ContactEnd end = ContactEnd::zero_approach);

} // namespace impact::reduced
