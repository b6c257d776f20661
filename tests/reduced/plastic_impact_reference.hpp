#pragma once
// An independent reference for rate-independent elastic-plastic impacts: the equation of
// motion m x'' = -F(x) integrated in long double by the fixed-step Runge-Kutta-Fehlberg 7(8)
// stepper of Boost.Odeint (its 8th-order solution), with every event (a loading breakpoint,
// x' = 0, separation) located exactly by re-taking the step that contains it with a
// bisected length. Nothing here uses the energy integrals or the quadratures of the library.

#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace impact::testing {

struct PlasticReferenceLaw {
  std::function<long double(long double)> loading; // F_L(x)
  std::vector<long double> breakpoints;            // where F_L or F_L' jumps
  // The unloading force F_U(x) from x_max and the approach where the bodies part.
  std::function<long double(long double approach, long double approach_max)> unloading;
  std::function<long double(long double approach_max)> separation_approach;
};

struct PlasticReferenceResult {
  long double approach_max;
  long double compression_time;
  long double contact_time;
  long double rebound_velocity; // negative
  long double separation_approach;
};

namespace detail {

using State = std::array<long double, 2>; // x, x'

// Integrates from `state` at `time` with step h under `force` until event(state) changes sign
// from positive; returns the state and time exactly at the event.
inline void integrate_to_event(State& state, long double& time, long double mass, long double h,
                               const std::function<long double(long double)>& force,
                               const std::function<long double(const State&)>& event) {
  boost::numeric::odeint::runge_kutta_fehlberg78<State, long double> stepper;
  const auto system = [&](const State& y, State& dydt, long double) {
    dydt[0] = y[1];
    dydt[1] = -force(y[0]) / mass;
  };
  const auto step = [&](const State& from, long double length) {
    State to = from;
    stepper.do_step(system, to, 0.0L, length);
    return to;
  };
  for (long count = 0; count < 100000000; ++count) {
    const State next = step(state, h);
    if (event(next) > 0) {
      state = next;
      time += h;
      continue;
    }
    long double lower = 0, upper = h; // event(step(lower)) > 0 >= event(step(upper))
    for (int i = 0; i < 200 && upper - lower > 1e-24L * h; ++i) {
      const long double middle = 0.5L * (lower + upper);
      (event(step(state, middle)) > 0 ? lower : upper) = middle;
    }
    state = step(state, upper);
    time += upper;
    return;
  }
  throw std::runtime_error("reference integration: event never reached");
}

} // namespace detail

/// `steps` per characteristic time x_scale / V of the impact.
inline PlasticReferenceResult integrate_plastic_reference(long double mass, long double velocity,
                                                          const PlasticReferenceLaw& law,
                                                          long double approach_scale,
                                                          long steps = 4000) {
  const long double h = approach_scale / velocity / steps;
  detail::State state{0.0L, velocity};
  long double time = 0;
  // Compression, stopping exactly at each breakpoint passed on the way. Up to a breakpoint the
  // force is that of the branch below it, held at its end value beyond: the Runge-Kutta
  // stages of the step that lands on the breakpoint may reach slightly past it, and a jump
  // of the force seen there would make the result depend on where the breakpoint falls in
  // the step grid (1e-10 for a change of h in its last digit, measured on Jackson-Green's
  // 0.5 % jump).
  for (const long double breakpoint : law.breakpoints) {
    const auto below = [&](long double x) { return law.loading(std::min(x, breakpoint)); };
    detail::integrate_to_event(state, time, mass, h, below, [&](const detail::State& y) {
      return std::min(breakpoint - y[0], y[1]);
    });
    if (state[1] <= 0) break; // at rest before this breakpoint
  }
  if (state[1] > 0)
    detail::integrate_to_event(state, time, mass, h, law.loading,
                               [](const detail::State& y) { return y[1]; });
  PlasticReferenceResult result{};
  result.approach_max = state[0];
  result.compression_time = time;
  state[1] = 0; // exactly at rest at x_max
  const long double approach_max = result.approach_max;
  const long double separation = law.separation_approach(approach_max);
  detail::integrate_to_event(
      state, time, mass, h, [&](long double x) { return law.unloading(x, approach_max); },
      [&](const detail::State& y) { return y[0] - separation; });
  result.contact_time = time;
  result.rebound_velocity = state[1];
  result.separation_approach = separation;
  return result;
}

} // namespace impact::testing
