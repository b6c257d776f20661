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

#include "event_stepping.hpp"
#include "switched_impact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <tuple>

namespace impact::reduced {

namespace {

using detail::describe;
using Stepper = detail::EventStepper<2>;
using State = Stepper::State; // scaled approach X, scaled approach rate U

constexpr double time_limit = 1e5;          // in characteristic times T
constexpr std::size_t step_limit = 1000000; // accepted steps

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

class ImpactIntegration {
public:
  ImpactIntegration(double mass, double velocity, const ContactForceLaw& force,
                    double relative_tolerance, ContactEnd end,
                    const detail::LawAtMaximum& at_maximum = nullptr)
      : mass_(mass), velocity_(velocity), force_(&force), end_(end), at_maximum_(at_maximum) {
    require_positive("mass", mass);
    require_positive("velocity", velocity);
    if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-3))
      throw InvalidInput("relative_tolerance",
                         "relative_tolerance must be a number in [1e-14, 1e-3] (got " +
                             describe(relative_tolerance) + ")");
    if (!force) throw InvalidInput("force", "force must be a contact force law (got an empty one)");
    length_ = characteristic_length(mass, velocity, force);
    time_ = length_ / velocity;
    stepper_.emplace([this](const State& y, State& dydt) { rhs(y, dydt); }, relative_tolerance,
                     time_);
    run();
  }

  // The figures; the force maximum is located here, not for a history, which does not need it
  // (its search re-steps the steps next to the largest node force some ten times).
  OdeImpactResult result() {
    locate_force_maximum();
    OdeImpactResult result{};
    result.approach_max = length_ * approach_max_;
    result.compression_time = time_ * compression_time_;
    result.force_max = force_max_;
    result.time_force_max = time_ * time_force_max_;
    result.contact_time = time_ * contact_time_;
    result.rebound_velocity = velocity_ * separation_rate_;
    result.restitution = -separation_rate_;
    result.force_at_separation = force_at(separation_);
    result.steps = stepper_->steps().size();
    result.approach_at_separation = length_ * separation_[0];
    return result;
  }

