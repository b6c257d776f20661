// impact-reduced oscillator: amplitudes of the free decay of the Olshanskiy oscillator,
// m x'' + k x' + c1 x + c2 |x|^(v+1) sign(x) = 0, x(0) = -a0, x'(0) = 0, as a CSV table.

#include "commands.hpp"
#include "output.hpp"

#include "impact_reduced/oscillator.hpp"

namespace impact::cli {

int run_oscillator_command(CommandLine& options, std::ostream& out) {
  namespace reduced = impact::reduced;
  reduced::PowerLawOscillator oscillator{};
  oscillator.mass = options.real("mass", Range::positive());                     // kg
  oscillator.viscous_damping = options.real("viscous", Range::non_negative());   // N s/m
  oscillator.linear_stiffness = options.real("c1", Range::positive());           // N/m
  oscillator.nonlinear_stiffness = options.real("c2", Range::finite());          // N/m^(v+1)
  oscillator.power = options.real("power", Range::non_negative());               // -
  oscillator.initial_amplitude = options.real("a0", Range::positive());          // m
  const int count = static_cast<int>(options.integer("count", 1, reduced::max_extreme_count));
  const std::string method =
      options.choice("method", {"numeric", "implicit", "lambert", "lambert-approx"});
  // The table is the only output of this command; --format csv is accepted for uniformity.
  options.choice("format", {"csv"}, "csv");
  options.finish();

  std::vector<std::vector<double>> rows;
  if (method == "numeric") {
    for (const auto& extreme : reduced::free_decay_extremes(oscillator, count))
      rows.push_back({static_cast<double>(extreme.index), extreme.time, extreme.amplitude});
    print_csv(out, {"i", "time", "amplitude"}, rows);
  } else {
    const auto amplitudes = reduced::free_decay_amplitudes(
        oscillator, count, reduced::amplitude_method_from_name(method));
    for (std::size_t i = 0; i < amplitudes.size(); ++i)
      rows.push_back({static_cast<double>(i + 1), amplitudes[i]});
    print_csv(out, {"i", "amplitude"}, rows);
  }
  return 0;
}

} // namespace impact::cli
