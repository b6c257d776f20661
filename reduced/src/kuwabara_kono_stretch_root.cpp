// The Kuwabara-Kono elastic-plastic impact in the square root of the stretch (see
// kuwabara_kono_stretch_root.hpp for the variables and why).
//
// Scaled variables: length L = (5 m V^2 / (4 c))^(2/5) (the elastic Hertz impact's x_max),
// time T = L / V, force m V / T. State y = (S, U, theta): S = sigma / sqrt(L), U = x' / V,
// theta = t / T; the approach is L S^2 while loading and L (S^2 + X_r) while unloading,
// X_r = x_r / L. With the scaled force phi = F T / (m V):
//     dS/dtau = U,   dU/dtau = -2 S phi,   dtheta/dtau = 2 S.

#include "kuwabara_kono_stretch_root.hpp"

#include "impact_reduced/invalid_input.hpp"

#include "event_stepping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace impact::reduced::detail {

namespace {

using State = std::array<double, 3>;
class StretchRootIntegration;

// The right-hand side, a concrete type so that the stepper's stages call it inline.
struct System {
  const StretchRootIntegration* integration;
  void operator()(const State& y, State& dydt) const;
};

using Stepper = EventStepper<3, Fehlberg78<3>, System>;

constexpr double time_limit = 1e5;          // in characteristic times T
constexpr std::size_t step_limit = 1000000; // accepted steps

// The pieces of the impact, each with its own force and the meaning of S.
enum class Piece {
  hertz,    // loading below the breakpoint: phi = c' S (S^2 + (3/2) A' U), S^2 = x / L
  fit,      // loading above it: the spring's F_L and dF_L/dx at x = L S^2
  unloading // from x_max: phi = k_u' S (S^2 + (3/2) A' U), S^2 = (x - x_r) / L
};

double first_breakpoint(const ElasticPlasticContact& spring) {
  const std::vector<double> breakpoints = spring.loading_breakpoints();
  if (breakpoints.empty()) return std::numeric_limits<double>::infinity();
  return *std::min_element(breakpoints.begin(), breakpoints.end());
}

class StretchRootIntegration {
public:
  friend struct System;
  StretchRootIntegration(double mass, double velocity, const ElasticPlasticContact& spring,
                         double dissipative_constant, double relative_tolerance)
      : spring_(spring), mass_(mass), velocity_(velocity), damping_(dissipative_constant) {
    if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-3))
      throw InvalidInput("relative_tolerance",
                         "relative_tolerance must be a number in [1e-14, 1e-3] (got " +
                             describe(relative_tolerance) + ")");
    const double hertz = spring.loading_power_law()->stiffness;
    length_ = std::pow(1.25 * mass * velocity * velocity / hertz, 0.4);
    time_ = length_ / velocity;
    force_unit_ = mass * velocity / time_;
    scaled_damping_ = 1.5 * dissipative_constant / time_;
    stiffness_unit_ = length_ * std::sqrt(length_) / force_unit_;
    hertz_scale_ = hertz * stiffness_unit_;
    breakpoint_ = first_breakpoint(spring);
    breakpoint_root_ = std::sqrt(breakpoint_ / length_);
    if (std::isfinite(breakpoint_)) {
      // The fit's values at the breakpoint: the spring's are Hertz's at x_b itself.
      std::tie(breakpoint_force_, breakpoint_stiffness_) = spring.loading_force_and_stiffness(
          std::nextafter(breakpoint_, std::numeric_limits<double>::infinity()));
    }
    stepper_.emplace(System{this}, relative_tolerance, time_);
    run();
  }

  OdeImpactResult result() {
    locate_force_maximum();
    OdeImpactResult result{};
    result.approach_max = approach_max_;
    result.compression_time = time_ * compression_time_;
    result.force_max = force_unit_ * force_max_;
    result.time_force_max = time_ * time_force_max_;
    result.contact_time = time_ * separation_[2];
    result.rebound_velocity = velocity_ * separation_[1];
    result.restitution = -separation_[1];
    result.force_at_separation = force_unit_ * scaled_force(separation_);
    result.steps = stepper_->steps().size();
    result.approach_at_separation = approach_at_separation_;
    return result;
  }

  std::vector<ImpactSample> history(std::size_t points) {
    std::vector<ImpactSample> samples;
    samples.reserve(points);
    const auto& steps = stepper_->steps();
    const double end_time = separation_[2];
    std::size_t index = 0;
    for (std::size_t i = 0; i + 1 < points; ++i) {
      const double theta = end_time * static_cast<double>(i) / static_cast<double>(points - 1);
      // The last step that starts at or before theta (theta grows along the steps).
      while (index + 1 < steps.size() && steps[index + 1].state[2] <= theta) ++index;
      const auto& step = steps[index];
      piece_ = pieces_[index];
      State state = step.state;
      if (theta > step.state[2]) {
        const double h = stepper_->locate(step.state, 0.0, step.length,
                                          [theta](const State& s) { return s[2] - theta; });
        state = stepper_->advance(step.state, h);
      }
      samples.push_back(sample(state));
    }
    piece_ = Piece::unloading;
    ImpactSample last = sample(separation_);
    last.approach = approach_at_separation_;
    samples.push_back(last);
    return samples;
  }