  std::vector<ImpactSample> history(std::size_t points) const {
    std::vector<ImpactSample> samples;
    for (const auto& [tau, state] : stepper_->sample_uniformly(points, contact_time_, separation_))
      samples.push_back({time_ * tau, length_ * state[0], velocity_ * state[1], force_at(state)});
    return samples;
  }

private:
  // Contact force in N at a scaled state; the law sees x >= 0 only.
  double force_at(const State& y) const {
    const double approach = std::max(length_ * y[0], 0.0);
    const double rate = velocity_ * y[1];
    const double value = (*force_)(approach, rate);
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

  State advance(const State& start, double h) const { return stepper_->advance(start, h); }

  template <class Event>
  double locate(const State& start, double lower, double h, Event event) const {
    return stepper_->locate(start, lower, h, event);
  }

  void run() {
    State y{0.0, 1.0};
    double tau = 0;
    double dtau = 1e-3;
    bool compressing = true;
    // The force at y, carried from the check after a step to the start of the next one, where
    // it gives the stepper its first derivative and the force maximum its node value.
    double force_at_y = force_at(y);
    while (true) {
      if (stepper_->steps().size() >= step_limit || tau > time_limit) {
        std::ostringstream message;
        message.precision(6);
        message << "the body does not return to x = 0: after " << stepper_->steps().size()
                << " steps, at t = " << time_ * tau << " s (" << tau
                << " characteristic times), approach = " << length_ * y[0]
                << " m, approach rate = " << velocity_ * y[1]
                << " m/s; the contact force law sticks";
        throw ContactDoesNotEnd(message.str());
      }
      const State start_rate{y[1], -force_at_y * time_ / (mass_ * velocity_)}; // rhs(y)
      node_forces_.push_back(force_at_y);
      const auto& step = stepper_->step(y, tau, dtau, &start_rate);
      const State start = step.state;
      const double start_time = step.start;
      const double length = step.length;
      double event_start = 0; // where the search for a later event in this step begins
      if (compressing && y[1] <= 0 && at_maximum_ && !switched_) {
        // x_max is reached in this step: the step ends there (x' = 0 exactly) and the law of
        // that x_max takes over from it. The law's slope changes at x_max (loading to
        // unloading stiffness), so a step boundary there keeps that kink out of every step,
        // and the steps up to x_max are those of the loading law, which is the switched
        // law while x' >= 0.
        const double h = locate(start, 0.0, length, [](const State& s) { return s[1]; });
        y = advance(start, h);
        y[1] = 0; // the located root, without its rounding
        tau = start_time + h;
        stepper_->truncate_last_step(h);
        switched_law_ = at_maximum_(length_ * y[0]);
        force_ = &switched_law_;
        switched_ = true;
        compression_time_ = tau;
        approach_max_ = y[0];
        compressing = false;
        force_at_y = force_at(y); // F_L(x_max): the damping term vanishes at x' = 0
        continue;
      }
      if (compressing && y[1] <= 0) {
        const double h = locate(start, 0.0, length, [](const State& s) { return s[1]; });
        compression_time_ = start_time + h;
        approach_max_ = advance(start, h)[0];
        compressing = false;
        event_start = h;
      }
      // End of contact: x back at 0, or (no tension) the force back at 0, whichever first.
      force_at_y = force_at(y);
      const bool released = !compressing && end_ == ContactEnd::zero_force && force_at_y <= 0;
      if (!compressing && (y[0] <= 0 || released)) {
        double h = length;
        bool at_zero_approach = y[0] <= 0;
        if (at_zero_approach)
          h = locate(start, event_start, length, [](const State& s) { return s[0]; });
        if (end_ == ContactEnd::zero_force) {
          const auto force = [this](const State& s) { return force_at(s); };
          const double force_at_end = force(advance(start, h));
          if (at_zero_approach && force_at_end == 0) {
            // The law vanishes at x = 0 (a factor x^(1/2)): a window of tension just before
            // x = 0 may lie inside this step with the force 0, not negative, at its end.
            // Bracket against -1 beyond x = 0, so that such a crossing is found; a root at
            // the jump itself is x = 0, kept exact.
            const double released_at = locate(start, event_start, h, [&](const State& s) {
              return s[0] <= 0 ? -1.0 : force(s);
            });
            if (advance(start, released_at)[0] > 0) {
              at_zero_approach = false;
              h = released_at;
            }
          } else if (force_at_end <= 0) {
            const double released_at = locate(start, event_start, h, force);
            at_zero_approach = at_zero_approach && released_at == h;
            h = released_at;
          }
        }
        separation_ = advance(start, h);
        if (at_zero_approach) separation_[0] = 0; // the located root, without its rounding
        stepper_->truncate_last_step(h);
        contact_time_ = start_time + h;
        separation_rate_ = separation_[1];
        return;
      }
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
  // steps (or at that node): located where dF/dt = 0 by re-stepping, to 2^-39 of the step
  // (1e-13 of the contact time): the finite difference's rounding, 1e-13 of F's scale, makes
  // its sign random closer to the root, and TOMS 748 then bisects (10 to 22 evaluations of
  // dF/dt instead of 5 to 13, measured on Kuwabara-Kono). F_max, second order in that
  // distance, does not change.
  void locate_force_maximum() {
    std::vector<double> node_value = node_forces_;
    node_value.push_back(force_at(separation_));
    constexpr int rate_bits = 40;
    std::tie(force_max_, time_force_max_) = stepper_->locate_maximum(
        node_value, [this](const State& y) { return force_at(y); },
        [this](const State& y) { return force_rate(y); }, rate_bits);
  }

  double mass_;
  double velocity_;
  const ContactForceLaw* force_; // the law in use
  ContactEnd end_;
  detail::LawAtMaximum at_maximum_; // if set: the law from x_max on, given x_max
  ContactForceLaw switched_law_;
  bool switched_ = false;
  std::vector<double> node_forces_; // the force at the start of each recorded step
  double length_ = 0;
  double time_ = 0;
  std::optional<Stepper> stepper_;
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
                                                   const ContactForceLaw& force, std::size_t points,
                                                   double relative_tolerance, ContactEnd end) {
  if (points < 2)
    throw InvalidInput("points",
                       "points must be a whole number >= 2 (got " + std::to_string(points) + ")");
  return ImpactIntegration(mass, velocity, force, relative_tolerance, end).history(points);
}

} // namespace impact::reduced

namespace impact::reduced::detail {

OdeImpactResult integrate_switched_impact(double mass, double velocity,
                                          const ContactForceLaw& loading,
                                          const LawAtMaximum& at_maximum, double relative_tolerance,
                                          ContactEnd end) {
  return ImpactIntegration(mass, velocity, loading, relative_tolerance, end, at_maximum).result();
}

std::vector<ImpactSample> integrate_switched_impact_history(
    double mass, double velocity, const ContactForceLaw& loading, const LawAtMaximum& at_maximum,
    std::size_t points, double relative_tolerance, ContactEnd end) {
  if (points < 2)
    throw InvalidInput("points",
                       "points must be a whole number >= 2 (got " + std::to_string(points) + ")");
  return ImpactIntegration(mass, velocity, loading, relative_tolerance, end, at_maximum)
      .history(points);
}

} // namespace impact::reduced::detail
