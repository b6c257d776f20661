#pragma once
// Adaptive Runge–Kutta integration with exact event location, shared by the library's
// reference integrators (impact_ode.cpp: a body on a fixed obstacle; thin_plate.cpp: a
// sphere on an infinite thin plate). Internal to the library.
//
// An embedded Runge–Kutta pair of Boost.Odeint (Cash–Karp 5(4) unless the caller chooses
// another) with mixed absolute/relative error control on a scaled state. An event (the sign change of a function of the state within an accepted step) is
// located by re-taking the step from its start with a length found by TOMS 748 to machine
// precision; a re-step never exceeds an accepted step, so it carries the step's accuracy.
// The accepted steps are kept, so that the trajectory can be sampled the same way.

#include <boost/math/tools/toms748_solve.hpp>
// GCC 12 flags the implicit copy of Odeint's stepper temporaries (uninitialised scratch
// arrays, overwritten before use) as -Wuninitialized; the warning is Boost's, not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace impact::reduced::detail {

/// A number with 17 significant digits, for error messages.
inline std::string describe(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

/// Cash-Karp 5(4), the default pair. Not Fehlberg 7(8) for a right-hand side that is not
/// smooth: its error estimate is a multiple of k1 + k11 - k12 - k13, which vanishes when the
/// right-hand side depends on time only (quadrature), and the start and end of a contact are
/// nearly that (x ~ V t, F ~ t^n with a fractional n): it accepted steps with 2e-8 error at a
/// 1e-13 tolerance on the Hertz impact. Cash-Karp's embedded estimate stays honest there
/// (1e-12 at 1e-13).
template <std::size_t N>
using CashKarp = boost::numeric::odeint::runge_kutta_cash_karp54<std::array<double, N>>;

/// Fehlberg 7(8), for a system written so that its right-hand side is analytic along the
/// whole trajectory (kuwabara_kono_stretch_root.hpp): there its estimate is honest and its
/// order takes a quarter of Cash-Karp's steps.
template <std::size_t N>
using Fehlberg78 = boost::numeric::odeint::runge_kutta_fehlberg78<std::array<double, N>>;

/// Integration of y' = f(y) (autonomous, scaled variables) step by step, with the accepted
/// steps recorded and events located exactly. `Method`: an Odeint error stepper on
/// std::array<double, N>; `SystemType`: f, callable as f(y, dydt) (a concrete type lets the
/// stages call it inline, without std::function's indirection).
template <std::size_t N, class Method = CashKarp<N>,
          class SystemType =
              std::function<void(const std::array<double, N>&, std::array<double, N>&)>>
class EventStepper {
public:
  using State = std::array<double, N>;
  using System = SystemType;

  /// One accepted step: scaled start time, start state, scaled length.
  struct Step {
    double start;
    State state;
    double length;
  };

  /// `tolerance`: local error tolerance, absolute = relative, on the scaled state.
  /// `time_unit` [s]: one scaled time unit, for the messages only.
  EventStepper(System system, double tolerance, double time_unit)
      : system_(std::move(system)),
        time_unit_(time_unit),
        controlled_(ErrorChecker(tolerance, tolerance, 1.0, 0.0)) {}

  /// One accepted step from (y, tau) with trial length dtau, all three updated (dtau to
  /// the controller's proposal for the next step). The step is recorded and returned.
  /// `start_rate`: f(y) if the caller has it (else evaluated here).
  /// Throws std::runtime_error if the tolerance cannot be met or the state is non-finite.
  const Step& step(State& y, double& tau, double& dtau, const State* start_rate = nullptr) {
    const auto system = [this](const State& s, State& d, double) { system_(s, d); };
    const State start = y;
    const double start_time = tau;
    // The derivative at the start, evaluated once for all the tries from it (the controller
    // would evaluate it again after each rejection).
    State rate;
    if (start_rate)
      rate = *start_rate;
    else
      system_(y, rate);
    std::size_t rejections = 0;
    while (controlled_.try_step(system, y, rate, tau, dtau) == boost::numeric::odeint::fail) {
      if (++rejections > rejection_limit || !(dtau > 1e-300))
        throw std::runtime_error("impact integration cannot satisfy the tolerance at t = " +
                                 describe(time_unit_ * tau) + " s");
    }
    for (const double component : y)
      if (!std::isfinite(component) || !std::isfinite(tau))
        throw std::runtime_error(
            "impact integration diverged at t = " + describe(time_unit_ * start_time) + " s");
    steps_.push_back({start_time, start, tau - start_time});
    return steps_.back();
  }

  /// Shortens the last recorded step to `length` (an event ends the integration in it).
  void truncate_last_step(double length) { steps_.back().length = length; }

  /// Forgets the last recorded step (it is to be re-taken, the system having changed).
  void drop_last_step() { steps_.pop_back(); }

  const std::vector<Step>& steps() const { return steps_; }

  /// The state reached from `start` after a single step of length h (no error control).
  State advance(const State& start, double h) const {
    if (h == 0) return start;
    return advance(start, rate_at(start), h);
  }

  /// The same with f(start) given: the re-steps from one start (an event's search, the
  /// samples in one step) share it, so that each costs five evaluations of f instead of six,
  /// with the same result to the last bit.
  State advance(const State& start, const State& start_rate, double h) const {
    if (h == 0) return start;
    State end;
    ErrorStepper stepper;
    stepper.do_step([this](const State& s, State& d, double) { system_(s, d); }, start, start_rate,
                    0.0, end, h);
    return end;
  }

  /// Root in [lower, h] of event(advance(start, s)), where the event changes sign between
  /// lower and h (or vanishes at h); returns h if it does not.
  template <class Event>
  double locate(const State& start, double lower, double h, Event event) const {
    const State start_rate = rate_at(start);
    return locate(start, start_rate, lower, h, event, event(advance(start, start_rate, lower)),
                  event(advance(start, start_rate, h)));
  }

  /// The same with the event's values at lower and h given.
  template <class Event>
  double locate(const State& start, double lower, double h, Event event, double at_lower,
                double at_upper) const {
    return locate(start, rate_at(start), lower, h, event, at_lower, at_upper);
  }

  /// The same with f(start) given. `bits`: the root is bracketed to 2^(1 - bits) relative
  /// (the default: to the last bit); fewer for an event whose own rounding noise is larger,
  /// where TOMS 748 would otherwise end in bisection steps that only resolve that noise.
  template <class Event>
  double locate(const State& start, const State& start_rate, double lower, double h, Event event,
                double at_lower, double at_upper,
                int bits = std::numeric_limits<double>::digits) const {
    if (at_upper == 0 || (at_upper > 0) == (at_lower > 0)) return h; // the sign change is at h
    if (at_lower == 0) return lower;
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve(
        [&](double s) { return event(advance(start, start_rate, s)); }, lower, h, at_lower,
        at_upper, boost::math::tools::eps_tolerance<double>(bits), iterations);
    return 0.5 * (root.first + root.second);
  }

  /// The state at scaled time tau in [0, end of the last step], by re-stepping from the
  /// start of the recorded step that contains it.
  State sample(double tau) const {
    const Step& step = step_at(tau);
    return advance(step.state, tau - step.start);
  }

  /// The recorded step that contains scaled time tau (the last that starts at or before it).
  const Step& step_at(double tau) const {
    const auto after = std::upper_bound(steps_.begin(), steps_.end(), tau,
                                        [](double t, const Step& s) { return t < s.start; });
    return *std::prev(after);
  }

  /// `points` >= 2 (scaled time, state) pairs equally spaced over [0, end_time], both ends
  /// included; the last is `end` (the located final state, not re-stepped). Each as sample(),
  /// the derivative at a step's start evaluated once for all the samples in that step.
  std::vector<std::pair<double, State>> sample_uniformly(std::size_t points, double end_time,
                                                         const State& end) const {
    std::vector<std::pair<double, State>> samples;
    samples.reserve(points);
    const Step* current = nullptr;
    State start_rate{};
    for (std::size_t i = 0; i + 1 < points; ++i) {
      const double tau = end_time * static_cast<double>(i) / static_cast<double>(points - 1);
      const Step& step = step_at(tau);
      if (&step != current) {
        current = &step;
        start_rate = rate_at(step.state);
      }
      samples.emplace_back(tau, advance(step.state, start_rate, tau - step.start));
    }
    samples.emplace_back(end_time, end);
    return samples;
  }

  /// The maximum of value(state) over the recorded trajectory ending in `end` (the state at
  /// the end of the last step): the largest node value, refined where rate(state) (the
  /// derivative of the value along the flow) changes from + to - in one of the two steps
  /// next to that node, to `rate_bits` (as locate: the rate is typically a finite
  /// difference, whose rounding noise limits the root anyway). Returns (maximum, scaled time).
  template <class Value, class Rate>
  std::pair<double, double> locate_maximum(
      const State& end, Value value, Rate rate,
      int rate_bits = std::numeric_limits<double>::digits) const {
    const std::size_t count = steps_.size();
    std::vector<double> node_value(count + 1);
    for (std::size_t i = 0; i < count; ++i) node_value[i] = value(steps_[i].state);
    node_value[count] = value(end);
    return locate_maximum(node_value, value, rate, rate_bits);
  }

  /// The same with the values at the nodes given: node_value[i] = value(steps()[i].state),
  /// and the last one the value at the end.
  template <class Value, class Rate>
  std::pair<double, double> locate_maximum(const std::vector<double>& node_value, Value value,
                                           Rate rate, int rate_bits) const {
    const std::size_t count = steps_.size();
    const std::size_t j = static_cast<std::size_t>(
        std::max_element(node_value.begin(), node_value.end()) - node_value.begin());
    double maximum = node_value[j];
    double time = j < count ? steps_[j].start : steps_.back().start + steps_.back().length;
    for (std::size_t s = (j > 0 ? j - 1 : 0); s <= j && s < count; ++s) {
      const Step& step = steps_[s];
      const State start_rate = rate_at(step.state);
      const auto rate_after = [&](double h) { return rate(advance(step.state, start_rate, h)); };
      const double at_start = rate_after(0);
      if (!(at_start > 0)) continue;
      const double at_end = rate_after(step.length);
      if (!(at_end < 0)) continue;
      const double h =
          locate(step.state, start_rate, 0.0, step.length, rate, at_start, at_end, rate_bits);
      const double candidate = value(advance(step.state, start_rate, h));
      if (candidate > maximum) {
        maximum = candidate;
        time = step.start + h;
      }
    }
    return {maximum, time};
  }

private:
  State rate_at(const State& y) const {
    State rate;
    system_(y, rate);
    return rate;
  }

  using ErrorStepper = Method;
  using ErrorChecker =
      boost::numeric::odeint::default_error_checker<double, typename ErrorStepper::algebra_type,
                                                    typename ErrorStepper::operations_type>;
  using ControlledStepper =
      boost::numeric::odeint::controlled_runge_kutta<ErrorStepper, ErrorChecker>;
  static constexpr std::size_t rejection_limit = 1000; // consecutive rejected steps

  System system_;
  double time_unit_;
  ControlledStepper controlled_;
  std::vector<Step> steps_;
};

} // namespace impact::reduced::detail
