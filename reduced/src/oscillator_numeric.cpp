// Olshanskiy oscillator: the reference numerical integration with event location of the
// extremes (Boost.Odeint, Cash-Karp 5(4), TOMS 748 on the step length).
//
// Cash-Karp rather than Fehlberg 7(8): for a non-integer power the force |X|^v X is not
// smooth at X = 0, and the error estimate of Fehlberg 7(8) (built from four stages only)
// misses the resulting error there (3e-11 per half-cycle at v = 1.5 against 1e-12 here).
// Dormand-Prince 5(4) would do as well, but its controlled try_step(in, out) does not
// compile in Boost 1.74.
//
// The equation is odd (x -> -x maps solutions to solutions), so every half-cycle is the same
// problem in scaled variables: start at X = -1, X' = 0 and run to the next extreme X' = 0,
// where X = x / a_{i-1}, tau = sqrt(c1/m) t and
//     X'' + 2 zeta X' + X + gamma_i |X|^v X = 0,  2 zeta = k / sqrt(c1 m),
//     gamma_i = c2 a_{i-1}^v / c1.
// The half-cycle gives a_i / a_{i-1} = X(tau_i) and t_i - t_{i-1} = tau_i / sqrt(c1/m).
// Restarting at each extreme keeps the tolerances relative to the current amplitude, so the
// accuracy does not degrade, nor the state underflow, as the oscillation decays.

#include "impact_reduced/oscillator.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::reduced {

namespace {

// Scaled deflection X and velocity dX/dtau. A vector rather than std::array: Odeint copies
// default-constructed steppers, whose std::array buffers would be copied uninitialized.
using State = std::vector<double>;

// Relative tolerance of the step control, on the scaled state (error measured against
// |X| + dtau |dX/dtau| per component, which never vanishes together). The absolute
// tolerance is negligible so that a heavily damped half-cycle, which ends at a small X,
// keeps its relative accuracy.
constexpr double tolerance = 1e-13;
constexpr double absolute_tolerance = 1e-25;
constexpr long max_steps_per_half_cycle = 1000000;

struct HalfCycle {
  double duration; // tau_i - tau_{i-1}, scaled time
  double ratio;    // a_i / a_{i-1}
};

struct ScaledEquation {
  double two_zeta;
  double gamma;
  double power;
  void operator()(const State& s, State& ds, double /*tau*/) const {
    ds[0] = s[1];
    ds[1] = -two_zeta * s[1] - s[0] - gamma * std::pow(std::abs(s[0]), power) * s[0];
  }
};

namespace odeint = boost::numeric::odeint;
using ErrorStepper = odeint::runge_kutta_cash_karp54<State>;
using ControlledStepper = odeint::controlled_runge_kutta<ErrorStepper>;

// Advances (state, tau) with step control until state[component] reaches 0 from above
// (from below if `sign` is -1) and stops exactly there: the step over which the component
// changes sign is repeated from its start with the step length that TOMS 748 finds for
// state[component] = 0 to machine precision. On return state[component] is set to 0.
void advance_to_event(const ScaledEquation& equation, State& state, double& tau,
                      std::size_t component, double sign, double max_step) {
  ControlledStepper stepper(ControlledStepper::error_checker_type(absolute_tolerance, tolerance));
  ErrorStepper single_step;
  double step = max_step / 16;
  for (long n = 0; n < max_steps_per_half_cycle; ++n) {
    step = std::min(step, max_step);
    State next(2);
    double next_tau = tau;
    const double tried = step;
    if (stepper.try_step(equation, state, next_tau, next, step) == odeint::fail) continue;
    if (sign * next[component] > 0) { // not there yet
      state = next;
      tau = next_tau;
      continue;
    }
    auto component_after = [&](double h) {
      State end(2);
      single_step.do_step(equation, state, tau, end, h);
      return sign * end[component];
    };
    double event_step = tried;
    if (sign * next[component] < 0) {
      std::uintmax_t iterations = 100;
      const auto bracket =
          boost::math::tools::toms748_solve(component_after, 0.0, tried, sign * state[component],
                                            sign * next[component],
                                            boost::math::tools::eps_tolerance<double>(),
                                            iterations);
      event_step =
          std::abs(component_after(bracket.first)) < std::abs(component_after(bracket.second))
              ? bracket.first
              : bracket.second;
    }
    single_step.do_step(equation, state, tau, next, event_step);
    state = next;
    state[component] = 0.0;
    tau += event_step;
    return;
  }
  throw std::runtime_error("oscillator: no extreme found within " +
                           std::to_string(max_steps_per_half_cycle) + " integration steps");
}

// One half-cycle from X = -1, X' = 0 to the next extreme. It stops at the zero crossing
// X = 0 on the way: there the force |X|^v X is not smooth, and an integration step across
// it would lose the order of the method (and the error estimate its reliability).
HalfCycle integrate_half_cycle(const ScaledEquation& equation) {
  // The stiffness on |X| <= 1 is at most 1 + max(gamma, 0): a step never exceeds a sixteenth
  // of the shortest half-period, so that it cannot jump over an event.
  const double max_step =
      boost::math::constants::pi<double>() / std::sqrt(1 + std::max(equation.gamma, 0.0)) / 16;
  State state{-1.0, 0.0};
  double tau = 0.0;
  advance_to_event(equation, state, tau, 0, -1.0, max_step); // X rises to 0
  advance_to_event(equation, state, tau, 1, 1.0, max_step);  // X' falls to 0
  return {tau, std::abs(state[0])};
}

} // namespace

std::vector<OscillatorExtreme> free_decay_extremes(const PowerLawOscillator& o, int count) {
  validate_oscillator(o);
  if (count < 1 || count > max_extreme_count)
    throw InvalidInput("count", "count must be a whole number in [1, " +
                                    std::to_string(max_extreme_count) + "] (got " +
                                    std::to_string(count) + ")");
  const double linear_frequency = std::sqrt(o.linear_stiffness / o.mass);
  ScaledEquation equation{o.viscous_damping / std::sqrt(o.linear_stiffness * o.mass), 0.0, o.power};
  std::vector<OscillatorExtreme> extremes;
  extremes.reserve(count);
  double amplitude = o.initial_amplitude;
  double tau = 0.0;
  for (int i = 1; i <= count; ++i) {
    equation.gamma = o.nonlinear_stiffness * std::pow(amplitude, o.power) / o.linear_stiffness;
    const HalfCycle half_cycle = integrate_half_cycle(equation);
    tau += half_cycle.duration;
    amplitude *= half_cycle.ratio;
    extremes.push_back({i, tau / linear_frequency, amplitude});
  }
  return extremes;
}

} // namespace impact::reduced
