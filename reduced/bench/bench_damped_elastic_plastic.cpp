// Cost of one impact under the damped elastic-plastic laws, the unit of work of a calibration
// that fits the damping and the yield parameter: Hunt-Crossley on an elastic-plastic spring
// (closed-form e and x_max; the response adds the force peak and the two time integrals) and
// Kuwabara-Kono on the same springs (integrated in the square root of the stretch,
// kuwabara_kono_stretch_root.hpp). Targets: closed-form e <= 1 us, full response <= 10 us
// for every spring, Kuwabara-Kono <= 20 us.
// Measured 2026-12-04 (CPU-time medians, machine at load 3-4): response 3.8 / 7.2 / 8.0 /
// 8.3 us (Hertz / Thornton / Jackson-Green / Ghaednia; the last two 10.3 / 10.7 us before the
// F(W) series of the octave table). Kuwabara-Kono, later that day at load 5.7 (branch
// kk-speed): 7.0 / 7.6 / 19.6 / 19.3 us, against 26.3 / 35.0 / 91.7 / 143 us for the former
// Cash-Karp integration in x and t run back to back; about 20 Fehlberg 7(8) steps, and on
// the fitted springs 185 evaluations of the table's F and dF/dx per impact. The fitted
// springs' figures reach 22-24 us when the machine's other jobs weigh more: met only narrowly.

#include "impact_reduced/ghaednia.hpp"
#include "impact_reduced/hertz_contact.hpp"
#include "impact_reduced/hunt_crossley_elastic_plastic.hpp"
#include "impact_reduced/kuwabara_kono_elastic_plastic.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "impact_reduced/thornton.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

namespace {

using namespace impact::reduced;

// Steel ball R = 10 mm (7800 kg/m^3) on steel, Y = 1 GPa; V = 1.4 m/s (about 10 V_y),
// beta = b V = 0.05.
const double mass = 4.0 / 3.0 * 3.14159265358979323846 * 1e-6 * 7800;
const SphereFlatContact steel{0.01, 2.1e11 / 1.82, 1e9, 0.3};
constexpr double velocity = 1.4;
constexpr double damping = 0.05 / velocity;
constexpr double dissipative_constant = 1e-7; // A [s]

std::shared_ptr<const ElasticPlasticContact> spring(int kind) {
  switch (kind) {
    case 0:
      return std::make_shared<HertzContact>(4.0 / 3.0 * steel.contact_modulus *
                                            std::sqrt(steel.radius));
    case 1:
      return std::make_shared<ThorntonContact>(steel.radius, steel.contact_modulus, 1.6e9);
    case 2:
      return std::make_shared<JacksonGreenContact>(steel);
    default:
      return std::make_shared<GhaedniaContact>(steel, 2.1e11, 0.02 * 2.1e11);
  }
}

const char* spring_name(int kind) {
  static const char* names[] = {"hertz", "thornton", "jackson_green", "ghaednia"};
  return names[kind];
}

// The closed forms alone: construction gives x_max and e.
void hunt_crossley_elastic_plastic_restitution(benchmark::State& state) {
  const auto contact = spring(static_cast<int>(state.range(0)));
  state.SetLabel(spring_name(static_cast<int>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(
        HuntCrossleyElasticPlasticImpact(mass, contact, damping, velocity).restitution());
}
BENCHMARK(hunt_crossley_elastic_plastic_restitution)
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMicrosecond);

void hunt_crossley_elastic_plastic_response(benchmark::State& state) {
  const auto contact = spring(static_cast<int>(state.range(0)));
  state.SetLabel(spring_name(static_cast<int>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(
        HuntCrossleyElasticPlasticImpact(mass, contact, damping, velocity).response());
}
BENCHMARK(hunt_crossley_elastic_plastic_response)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

void kuwabara_kono_elastic_plastic(benchmark::State& state) {
  const auto contact = spring(static_cast<int>(state.range(0)));
  state.SetLabel(spring_name(static_cast<int>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(
        kuwabara_kono_elastic_plastic_impact(mass, velocity, *contact, dissipative_constant));
}
BENCHMARK(kuwabara_kono_elastic_plastic)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

} // namespace
