// Accuracy of the linear-time Hunt-Crossley history (HuntCrossleyImpact::history, power
// law) over the parameter range, hard regions included (beta = 0, beta down to 1e-12 and up
// to 1e3 on both sides of the library's switch of variables at beta = 1, n from 1 to 2.5,
// and outside it 0.5 and 4), against
//   (a) the library's per-point quadrature (state_at: each instant inverted by Newton's
//       method on the adaptive tanh-sinh quadrature, independently of history's series),
//       at every point near the ends and every 7th point elsewhere;
//   (b) 50-digit references (high_precision_reference.hpp's formulas): the exact time at
//       which the impact passes the history's approach rate, by tanh-sinh quadrature in
//       50 digits, and the exact approach and force at that rate.
// Each test prints the worst error and where it occurred.

#include "high_precision_reference.hpp"

#include "impact_reduced/hunt_crossley.hpp"
#include "impact_reduced/invalid_input.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace impact::reduced;
using hp::Real100;
using hp::Real50;
using hp::WorstError;

constexpr double mass = 0.1;
constexpr double stiffness = 1.7135e10;

// The library's stated accuracy of a history state (hunt_crossley.hpp): approach, rate and
// force within 1e-12 of x_max, V and F_max; time of the state within 1e-13 t_c.
constexpr double target_state = 1e-12;
constexpr double target_time = 1e-13;

const std::vector<double> betas = {0.0, 1e-12,      1e-8, 1e-4, 0.01,  0.1, 0.5,
                                   1.0, 1.0 + 1e-9, 2.0,  10.0, 100.0, 1e3};

std::string where(double beta, double n, double velocity, std::size_t i) {
  return hp::format("beta=%.6g", beta) + hp::format(" n=%g", n) + hp::format(" V=%g", velocity) +
         " point " + std::to_string(i);
}

TEST(HuntCrossleyHistory, AgreesWithThePerPointQuadrature) {
  WorstError approach("history vs state_at: |dx| / x_max", target_state);
  WorstError rate("history vs state_at: |dv| / V", target_state);
  WorstError force("history vs state_at: |dF| / F_max", target_state);
  WorstError end("history end vs contact_time()", 1e-14);
  constexpr std::size_t points = 1001;
  for (const double n : {1.0, 1.5, 2.5, 0.5, 4.0}) {
    for (const double velocity : {1.0, 0.05, 20.0}) {
      for (const double beta : betas) {
        if (velocity != 1.0 && !(n == 1.5 && (beta == 0.1 || beta == 1e3 || beta == 1e-8)))
          continue; // V only scales the problem: a few cases
        const HuntCrossleyImpact impact(mass, stiffness, n, beta / velocity, velocity);
        const auto history = impact.history(points);
        ASSERT_EQ(history.size(), points);
        const double x_max = impact.approach_max();
        const double f_max = impact.force_peak().force;
        end.update(std::fabs(history.back().time / impact.contact_time() - 1),
                   where(beta, n, velocity, points - 1));
        for (std::size_t i = 1; i + 1 < points; ++i) {
          EXPECT_GT(history[i].time, history[i - 1].time);
          if (!(i < 12 || i + 12 > points || i % 7 == 0)) continue;
          const ImpactState exact = impact.state_at(history[i].time);
          const std::string at = where(beta, n, velocity, i);
          approach.update(std::fabs(history[i].approach - exact.approach) / x_max, at);
          rate.update(std::fabs(history[i].approach_rate - exact.approach_rate) / velocity, at);
          force.update(std::fabs(history[i].force - exact.force) / f_max, at);
        }
      }
    }
  }
  std::cout << "History (1001 points) against the per-point quadrature, beta in {0} U "
               "[1e-12, 1e3], n in {0.5, 1, 1.5, 2.5, 4}:\n";
  for (const WorstError* w : {&approach, &rate, &force, &end}) hp::expect_target(*w);
}

