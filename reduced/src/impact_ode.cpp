// Reference integration of an impact under an arbitrary contact force law, with exact
// event location (see impact_ode.hpp for the method and its accuracy).
//
// The equation is integrated in the impact's own units: length L, time T = L / V with
// L * F(L, V) = m V^2 (the approach at which the force, acting over that approach, would
// take the incoming kinetic energy; it is within a factor of order one of x_max for every
// reasonable law). Scaled state y = (X, U) = (x / L, x' / V), scaled time tau = t / T:
//     dX/dtau = U,   dU/dtau = -F(L X, V U) T / (m V).

#include "impact_reduced/impact_ode.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/tools/toms748_solve.hpp>
// GCC 12 flags the implicit copy of Odeint's stepper temporaries (uninitialised scratch
// arrays, overwritten before use) as -Wuninitialized; the warning is Boost's, not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace impact::reduced {

namespace {

namespace odeint = boost::numeric::odeint;

using State = std::array<double, 2>; // scaled approach X, scaled approach rate U
// Cash-Karp 5(4). Not Fehlberg 7(8): its error estimate is a multiple of
// k1 + k11 - k12 - k13, which vanishes when the right-hand side depends on time only
// (quadrature), and the start and end of a contact are nearly that (x ~ V t, F ~ t^n with a
// fractional n): it accepted steps with 2e-8 error at a 1e-13 tolerance on the Hertz
// impact. Cash-Karp's embedded estimate stays honest there (1e-12 at 1e-13).
using ErrorStepper = odeint::runge_kutta_cash_karp54<State>;
using ErrorChecker =
    odeint::default_error_checker<double, ErrorStepper::algebra_type, ErrorStepper::operations_type>;
using ControlledStepper = odeint::controlled_runge_kutta<ErrorStepper, ErrorChecker>;

constexpr double time_limit = 1e5;            // in characteristic times T
constexpr std::size_t step_limit = 1000000;   // accepted steps
constexpr std::size_t rejection_limit = 1000; // consecutive rejected steps

std::string describe(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// The approach L with L * F(L, V) = m V^2, by a decade scan and bisection in log L.
// Fails if the law offers (almost) no resistance to the approach.
double characteristic_length(double mass, double velocity, const ContactForceLaw& force) {
  const double target = mass * velocity * velocity;
  const auto work = [&](double length) { return length * force(length, velocity); };
  double lower = 1e-30;
  if (!(work(lower) < target)) {
    // Resists already over 1e-30 m (e.g. a huge damper): take that as the scale.
    return lower;
  }
  double upper = lower;
  while (true) {
    upper = lower * 10;
    const double value = work(upper);
    if (!std::isfinite(value))
      throw std::runtime_error("contact force law returned a non-finite force at approach " +
                               describe(upper) + " m");
    if (value >= target) break;
    lower = upper;
    if (upper > 1e30)
      throw std::runtime_error(
          "contact force law offers no resistance to the approach: even at an approach of "
          "1e30 m, approach * F(approach, V) stays below m V^2");
  }
  for (int i = 0; i < 30; ++i) { // to ~1e-9 relative: more than enough for a scale
    const double middle = std::sqrt(lower * upper);
    (work(middle) < target ? lower : upper) = middle;
  }
  return std::sqrt(lower * upper);
}

// One accepted step: start time, start state and length (scaled).
struct Step {
  double start;
  State state;
  double length;
};

class ImpactIntegration {
public:
  ImpactIntegration(double mass, double velocity, const ContactForceLaw& force,
                    double relative_tolerance, ContactEnd end)
    : mass_(mass), velocity_(velocity), force_(force), tolerance_(relative_tolerance),
      end_(end) {
    require_positive("mass", mass);
    require_positive("velocity", velocity);
    if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-3))
      throw InvalidInput("relative_tolerance",
                         "relative_tolerance must be a number in [1e-14, 1e-3] (got " +
                             describe(relative_tolerance) + ")");
    if (!force) throw InvalidInput("force", "force must be a contact force law (got an empty one)");
    length_ = characteristic_length(mass, velocity, force);
    time_ = length_ / velocity;
    run();
    locate_force_maximum();
  }

  OdeImpactResult result() const {
    OdeImpactResult result{};
    result.approach_max = length_ * approach_max_;
    result.compression_time = time_ * compression_time_;
    result.force_max = force_max_;
    result.time_force_max = time_ * time_force_max_;
    result.contact_time = time_ * contact_time_;
    result.rebound_velocity = velocity_ * separation_rate_;
    result.restitution = -separation_rate_;
    result.force_at_separation = force_at(separation_);
    result.steps = steps_.size();
    result.approach_at_separation = length_ * separation_[0];
    return result;
  }

