// Linear Kelvin–Voigt (spring-dashpot) contact: F = k x + mu x'.
//
// Damping map: the half period of the damped linear oscillator, x(0) = 0, x'(0) = V, ends
// at t = pi / w_d with x' = -V exp(-zeta pi / sqrt(1 - zeta^2)), so the restitution is that
// exponential and mu = 2 zeta sqrt(k m) with zeta = -ln e / sqrt(pi^2 + ln^2 e) (the classical
// result, e.g. Goldsmith, Impact, 1960; the linear spring-dashpot of Cundall and Strack,
// Geotechnique 29, 1979). The map is exact, but the force jumps to mu V at first touch and
// is tensile, mu x' < 0, at separation: the known defect of the model.

#include "impact_reduced/comparison_laws.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "law_catalogue.hpp"

#include <cmath>
#include <string>

namespace impact::reduced {

double linear_oscillator_damping_ratio(double restitution) {
  if (!(restitution > 0 && restitution <= 1))
    throw InvalidInput("restitution", "restitution must be a number in (0, 1] (got " +
                                          std::to_string(restitution) + ")");
  if (restitution == 1) return 0.0;
  const double log_e = std::log(restitution);
  constexpr double pi = 3.14159265358979323846;
  return -log_e / std::sqrt(pi * pi + log_e * log_e);
}

namespace laws {

ComparisonLaw kelvin_voigt() {
  ComparisonLaw law;
  law.name = "kelvin-voigt";
  law.formula = "F = k x + mu x', mu = 2 zeta sqrt(k m), zeta = -ln e / sqrt(pi^2 + ln^2 e)";
  law.reference = "damped linear oscillator over its half period (Goldsmith 1960)";
  law.damping_name = "mu";
  law.damping_unit = "N s/m";
  law.required_exponent = 1.0;
  law.damping_for_restitution = [](double restitution, double, const ContactSetup& setup) {
    return 2 * linear_oscillator_damping_ratio(restitution) *
           std::sqrt(setup.stiffness * setup.mass);
  };
  law.force_law = [](double damping, const ContactSetup& setup) -> ContactForceLaw {
    const double stiffness = setup.stiffness;
    return [=](double x, double rate) { return stiffness * x + damping * rate; };
  };
  return law;
}

} // namespace laws
} // namespace impact::reduced