// The exact state that the impact passes at a history state's approach rate v, or, where
// 1 + b v is too small to be known from v in double precision (late restitution at large
// beta, where 1 + b v_out ~ exp(-995) at beta = 1e3), at its approach x. In the variables
// of hp::hunt_crossley_reference (b > 0): psi = log(1 + b v), delta the log-rate distance
// to the phase's singular end, b^2 E / m a closed form in delta; the time from that end is
// the 50-digit tanh-sinh integral of (m / b) / f over delta.
struct StateReference {
  Real100 time;     // since first contact
  Real100 approach; // x
  Real100 rate;     // v
  Real100 force;    // f(x) (1 + b v)
};

StateReference state_reference(const hp::ImpactInput& in, const hp::ImpactReference& r,
                               const ImpactState& state) {
  const bool compression = state.approach_rate > 0;
  const Real100 m = in.mass, c = in.stiffness, n = in.exponent, b = in.damping;
  const Real100 beta = b * in.velocity, p = n + 1;
  // w_out = W0(-(1 + beta) exp(-(1 + beta))) as in hunt_crossley_reference (not from v_out:
  // 1 + b v_out = -w_out ~ 1e-432 at beta = 1e3 is lost in 1 - y).
  const Real100 w_out = boost::math::lambert_w0(-(1 + beta) * exp(-(1 + beta)));
  const Real100 y = 1 + w_out;
  const Real50 m50(m), c50(c), n50(n), b50(b), p50(p), beta50(beta), y50(y), a50(-w_out);
  const Real50 energy_to_xp = p50 * m50 / (c50 * b50 * b50);
  auto energy = [&](const Real50& delta) {
    if (compression) return Real50(-beta50 * expm1(-delta) - hp::expm1_excess(Real50(-delta)));
    return y50 <= 0.5 ? Real50(y50 * expm1(delta) - hp::expm1_excess(delta))
                      : Real50(delta - a50 * expm1(delta));
  };
  auto density = [&](const Real50& delta) {
    const Real50 x = pow(energy_to_xp * energy(delta), 1 / p50);
    return m50 / (b50 * c50 * pow(x, n50));
  };
  const Real100 psi_in = log1p(beta), psi_out = log(-w_out);
  Real50 delta;
  // Near x_max the state is known well by v, near the ends (E ~ delta ~ x^(n+1)) by x.
  const bool by_rate = state.approach > 0.5 * static_cast<double>(r.approach_max) &&
                       1 + in.damping * state.approach_rate > 0.01;
  if (by_rate) {
    const Real100 psi = log1p(b * Real100(state.approach_rate));
    delta = compression ? Real50(psi_in - psi) : Real50(psi - psi_out);
  } else { // E(delta) = E(x), E increasing in delta on the phase
    const Real50 target = pow(Real50(state.approach), p50) / energy_to_xp;
    boost::uintmax_t iterations = 300;
    const auto [low, high] =
        boost::math::tools::toms748_solve([&](const Real50& d) { return energy(d) - target; },
                                          Real50(0),
                                          compression ? Real50(psi_in) : Real50(-psi_out),
                                          boost::math::tools::eps_tolerance<Real50>(160),
                                          iterations);
    delta = (low + high) / 2;
  }
  Real50 error = 0;
  const Real50 elapsed =
      delta > 0 ? hp::quadrature50().integrate(
                      [&](const Real50& u) {
                        // The tail within 1e-200 of the end weighs < 1e-57 (as in
                        // hunt_crossley_reference); there E underflows.
                        return u > Real50(1e-200) ? Real50(delta * density(delta * u)) : Real50(0);
                      },
                      Real50(0), Real50(1), Real50(1e-32), &error)
                : Real50(0);
  StateReference s;
  s.time = compression ? Real100(elapsed) : Real100(r.contact_time - Real100(elapsed));
  s.approach = Real100(pow(energy_to_xp * energy(delta), 1 / p50));
  const Real100 psi =
      compression ? Real100(psi_in - Real100(delta)) : Real100(psi_out + Real100(delta));
  s.rate = expm1(psi) / b;
  s.force = c * pow(s.approach, n) * exp(psi);
  return s;
}