private:
  // The scaled force phi at y on the current piece.
  double scaled_force(const State& y) const {
    double phi;
    if (piece_ == Piece::fit) {
      const auto [force, stiffness] = fit(length_ * y[0] * y[0]);
      phi = (force + damping_ * stiffness * velocity_ * y[1]) / force_unit_;
    } else {
      const double scale = piece_ == Piece::hertz ? hertz_scale_ : unloading_scale_;
      phi = scale * y[0] * (y[0] * y[0] + scaled_damping_ * y[1]);
    }
    if (!std::isfinite(phi))
      throw std::runtime_error("Kuwabara-Kono law returned a non-finite force at approach " +
                               describe(approach(y)) + " m");
    return phi;
  }

  // F_L and dF_L/dx above the breakpoint, continued to it and below it to first order. The
  // spring's own law is Hertz's at x_b itself and below (Jackson-Green's force jumps there,
  // by 0.5 % at 1.9 omega_c), and the fit piece starts at x_b: its first steps failed their
  // error test down to 4e-6 of the usual length (measured). Below x_b only the few ulps by
  // which Fehlberg 7(8)'s twelfth stage (c = 0, weights summing to 0) can land under the
  // step's start: the continuation's error there, k' d^2 / 2, is far below F's rounding.
  std::pair<double, double> fit(double x) const {
    if (x > breakpoint_) return spring_.loading_force_and_stiffness_from_table(x);
    return {breakpoint_force_ + breakpoint_stiffness_ * (x - breakpoint_), breakpoint_stiffness_};
  }

  State rate_at(const State& y) const {
    State rate;
    rhs(y, rate);
    return rate;
  }

  double approach(const State& y) const {
    return length_ * (y[0] * y[0] + (piece_ == Piece::unloading ? residual_ : 0.0));
  }

  ImpactSample sample(const State& y) const {
    return {time_ * y[2], approach(y), velocity_ * y[1], force_unit_ * scaled_force(y)};
  }

  void rhs(const State& y, State& dydt) const { derivative(y, scaled_force(y), dydt); }

  static void derivative(const State& y, double phi, State& dydt) {
    dydt[0] = y[1];
    dydt[1] = -2 * y[0] * phi;
    dydt[2] = 2 * y[0];
  }

  // phi and its first two derivatives in tau at y on the current piece (the force peak's
  // search: dphi/dtau = 0 by Newton). On the Hertzian pieces in closed form; on the fit
  // dF/dt = k x' + A k' x'^2 + A k x'' and its derivative, with k' and k'' by differences of
  // the slope over 2^-14 x (central, or one-sided where they would reach below the
  // breakpoint), the table's slope: its 2.4e-13 makes 4e-9 of k', the truncation as much.
  // The k' term vanishes as x'^2 at the force peak (x' ~ A x'' there): its error moves the
  // peak by ~1e-12 of the step, and dF/dt's sign elsewhere not at all; k'' enters only the
  // Newton slope, times A x'.
  struct ForceRates {
    double force, rate, curvature; // phi, dphi/dtau, d2phi/dtau2
  };
  ForceRates force_rates(const State& y) const {
    const double phi = scaled_force(y); // with its check
    const double S = y[0], U = y[1];
    const double u1 = -2 * S * phi; // dU/dtau
    if (piece_ != Piece::fit) {
      const double scale = piece_ == Piece::hertz ? hertz_scale_ : unloading_scale_;
      const double d = scaled_damping_;
      const double rate = scale * ((3 * S * S + d * U) * U + d * S * u1);
      const double u2 = -2 * (U * phi + S * rate);
      return {phi, rate, scale * (6 * S * U * U + 3 * S * S * u1 + 3 * d * U * u1 + d * S * u2)};
    }
    const double x = length_ * S * S;
    const double dx = std::ldexp(x, -14);
    const double k = fit(x).second;
    double k1, k2;
    if (x - dx >= breakpoint_) {
      const double above = fit(x + dx).second, below = fit(x - dx).second;
      k1 = (above - below) / (2 * dx);
      k2 = (above - 2 * k + below) / (dx * dx);
    } else {
      const double above = fit(x + dx).second, further = fit(x + 2 * dx).second;
      k1 = (-3 * k + 4 * above - further) / (2 * dx);
      k2 = (k - 2 * above + further) / (dx * dx);
    }
    const double v = velocity_ * U, v1 = velocity_ * u1;
    const double x1 = 2 * length_ * S * U, x2 = 2 * length_ * (U * U + S * u1);
    const double rate = (k * x1 + damping_ * (k1 * x1 * v + k * v1)) / force_unit_;
    const double v2 = -2 * velocity_ * (U * phi + S * rate);
    const double curvature =
        (k1 * x1 * x1 + k * x2 +
         damping_ * (k2 * x1 * x1 * v + k1 * x2 * v + 2 * k1 * x1 * v1 + k * v2)) /
        force_unit_;
    return {phi, rate, curvature};
  }

  double force_rate(const State& y) const { return force_rates(y).rate; }

  // The re-stepped state at s + d from the one at s (`rate` f there) for |d| <= 1e-8 of the
  // step, to first order: the error, d^2 |f'| / 2 plus d times the re-step's departure from
  // f (the step's accuracy), is below 1e-18, and a re-step (13 evaluations) is saved.
  static State moved(const State& y, const State& rate, double d) {
    return {y[0] + d * rate[0], y[1] + d * rate[1], y[2] + d * rate[2]};
  }

  // An event's root in a step and the state there.
  struct Root {
    double length; // scaled time from the step's start
    State state;
  };

  // The root in [0, h] of event(advance(start, s)), where the event is > 0 at s = 0 and <= 0
  // at s = h (`at_h` the state there); event_rate(y, f(y)) is its derivative along the flow.
  // Newton's method on the re-stepped state, from the root on the step's cubic Hermite
  // interpolant (within about 1e-5 of the step, so that two Newton steps end it): the
  // derivative of the re-step in s is f there to the step's accuracy, so that convergence is
  // quadratic, and a Newton step below 1e-8 of the step leaves an error below 1e-16 of it.
  // Safeguarded by bisection on the bracket; TOMS 748 (EventStepper::locate) if it does not
  // end in 8 steps. Two re-steps and two evaluations of f instead of TOMS 748's five to
  // seven re-steps and the re-step to the root (measured).
  template <class Event, class EventRate>
  Root locate_event(const State& start, const State& start_rate, double h, const State& at_h,
                    Event event, EventRate event_rate) const {
    State end_rate;
    rhs(at_h, end_rate);
    // The Hermite interpolant at u = s / h in [0, 1] and its derivative in s.
    const auto hermite = [&](double u, State& state, State& slope) {
      const double u2 = u * u, u3 = u2 * u;
      const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = 3 * u2 - 2 * u3,
                   h11 = u3 - u2;
      const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d11 = 3 * u2 - 2 * u;
      for (std::size_t i = 0; i < 3; ++i) {
        state[i] = h00 * start[i] + h10 * h * start_rate[i] + h01 * at_h[i] + h11 * h * end_rate[i];
        slope[i] = (d00 * (start[i] - at_h[i])) / h + d10 * start_rate[i] + d11 * end_rate[i];
      }
    };
    double low = 0, high = 1, u = 0.5;
    for (int i = 0; i < 30; ++i) {
      State state, slope;
      hermite(u, state, slope);
      const double value = event(state);
      (value > 0 ? low : high) = u;
      double next = u - value / (h * event_rate(state, slope));
      if (!(next > low && next < high)) next = 0.5 * (low + high);
      const bool done = std::abs(next - u) <= 1e-14;
      u = next;
      if (done) break;
    }
    double lower = 0, upper = h, s = u * h;
    for (int i = 0; i < 8; ++i) {
      const State y = stepper_->advance(start, start_rate, s);
      const double value = event(y);
      if (value == 0) return {s, y};
      (value > 0 ? lower : upper) = s;
      State rate;
      rhs(y, rate);
      double next = s - value / event_rate(y, rate);
      // Converged (the test comes before the bracket's, which a step below an ulp of s fails).
      if (next == s) return {s, y};
      if (std::abs(next - s) <= 1e-8 * h && next >= lower && next <= upper)
        return {next, moved(y, rate, next - s)};
      if (!(next > lower && next < upper)) next = 0.5 * (lower + upper);
      s = next;
    }
    const double root = stepper_->locate(start, start_rate, lower, upper, event,
                                         event(stepper_->advance(start, start_rate, lower)),
                                         event(stepper_->advance(start, start_rate, upper)));
    return {root, stepper_->advance(start, start_rate, root)};
  }

  // The step just taken ends at an event's root.
  void end_step_at(const Root& root, double start_time, double& tau) {
    stepper_->truncate_last_step(root.length);
    tau = start_time + root.length;
  }

  void run() {
    State y{0.0, 1.0, 0.0};
    double tau = 0;
    double dtau = 0.1; // the steps are 0.1 to 0.2 over the impact (measured)
    piece_ = Piece::hertz;
    // The force at y, carried from the end of a step to the start of the next one, where it
    // gives the stepper its first derivative and the force maximum its node value.
    double phi = scaled_force(y);
    while (true) {
      if (stepper_->steps().size() >= step_limit || y[2] > time_limit) {
        std::ostringstream message;
        message.precision(6);
        message << "the body does not separate: after " << stepper_->steps().size()
                << " steps, at t = " << time_ * y[2] << " s, approach = " << approach(y)
                << " m, approach rate = " << velocity_ * y[1] << " m/s";
        throw ContactDoesNotEnd(message.str());
      }
      State start_rate;
      derivative(y, phi, start_rate);
      node_forces_.push_back(phi);
      pieces_.push_back(piece_);
      const auto& step = stepper_->step(y, tau, dtau, &start_rate);
      const State start = step.state;
      const double start_time = step.start;
      const double length = step.length;
      if (piece_ != Piece::unloading)
        end_loading_step(start, start_rate, start_time, length, y, tau);
      else if (ends_contact(start, start_rate, start_time, length, y, tau))
        return;
      phi = scaled_force(y);
    }
  }

  // After a step on a loading piece: the step ends at the breakpoint or at x_max if it holds
  // either, and the next piece starts there (y, tau: the state and time to go on from).
  void end_loading_step(const State& start, const State& start_rate, double start_time,
                        double length, State& y, double& tau) {
    // The maximum approach x' = 0, if reached in this step; the breakpoint before it.
    const bool stops = y[1] <= 0;
    Root stop{length, y};
    if (stops)
      stop = locate_event(
          start, start_rate, length, y, [](const State& s) { return s[1]; },
          [](const State&, const State& f) { return f[1]; });
    const double root = breakpoint_root_;
    if (piece_ == Piece::hertz && stop.state[0] >= root) {
      const Root at = locate_event(
          start, start_rate, stop.length, stop.state,
          [root](const State& s) { return root - s[0]; },
          [](const State&, const State& f) { return -f[0]; });
      end_step_at(at, start_time, tau);
      y = at.state;
      y[0] = root; // the located root, without its rounding
      piece_ = Piece::fit;
      return;
    }
    if (!stops) return;
    end_step_at(stop, start_time, tau);
    y = stop.state;
    y[1] = 0;
    maximum_step_ = stepper_->steps().size() - 1;
    maximum_state_ = y;
    approach_max_ = length_ * y[0] * y[0];
    compression_time_ = y[2];
    const HertzianUnloading branch = spring_.unloading(approach_max_);
    unloading_scale_ = branch.stiffness * stiffness_unit_;
    residual_ = branch.residual_approach / length_;
    y[0] = std::sqrt(std::max(0.0, y[0] * y[0] - residual_));
    piece_ = Piece::unloading;
  }

  // After a step on the unloading piece: whether the contact ends in it (then the step ends
  // there and the separation is recorded). Separation where F = 0, i.e. S^2 + (3/2) A' U = 0
  // (A > 0; S = 0 for A = 0, x = x_r), or where x returns to 0 first (x_r < 0). Both
  // functions decrease along the unloading while S >= 0, and both are negative at S = 0: if
  // S crossed 0 in the step, the search is confined to the part before.
  bool ends_contact(const State& start, const State& start_rate, double start_time, double length,
                    const State& y, double& tau) {
    const double scaled_damping = scaled_damping_, residual = residual_;
    const auto released = [scaled_damping](const State& s) {
      return scaled_damping > 0 ? s[0] * s[0] + scaled_damping * s[1] : s[0];
    };
    const auto released_rate = [scaled_damping](const State& s, const State& f) {
      return scaled_damping > 0 ? 2 * s[0] * f[0] + scaled_damping * f[1] : f[0];
    };
    const auto returned = [residual](const State& s) { return s[0] * s[0] + residual; };
    const auto returned_rate = [](const State& s, const State& f) { return 2 * s[0] * f[0]; };
    Root end{length, y};
    if (y[0] <= 0)
      end = locate_event(
          start, start_rate, length, y, [](const State& s) { return s[0]; },
          [](const State&, const State& f) { return f[0]; });
    const bool releases = released(end.state) <= 0;
    const bool returns = residual < 0 && returned(end.state) <= 0;
    if (!releases && !returns && end.length == length) return false;
    Root separation = end;
    if (releases)
      separation = locate_event(start, start_rate, end.length, end.state, released, released_rate);
    bool at_zero_approach = false;
    if (residual < 0 && returned(separation.state) <= 0) { // x = 0 first
      separation = locate_event(start, start_rate, separation.length, separation.state, returned,
                                returned_rate);
      at_zero_approach = true;
    }
    end_step_at(separation, start_time, tau);
    separation_ = separation.state;
    approach_at_separation_ = at_zero_approach ? 0.0 : std::max(0.0, approach(separation_));
    return true;
  }

  // The peak of phi inside a step (phi0, r0 > 0 at its start, phi1, r1 < 0 at its end; r the
  // rate dphi/dtau): where r = 0, by Newton's method on the re-stepped state from the peak of
  // phi's cubic Hermite interpolant on the step, r's derivative from force_rates; as
  // locate_event otherwise. Two Newton steps (measured) instead of TOMS 748's five.
  Root locate_peak(const Stepper::Step& step, double phi0, double phi1, double r0,
                   double r1) const {
    const double h = step.length;
    double low = 0, high = 1, u = 0.5;
    for (int i = 0; i < 30; ++i) {
      const double u2 = u * u;
      const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d11 = 3 * u2 - 2 * u;
      const double e00 = 12 * u - 6, e10 = 6 * u - 4, e11 = 6 * u - 2;
      const double slope = (phi0 - phi1) * d00 + h * (r0 * d10 + r1 * d11); // h dH/ds
      const double curvature = (phi0 - phi1) * e00 + h * (r0 * e10 + r1 * e11);
      (slope > 0 ? low : high) = u;
      double next = u - slope / curvature;
      if (!(next > low && next < high)) next = 0.5 * (low + high);
      const bool done = std::abs(next - u) <= 1e-14;
      u = next;
      if (done) break;
    }
    const State start_rate = rate_at(step.state);
    const auto rate = [this](const State& y) { return force_rate(y); };
    double lower = 0, upper = h, s = u * h;
    for (int i = 0; i < 8; ++i) {
      const State y = stepper_->advance(step.state, start_rate, s);
      const ForceRates at = force_rates(y);
      const double value = at.rate;
      if (value == 0) return {s, y};
      (value > 0 ? lower : upper) = s;
      State f;
      derivative(y, at.force, f);
      double next = s - value / at.curvature;
      if (next == s) return {s, y}; // converged, as in locate_event
      if (std::abs(next - s) <= 1e-8 * h && next >= lower && next <= upper)
        return {next, moved(y, f, next - s)};
      if (!(next > lower && next < upper)) next = 0.5 * (lower + upper);
      s = next;
    }
    constexpr int bits = 40;
    const double root =
        stepper_->locate(step.state, start_rate, lower, upper, rate,
                         rate(stepper_->advance(step.state, start_rate, lower)),
                         rate(stepper_->advance(step.state, start_rate, upper)), bits);
    return {root, stepper_->advance(step.state, start_rate, root)};
  }

  // The force maximum lies next to the largest node value j: in step j if F still rises at
  // node j, else in step j - 1 (or at the node), on the piece of that step (locate_peak).
  // The state at a node is shared by the two steps next to it when they are on one piece
  // (the rate jumps where the piece changes).
  void locate_force_maximum() {
    const auto& steps = stepper_->steps();
    const std::size_t count = steps.size();
    std::vector<double> node_value = node_forces_;
    piece_ = Piece::unloading;
    node_value.push_back(scaled_force(separation_));
    const std::size_t j = static_cast<std::size_t>(
        std::max_element(node_value.begin(), node_value.end()) - node_value.begin());
    force_max_ = node_value[j];
    time_force_max_ = j < count ? steps[j].state[2] : separation_[2];
    // The state and phi at the end of step s on its piece (the current one).
    const auto step_end = [&](std::size_t s) -> std::pair<State, double> {
      if (s + 1 < count && pieces_[s + 1] == pieces_[s])
        return {steps[s + 1].state, node_value[s + 1]};
      if (s == maximum_step_) return {maximum_state_, scaled_force(maximum_state_)};
      const State end = stepper_->advance(steps[s].state, steps[s].length);
      return {end, scaled_force(end)};
    };
    const auto search = [&](std::size_t s, double at_start, double end_phi, double at_end) {
      const Root peak = locate_peak(steps[s], node_value[s], end_phi, at_start, at_end);
      const double candidate = scaled_force(peak.state);
      if (candidate > force_max_) {
        force_max_ = candidate;
        time_force_max_ = peak.state[2];
      }
    };
    double rate_j = 0; // at node j on step j's piece
    if (j < count) {
      piece_ = pieces_[j];
      rate_j = force_rate(steps[j].state);
      if (rate_j > 0) {
        const auto [end, end_phi] = step_end(j);
        const double at_end = force_rate(end);
        if (at_end < 0) search(j, rate_j, end_phi, at_end);
      }
    }
    if (j > 0) {
      const std::size_t s = j - 1;
      piece_ = pieces_[s];
      const double at_start = force_rate(steps[s].state);
      if (at_start > 0) {
        const auto [end, end_phi] = step_end(s);
        const bool shared = j < count && pieces_[j] == pieces_[s];
        const double at_end = shared ? rate_j : force_rate(end);
        if (at_end < 0) search(s, at_start, end_phi, at_end);
      }
    }
    piece_ = Piece::unloading;
  }

  const ElasticPlasticContact& spring_;
  double mass_;
  double velocity_;
  double damping_; // A [s]
  double length_ = 0, time_ = 0, force_unit_ = 0;
  double scaled_damping_ = 0;          // (3/2) A / T
  double stiffness_unit_ = 0;          // L^(3/2) / (m V / T): a Hertzian stiffness to scaled units
  double hertz_scale_ = 0;             // c, scaled
  double breakpoint_ = 0;              // x_b [m], infinite if none
  double breakpoint_root_ = 0;         // sqrt(x_b / L)
  double breakpoint_force_ = 0;        // the fit's F_L at x_b [N]
  double breakpoint_stiffness_ = 0;    // and its dF_L/dx [N/m]
  double unloading_scale_ = 0;         // k_u, scaled
  double residual_ = 0;                // X_r = x_r / L
  mutable Piece piece_ = Piece::hertz; // the piece whose law rhs() uses (set for re-steps)
  std::optional<Stepper> stepper_;
  std::vector<double> node_forces_; // phi at the start of each recorded step
  std::vector<Piece> pieces_;       // the piece of each recorded step
  std::size_t maximum_step_ = 0;    // the step that ends at x_max
  State maximum_state_{};           // and its end state, in the loading piece's variables
  double approach_max_ = 0;         // m
  double compression_time_ = 0;
  double approach_at_separation_ = 0; // m
  State separation_{0.0, 0.0, 0.0};
  double force_max_ = 0;
  double time_force_max_ = 0;
};

void System::operator()(const State& y, State& dydt) const {
  integration->rhs(y, dydt);
}

} // namespace

bool has_hertz_start(const ElasticPlasticContact& spring) {
  const auto power_law = spring.loading_power_law();
  return power_law && power_law->exponent == 1.5 && power_law->stiffness > 0;
}

OdeImpactResult kuwabara_kono_stretch_root_impact(double mass, double velocity,
                                                  const ElasticPlasticContact& spring,
                                                  double dissipative_constant,
                                                  double relative_tolerance) {
  return StretchRootIntegration(mass, velocity, spring, dissipative_constant, relative_tolerance)
      .result();
}

std::vector<ImpactSample> kuwabara_kono_stretch_root_history(double mass, double velocity,
                                                             const ElasticPlasticContact& spring,
                                                             double dissipative_constant,
                                                             std::size_t points,
                                                             double relative_tolerance) {
  if (points < 2)
    throw InvalidInput("points",
                       "points must be a whole number >= 2 (got " + std::to_string(points) + ")");
  return StretchRootIntegration(mass, velocity, spring, dissipative_constant, relative_tolerance)
      .history(points);
}

} // namespace impact::reduced::detail
