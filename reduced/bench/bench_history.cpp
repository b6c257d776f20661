// The time history of a Hunt-Crossley impact at P points equally spaced in time: the
// library's closed form (HuntCrossleyImpact::history, linear in P) against Boost.Odeint's
// dense output of the equation of motion (Dormand-Prince 5(4) and Bulirsch-Stoer), each
// ODE at a range of tolerances. Each ODE benchmark reports its error against the closed
// form as the counter `error` (largest of |dx|/x_max, |dv|/V, |dF|/F_max over the points),
// so that the tolerance at which it matches the closed form's accuracy can be read off.
//
// The published steel example (m = 0.1 kg, c = 1.7135e10 N/m^1.5, n = 3/2, b = 0.1 s/m,
// V = 1 m/s, so beta = 0.1).

#include "impact_reduced/hunt_crossley.hpp"

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace {

using namespace impact::reduced;
namespace odeint = boost::numeric::odeint;

constexpr double mass = 0.1;
constexpr double stiffness = 1.7135e10;
constexpr double exponent = 1.5;
constexpr double damping = 0.1;
constexpr double velocity = 1.0;

void closed_form_history(benchmark::State& state) {
  const auto points = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, velocity);
    benchmark::DoNotOptimize(impact.history(points));
  }
  state.SetComplexityN(state.range(0));
}
// 2 points: the fixed cost (the impact and the two phases' series, nothing located).
BENCHMARK(closed_form_history)
    ->Arg(2)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);

// The equation on the impact's own scales: x = x_max X, v = V Y, t = (x_max / V) T, so that
// the tolerances are relative to x_max and V: X' = Y, Y' = -F x_max / (m V^2).
using Scaled = std::array<double, 2>;

struct ScaledImpact {
  double approach_max;
  double time_scale;
  void operator()(const Scaled& y, Scaled& dydt, double) const {
    const double x = std::max(y[0], 0.0) * approach_max;
    const double force = stiffness * std::pow(x, exponent) * (1 + damping * velocity * y[1]);
    dydt[0] = y[1];
    dydt[1] = -force * approach_max / (mass * velocity * velocity);
  }
};

// Integrates with a dense-output stepper until X returns to 0, keeping a copy of the
// stepper after each step (its dense output on that step); locates the end of contact on
// the last step's dense output (TOMS 748); then evaluates the dense output of the step
// that holds each of the `points` uniform instants of [0, t_c].
template <class DenseStepper>
std::vector<ImpactState> ode_history(DenseStepper stepper, std::size_t points) {
  const double approach_max =
      HuntCrossleyImpact(mass, stiffness, exponent, damping, velocity).approach_max();
  const ScaledImpact system{approach_max, approach_max / velocity};
  stepper.initialize(Scaled{0.0, 1.0}, 0.0, 1e-3);
  // The copies of the steps reuse one buffer from call to call: at tight tolerances they
  // fill hundreds of kB, whose fresh allocation (page faults) would otherwise be timed too,
  // and more or less of it depending on what the allocator did before.
  thread_local std::vector<DenseStepper> steps;
  steps.clear();
  do {
    stepper.do_step(system);
    steps.push_back(stepper);
  } while (!(stepper.current_state()[1] < 0 && stepper.current_state()[0] <= 0));
  Scaled y;
  auto approach = [&](double t) {
    stepper.calc_state(t, y);
    return y[0];
  };
  boost::uintmax_t iterations = 100;
  const double previous = stepper.previous_time(), current = stepper.current_time();
  const auto [low, high] =
      boost::math::tools::toms748_solve(approach, previous, current, approach(previous),
                                        approach(current),
                                        boost::math::tools::eps_tolerance<double>(), iterations);
  const double end = 0.5 * (low + high);

  std::vector<ImpactState> states;
  states.reserve(points);
  std::size_t step = 0;
  for (std::size_t i = 0; i < points; ++i) {
    const double t = end * double(i) / double(points - 1);
    while (step + 1 < steps.size() && t > steps[step].current_time()) ++step;
    steps[step].calc_state(t, y);
    const double x = std::max(y[0], 0.0) * approach_max;
    const double v = y[1] * velocity;
    states.push_back(
        {t * system.time_scale, x, v, stiffness * std::pow(x, exponent) * (1 + damping * v)});
  }
  return states;
}

double history_error(const std::vector<ImpactState>& ode) {
  const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, velocity);
  const auto exact = impact.history(ode.size());
  const double force_scale = impact.force_peak().force;
  double error = 0;
  for (std::size_t i = 0; i < ode.size(); ++i)
    error = std::max({error, std::fabs(ode[i].approach - exact[i].approach) / impact.approach_max(),
                      std::fabs(ode[i].approach_rate - exact[i].approach_rate) / velocity,
                      std::fabs(ode[i].force - exact[i].force) / force_scale});
  return error;
}

template <class Make>
void ode_benchmark(benchmark::State& state, Make make) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  constexpr std::size_t points = 1000;
  for (auto _ : state) benchmark::DoNotOptimize(ode_history(make(tolerance), points));
  state.counters["error"] = history_error(ode_history(make(tolerance), points));
}

void dopri5_dense_history(benchmark::State& state) {
  ode_benchmark(state, [](double tolerance) {
    return odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<Scaled>());
  });
}
BENCHMARK(dopri5_dense_history)->DenseRange(8, 14, 1)->Unit(benchmark::kMicrosecond);

void bulirsch_stoer_dense_history(benchmark::State& state) {
  ode_benchmark(state, [](double tolerance) {
    return odeint::bulirsch_stoer_dense_out<Scaled>(tolerance, tolerance);
  });
}
BENCHMARK(bulirsch_stoer_dense_history)->DenseRange(8, 14, 1)->Unit(benchmark::kMicrosecond);

} // namespace
