#pragma once
// The reference integration of the elastic-plastic impact tests (Hunt-Crossley and
// Kuwabara-Kono damping on the library's springs): m x'' = -F(x, x') in long double with the
// fixed-step Runge-Kutta-Fehlberg 7(8) stepper of Boost.Odeint, independent of the library's
// integrators.
//
// The steps grow geometrically (doubling) from 1e-12 of the nominal step at first contact,
// where a damping term ~ x^(1/2) x' makes the solution non-smooth (x ~ V t - k t^(5/2)):
// fixed steps there would limit the reference to about 1e-10. Each stretch ends at an event,
// the first root of a function of the state, located by bisecting the step that holds it
// (to 1e-24 of the step): a force peak, x' = 0, a breakpoint of the spring, separation.

#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include <algorithm>
#include <array>
#include <functional>

namespace impact::test_reference {

class GradedEventIntegration {
public:
  using Real = long double;
  using State = std::array<Real, 2>; // x [m], x' [m/s]
  using Function = std::function<Real(const State&)>;

  /// The force law F(x, x') [N] (read at every stage: a law that switches branch between
  /// stretches may capture the branch by reference), mass m [kg], impact velocity V [m/s]
  /// and the nominal step h [s].
  GradedEventIntegration(Function force, Real mass, Real velocity, Real step)
      : force_(std::move(force)), mass_(mass), step_(step), state{Real(0), velocity} {}

  /// Steps on until `event` of the next step's end is no longer > 0, and ends the stretch
  /// at its root.
  void run_to(const Function& event) {
    for (long count = 0; count < 100000000; ++count) {
      const Real length = step_ * std::min(Real(1), grading_);
      grading_ *= 2;
      const State next = step(state, length);
      if (event(next) > 0) {
        state = next;
        time += length;
        continue;
      }
      Real lower = 0, upper = length;
      for (int i = 0; i < 200 && upper - lower > 1e-24L * length; ++i) {
        const Real middle = (lower + upper) / 2;
        (event(step(state, middle)) > 0 ? lower : upper) = middle;
      }
      state = step(state, upper);
      time += upper;
      return;
    }
  }

private:
  State step(const State& from, Real length) const {
    State to = from;
    const auto system = [this](const State& y, State& dydt, Real) {
      dydt[0] = y[1];
      dydt[1] = -force_(y) / mass_;
    };
    stepper_.do_step(system, to, Real(0), length);
    return to;
  }

  Function force_;
  Real mass_, step_;
  Real grading_ = 1e-12L;
  mutable boost::numeric::odeint::runge_kutta_fehlberg78<State, Real> stepper_;

public:
  State state;   ///< the state at the end of the last stretch (a test may move it)
  Real time = 0; ///< the time since first contact [s]
};

} // namespace impact::test_reference