  std::vector<ImpactSample> history(std::size_t points) const {
    std::vector<ImpactSample> samples;
    samples.reserve(points);
    for (std::size_t i = 0; i < points; ++i) {
      State state = separation_;
      double tau = contact_time_;
      if (i + 1 < points) {
        tau = contact_time_ * static_cast<double>(i) / static_cast<double>(points - 1);
        // The last step whose start is <= tau.
        const auto after = std::upper_bound(steps_.begin(), steps_.end(), tau,
                                            [](double t, const Step& s) { return t < s.start; });
        const Step& step = *std::prev(after);
        state = advance(step.state, tau - step.start);
      }
      samples.push_back({time_ * tau, length_ * state[0], velocity_ * state[1], force_at(state)});
    }
    return samples;
  }

private:
  // Contact force in N at a scaled state; the law sees x >= 0 only.
  double force_at(const State& y) const {
    const double approach = std::max(length_ * y[0], 0.0);
    const double rate = velocity_ * y[1];
    const double value = force_(approach, rate);
    if (!std::isfinite(value))
      throw std::runtime_error("contact force law returned a non-finite force (" + describe(value) +
                               ") at approach " + describe(approach) + " m, approach rate " +
                               describe(rate) + " m/s");
    return value;
  }

  void rhs(const State& y, State& dydt) const {
    dydt[0] = y[1];
    dydt[1] = -force_at(y) * time_ / (mass_ * velocity_);
  }

  // The state reached from `start` after a single step of length h (no error control): the
  // "re-step" used for event location and sampling. h never exceeds an accepted step, so
  // its error is within the tolerance.
  State advance(const State& start, double h) const {
    if (h == 0) return start;
    State rate;
    rhs(start, rate);
    State end;
    ErrorStepper stepper;
    stepper.do_step([this](const State& s, State& d, double) { rhs(s, d); }, start, rate, 0.0,
                    end, h);
    return end;
  }