TEST(HuntCrossleyHistory, StatesLieOnTheExactTrajectoryAtTheirTime) {
  WorstError time("history: |t - t_exact| / t_c", target_time);
  WorstError approach("history: |x - x_exact| / x_max", target_state);
  WorstError rate("history: |v - v_exact| / V", target_state);
  WorstError force("history: |F - F_exact| / F_max", target_state);
  constexpr std::size_t points = 1001;
  const std::vector<std::size_t> sampled = {1, 2, 5, 50, 250, 400, 600, 800, 950, 995, 998, 999};
  for (const double n : {1.0, 1.5, 2.5}) {
    for (const double beta : {1e-6, 0.1, 1.0, 1.0 + 1e-9, 20.0, 1e3}) {
      const hp::ImpactInput in{mass, stiffness, n, beta, 1.0};
      const hp::ImpactReference r = hp::hunt_crossley_reference(in);
      const HuntCrossleyImpact impact(mass, stiffness, n, beta, 1.0);
      const auto history = impact.history(points);
      for (const std::size_t i : sampled) {
        const ImpactState& state = history[i];
        const StateReference exact = state_reference(in, r, state);
        const std::string at = where(beta, n, 1.0, i);
        time.update(static_cast<double>(abs(Real100(state.time) - exact.time) / r.contact_time),
                    at);
        approach.update(static_cast<double>(abs(Real100(state.approach) - exact.approach) /
                                            r.approach_max),
                        at);
        rate.update(static_cast<double>(abs(Real100(state.approach_rate) - exact.rate)), at);
        force.update(static_cast<double>(abs(Real100(state.force) - exact.force) / r.force_max),
                     at);
      }
    }
  }
  std::cout << "History states against 50-digit references, beta in [1e-6, 1e3], "
               "n in {1, 1.5, 2.5}:\n";
  for (const WorstError* w : {&time, &approach, &rate, &force}) hp::expect_target(*w);
}

// states_at inverts each phase's instants in one pass: the same states as state_at, instant by
// instant, within 1e-11 of x_max, V and F_max (the increments' quadrature errors add up; worst
// measured 1.1e-12), for a law given by callables (the quadrature path) and the power law; times out of
// order or outside the contact are refused with "times" named.
TEST(HuntCrossleyHistory, StatesAtAgreesWithStateAt) {
  const double mass = 0.0327, stiffness = 1.2e10, exponent = 1.5, velocity = 1.4;
  const auto custom = std::make_shared<CustomElasticForce>(
      [=](double x) { return stiffness * std::pow(x, exponent); },
      [=](double x) { return stiffness * std::pow(x, exponent + 1) / (exponent + 1); },
      [=](double x) { return stiffness * exponent * std::pow(x, exponent - 1); });
  for (const double beta : {0.05, 2.0}) {
    const HuntCrossleyImpact impacts[] = {HuntCrossleyImpact(mass, custom, beta / velocity,
                                                             velocity),
                                          HuntCrossleyImpact(mass, stiffness, exponent,
                                                             beta / velocity, velocity)};
    for (const auto& impact : impacts) {
      std::vector<double> times;
      for (int i = 0; i <= 20; ++i) times.push_back(impact.contact_time() * i / 20.0);
      const auto states = impact.states_at(times);
      ASSERT_EQ(states.size(), times.size());
      const double force_scale = impact.force_peak().force;
      for (std::size_t i = 0; i < times.size(); ++i) {
        const ImpactState one = impact.state_at(times[i]);
        EXPECT_EQ(states[i].time, times[i]);
        EXPECT_NEAR(states[i].approach, one.approach, 1e-11 * impact.approach_max()) << i;
        EXPECT_NEAR(states[i].approach_rate, one.approach_rate, 1e-11 * velocity) << i;
        EXPECT_NEAR(states[i].force, one.force, 1e-11 * force_scale) << i;
      }
      const double t_c = impact.contact_time();
      for (const auto& bad : {std::vector<double>{0.5 * t_c, 0.25 * t_c},
                              std::vector<double>{-1e-9}, std::vector<double>{2 * t_c}}) {
        try {
          impact.states_at(bad);
          ADD_FAILURE() << "accepted bad times";
        } catch (const InvalidInput& error) {
          EXPECT_EQ(error.parameter(), "times");
        }
      }
    }
  }
}

} // namespace
