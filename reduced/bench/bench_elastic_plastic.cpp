// Cost of one elastic-plastic impact, the unit of work of a calibration loop that fits p_y or
// Y: Thornton's closed forms, the same law through the generic quadrature, and the
// Jackson-Green law (loading work from its octave series, the work below x_max differenced
// term by term, x_max by TOMS 748, the compression time by Gauss-Kronrod above the Hertz
// piece, which is an incomplete Beta function).

#include "impact_reduced/sphere_flat_fits.hpp"
#include "impact_reduced/thornton.hpp"
#include "impact_reduced/contact_formulas.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace impact::reduced;

// Steel ball R = 10 mm (7800 kg/m^3) on steel, Y = 1 GPa; V = 10 V_y roughly.
const double mass = 4.0 / 3.0 * 3.14159265358979323846 * 1e-6 * 7800;
const SphereFlatContact steel{0.01, 2.1e11 / 1.82, 1e9, 0.3};
constexpr double velocity = 1.4;

void thornton_closed_form(benchmark::State& state) {
  double v = velocity;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        ThorntonImpact({mass, 0.01, steel.contact_modulus, 1.6e9}, v).response());
    v = v < 2 * velocity ? v * 1.001 : velocity;
  }
}
BENCHMARK(thornton_closed_form);

void thornton_quadrature(benchmark::State& state) {
  const ThorntonContact contact(0.01, steel.contact_modulus, 1.6e9);
  for (auto _ : state) benchmark::DoNotOptimize(elastic_plastic_impact(mass, velocity, contact));
}
BENCHMARK(thornton_quadrature)->Unit(benchmark::kMicrosecond);

void jackson_green_impact(benchmark::State& state) {
  const JacksonGreenContact contact(steel);
  for (auto _ : state) benchmark::DoNotOptimize(elastic_plastic_impact(mass, velocity, contact));
}
BENCHMARK(jackson_green_impact)->Unit(benchmark::kMicrosecond);

} // namespace