  // Root in (0, h] of event(advance(start, s)), given event(start) and event at h of
  // opposite signs (or zero at h).
  template <class Event>
  double locate(const State& start, double lower, double h, Event event) const {
    const double at_lower = event(advance(start, lower));
    const double at_upper = event(advance(start, h));
    if (at_upper == 0 || (at_upper > 0) == (at_lower > 0)) return h; // the sign change is at h
    if (at_lower == 0) return lower;
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve(
        [&](double s) { return event(advance(start, s)); }, lower, h, at_lower, at_upper,
        boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits),
        iterations);
    return 0.5 * (root.first + root.second);
  }

  void run() {
    ControlledStepper stepper(
        ErrorChecker(tolerance_, tolerance_, 1.0, 0.0)); // abs = rel on the scaled state
    const auto system = [this](const State& s, State& d, double) { rhs(s, d); };
    State y{0.0, 1.0};
    double tau = 0;
    double dtau = 1e-3;
    bool compressing = true;
    std::size_t rejections = 0;
    while (true) {
      if (steps_.size() >= step_limit || tau > time_limit) {
        std::ostringstream message;
        message.precision(6);
        message << "the body does not return to x = 0: after " << steps_.size()
                << " steps, at t = " << time_ * tau << " s (" << tau
                << " characteristic times), approach = " << length_ * y[0]
                << " m, approach rate = " << velocity_ * y[1]
                << " m/s; the contact force law sticks";
        throw ContactDoesNotEnd(message.str());
      }
      const State start = y;
      const double start_time = tau;
      if (stepper.try_step(system, y, tau, dtau) == odeint::fail) {
        if (++rejections > rejection_limit || !(dtau > 1e-300))
          throw std::runtime_error("impact integration cannot satisfy the tolerance at t = " +
                                   describe(time_ * tau) + " s");
        continue;
      }
      rejections = 0;
      if (!std::isfinite(y[0]) || !std::isfinite(y[1]) || !std::isfinite(tau))
        throw std::runtime_error("impact integration diverged at t = " +
                                 describe(time_ * start_time) + " s");
      double length = tau - start_time;
      double event_start = 0; // where the search for a later event in this step begins
      if (compressing && y[1] <= 0) {
        const double h =
            locate(start, 0.0, length, [](const State& s) { return s[1]; });
        compression_time_ = start_time + h;
        approach_max_ = advance(start, h)[0];
        compressing = false;
        event_start = h;
      }
      // End of contact: x back at 0, or (no tension) the force back at 0, whichever first.
      const bool released = !compressing && end_ == ContactEnd::zero_force && force_at(y) <= 0;
      if (!compressing && (y[0] <= 0 || released)) {
        double h = length;
        bool at_zero_approach = y[0] <= 0;
        if (at_zero_approach)
          h = locate(start, event_start, length, [](const State& s) { return s[0]; });
        if (end_ == ContactEnd::zero_force) {
          const auto force = [this](const State& s) { return force_at(s); };
          if (force(advance(start, h)) <= 0) {
            const double released_at = locate(start, event_start, h, force);
            at_zero_approach = at_zero_approach && released_at == h;
            h = released_at;
          }
        }
        separation_ = advance(start, h);
        if (at_zero_approach) separation_[0] = 0; // the located root, without its rounding
        steps_.push_back({start_time, start, h});
        contact_time_ = start_time + h;
        separation_rate_ = separation_[1];
        return;
      }
      steps_.push_back({start_time, start, length});
    }
  }

  // dF/dtau at a scaled state: fourth-order finite difference of F along the flow
  // direction f(y) (central, or one-sided where the stencil would cross x = 0).
  double force_rate(const State& y) const {
    State direction;
    rhs(y, direction);
    const double epsilon = 7e-4; // ~ eps^(1/5): balances truncation and rounding
    const auto force_along = [&](double s) {
      return force_at(State{y[0] + s * direction[0], y[1] + s * direction[1]});
    };
    if (y[0] - 2 * epsilon * std::abs(direction[0]) >= 0) {
      return (-force_along(2 * epsilon) + 8 * force_along(epsilon) - 8 * force_along(-epsilon) +
              force_along(-2 * epsilon)) /
             (12 * epsilon);
    }
    const double h = direction[0] >= 0 ? epsilon : -epsilon; // keep x >= 0
    return (-25 * force_along(0) + 48 * force_along(h) - 36 * force_along(2 * h) +
            16 * force_along(3 * h) - 3 * force_along(4 * h)) /
           (12 * h);
  }

  // The force maximum lies next to the largest node value, in one of the two adjacent
  // steps (or at that node): locate dF/dt = 0 there by re-stepping.
  void locate_force_maximum() {
    const std::size_t count = steps_.size();
    std::vector<double> node_force(count + 1);
    for (std::size_t i = 0; i < count; ++i) node_force[i] = force_at(steps_[i].state);
    node_force[count] = force_at(separation_);
    const std::size_t j = static_cast<std::size_t>(
        std::max_element(node_force.begin(), node_force.end()) - node_force.begin());
    force_max_ = node_force[j];
    time_force_max_ = j < count ? steps_[j].start : contact_time_;
    for (std::size_t s = (j > 0 ? j - 1 : 0); s <= j && s < count; ++s) {
      const Step& step = steps_[s];
      const auto rate_at = [&](double h) { return force_rate(advance(step.state, h)); };
      if (!(rate_at(0) > 0 && rate_at(step.length) < 0)) continue;
      const double h = locate(step.state, 0.0, step.length,
                              [&](const State& y) { return force_rate(y); });
      const double value = force_at(advance(step.state, h));
      if (value > force_max_) {
        force_max_ = value;
        time_force_max_ = step.start + h;
      }
    }
  }

  double mass_;
  double velocity_;
  const ContactForceLaw& force_;
  double tolerance_;
  ContactEnd end_;
  double length_ = 0;
  double time_ = 0;
  std::vector<Step> steps_;
  double approach_max_ = 0;
  double compression_time_ = 0;
  double contact_time_ = 0;
  double separation_rate_ = 0;
  State separation_{0.0, 0.0}; // scaled state at the end of contact
  double force_max_ = 0;
  double time_force_max_ = 0;
};

} // namespace

OdeImpactResult integrate_impact(double mass, double velocity, const ContactForceLaw& force,
                                 double relative_tolerance, ContactEnd end) {
  return ImpactIntegration(mass, velocity, force, relative_tolerance, end).result();
}

std::vector<ImpactSample> integrate_impact_history(double mass, double velocity,
                                                   const ContactForceLaw& force,
                                                   std::size_t points,
                                                   double relative_tolerance, ContactEnd end) {
  if (points < 2)
    throw InvalidInput("points", "points must be a whole number >= 2 (got " +
                                     std::to_string(points) + ")");
  return ImpactIntegration(mass, velocity, force, relative_tolerance, end).history(points);
}

} // namespace impact::reduced
