// impact-reduced oscillator: amplitudes of the free decay of the Olshanskiy oscillator,
// m x'' + k x' + c1 x + c2 |x|^(v+1) sign(x) = 0, x(0) = -a0, x'(0) = 0, as a CSV table.

#include "commands.hpp"
#include "output.hpp"
#include "ranges.hpp"

#include "impact_reduced/oscillator.hpp"

namespace impact::cli {

namespace {

int run_oscillator(CommandLine& options, std::ostream& out) {
  namespace reduced = impact::reduced;
  reduced::PowerLawOscillator oscillator{};
  oscillator.mass = options.real("mass");
  oscillator.viscous_damping = options.real("viscous");
  oscillator.linear_stiffness = options.real("c1");
  oscillator.nonlinear_stiffness = options.real("c2");
  oscillator.power = options.real("power");
  oscillator.initial_amplitude = options.real("a0");
  const int count = static_cast<int>(options.integer("count"));
  const std::string method = options.choice("method");
  // The table is the only output of this command; --format csv is accepted for uniformity.
  options.choice("format");
  options.finish();

  std::vector<std::vector<double>> rows;
  if (method == "numeric") {
    for (const auto& extreme : reduced::free_decay_extremes(oscillator, count))
      rows.push_back({static_cast<double>(extreme.index), extreme.time, extreme.amplitude});
    print_csv(out, {"i", "time", "amplitude"}, rows);
  } else {
    const auto amplitudes =
        reduced::free_decay_amplitudes(oscillator, count,
                                       reduced::amplitude_method_from_name(method));
    for (std::size_t i = 0; i < amplitudes.size(); ++i)
      rows.push_back({static_cast<double>(i + 1), amplitudes[i]});
    print_csv(out, {"i", "amplitude"}, rows);
  }
  return 0;
}

} // namespace

Command oscillator_command() {
  return {"oscillator",
          "free decay of a damped oscillator with power-law stiffness (Olshanskiy)",
          "The successive amplitudes of the free decay of m x'' + k x' + c1 x + c2 |x|^(v+1) "
          "sign(x) = 0 from x(0) = -a0, x'(0) = 0: by numerical integration (numeric, with the "
          "times of the extremes) or by the averaged recurrences (implicit, lambert, "
          "lambert-approx).",
          {real_option("mass", "M", ranges::mass(), "mass m [kg]"),
           real_option("viscous", "K", ranges::viscous(),
                       "viscous damping k [N s/m]; the linear part must be underdamped"),
           real_option("c1", "C1", ranges::stiffness_c1(), "linear stiffness c1 [N/m]"),
           real_option("c2", "C2", ranges::stiffness_c2(),
                       "power-law stiffness c2 [N/m^(v+1)]: > 0 hardening, < 0 softening"),
           real_option("power", "NU", ranges::power(), "power v of the power-law term [-]"),
           real_option("a0", "A0", ranges::amplitude(), "initial deflection a0 [m]"),
           integer_option("count", "N", 1, reduced::max_extreme_count,
                          "number of amplitudes (extremes) to print"),
           choice_option("method", {"numeric", "implicit", "lambert", "lambert-approx"},
                         "how the amplitudes are computed"),
           choice_option("format", {"csv"},
                         "output format (a CSV table: i,time,amplitude for "
                         "numeric, i,amplitude otherwise)")
               .with_default("csv")},
          "",
          run_oscillator};
}

} // namespace impact::cli
