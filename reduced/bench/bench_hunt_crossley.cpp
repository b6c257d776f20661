// Cost of the closed-form Hunt-Crossley impact against a direct ODE integration of the
// same impact. Targets: restitution <= 100 ns, full response <= 5 us, closed form
// >= 1000 times faster than the ODE at equal accuracy.

#include "impact_reduced/hunt_crossley.hpp"
#include "impact_reduced/impact_ode.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace impact::reduced;

// The published steel example: m = 0.1 kg, c = 1.7135e10 N/m^1.5, n = 3/2, b = 0.1 s/m.
constexpr double mass = 0.1;
constexpr double stiffness = 1.7135e10;
constexpr double exponent = 1.5;
constexpr double damping = 0.1;

void restitution(benchmark::State& state) {
  double beta = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(restitution_from_impact_parameter(beta));
    beta = beta < 1.0 ? beta * 1.01 : 0.1; // vary the input so nothing is hoisted
  }
}
BENCHMARK(restitution);

void damping_from_restitution_inverse(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(damping_from_restitution(0.9, 1.0));
}
BENCHMARK(damping_from_restitution_inverse);

// The closed-form keys: x_max, restitution, rebound velocity, energy loss (the
// constructor computes them; no quadrature). These replace what an ODE integration is
// otherwise run for.
void closed_form_keys(benchmark::State& state) {
  double velocity = 1.0;
  for (auto _ : state) {
    const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, velocity);
    benchmark::DoNotOptimize(impact.approach_max());
    benchmark::DoNotOptimize(impact.energy_loss());
    velocity = velocity < 5.0 ? velocity * 1.01 : 1.0;
  }
}
BENCHMARK(closed_form_keys);

void full_response(benchmark::State& state) {
  for (auto _ : state) {
    const HuntCrossleyImpact impact(mass, stiffness, exponent, damping, 1.0);
    benchmark::DoNotOptimize(impact.response());
  }
}
BENCHMARK(full_response)->Unit(benchmark::kMicrosecond);

void ode_integration(benchmark::State& state) {
  const ContactForceLaw law = [](double x, double v) {
    return stiffness * std::pow(x, exponent) * (1.0 + damping * v);
  };
  const double relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(integrate_impact(mass, 1.0, law, relative_tolerance));
}
// rtol 1e-10 and 1e-13, the latter what it takes the ODE to come within
// about 1e-12 of the closed form (see test_impact_ode): the "equal accuracy" comparison.
BENCHMARK(ode_integration)->Arg(10)->Arg(13)->Unit(benchmark::kMicrosecond);

} // namespace
