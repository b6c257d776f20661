// Olshanskiy oscillator: validation, the implicit recurrence and the explicit Lambert
// recurrences. The reference integration is in oscillator_numeric.cpp.

#include "impact_reduced/oscillator.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/special_functions/lambert_w.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

namespace impact::reduced {

namespace {

constexpr double pi = boost::math::constants::pi<double>();

std::string number(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

[[noreturn]] void reject(const char* parameter, const std::string& message) {
  throw InvalidInput(parameter, message);
}

void require_count(int count) {
  if (count < 1 || count > max_extreme_count)
    reject("count", "count must be a whole number in [1, " + std::to_string(max_extreme_count) +
                        "] (got " + std::to_string(count) + ")");
}

// The decay factor of a half-cycle of the linear oscillator with stiffness `stiffness`.
double linear_half_cycle_ratio(const PowerLawOscillator& o, double stiffness) {
  const double m = o.mass, k = o.viscous_damping;
  const double frequency = std::sqrt(stiffness / m - (k / (2 * m)) * (k / (2 * m)));
  return std::exp(-k * pi / (2 * m * frequency));
}

std::vector<double> linear_decay(const PowerLawOscillator& o, int count) {
  const double stiffness = o.linear_stiffness + (o.power == 0 ? o.nonlinear_stiffness : 0.0);
  const double ratio = linear_half_cycle_ratio(o, stiffness);
  std::vector<double> amplitudes(count);
  double amplitude = o.initial_amplitude;
  for (auto& a : amplitudes) a = amplitude *= ratio;
  return amplitudes;
}

// a_i = a_{i-1} r with r = exp(-k pi / (2 m omega(r))), solved for r in (0, 1].
std::vector<double> implicit_recurrence(const PowerLawOscillator& o, int count) {
  const double m = o.mass, k = o.viscous_damping, c2 = o.nonlinear_stiffness, v = o.power;
  const double w2 = o.linear_stiffness / m - (k / (2 * m)) * (k / (2 * m));
  const double alpha = averaging_coefficient(v);
  if (w2 + alpha * c2 * std::pow(o.initial_amplitude, v) / m <= 0)
    reject("a0", "a0 = " + number(o.initial_amplitude) +
                     " m is too large for the implicit recurrence with this softening c2: "
                     "the averaged frequency squared w_*^2 + alpha c2 a0^v / m must be > 0 (got " +
                     number(w2 + alpha * c2 * std::pow(o.initial_amplitude, v) / m) +
                     " 1/s^2); use the numeric method");
  std::vector<double> amplitudes(count);
  double amplitude = o.initial_amplitude;
  for (auto& a : amplitudes) {
    const double nonlinear = alpha * c2 * std::pow(amplitude, v) / m;
    // residual(r) = r - exp(-k pi / (2 m omega)): negative at r = 0, >= 0 at r = 1.
    auto residual = [&](double r) {
      const double omega = std::sqrt(w2 + nonlinear * std::pow((1 + r) / 2, v));
      return r - std::exp(-k * pi / (2 * m * omega));
    };
    const double at_zero = residual(0.0), at_one = residual(1.0);
    double ratio = 1.0;
    if (at_one > 0) {
      std::uintmax_t iterations = 200;
      const auto bracket =
          boost::math::tools::toms748_solve(residual, 0.0, 1.0, at_zero, at_one,
                                            boost::math::tools::eps_tolerance<double>(),
                                            iterations);
      ratio = (bracket.first + bracket.second) / 2;
    }
    a = amplitude *= ratio;
  }
  return amplitudes;
}

// The explicit Lambert recurrences of the spec, with the exact W0 or the elementary W.
std::vector<double> lambert_recurrence(const PowerLawOscillator& o, int count, bool elementary) {
  const double m = o.mass, k = o.viscous_damping, c2 = o.nonlinear_stiffness, v = o.power;
  const double w = damped_linear_frequency(o);
  const double alpha = averaging_coefficient(v);
  const double phase = k * pi / (2 * m * w); // k pi / (2 m w_*)
  const double c2s = std::pow((1 + std::exp(phase)) / 2, v) * c2;
  const double A = k * pi * alpha * v * std::abs(c2s) / ((2 * m) * (2 * m) * w * w * w);
  const double hardening = c2 > 0 ? 1.0 : -1.0;
  std::vector<double> amplitudes(count);
  double amplitude = o.initial_amplitude;
  for (std::size_t i = 0; i < amplitudes.size(); ++i) {
    // s = -exp(y_i) (hardening) or +exp(z_i) (softening); y_i = ln(A a^v) - k pi v/(2 m w_*).
    const double s = -hardening * A * std::pow(amplitude, v) * std::exp(-phase * v);
    if (!std::isfinite(s) || s < -std::exp(-1.0))
      reject("a0", "a0 = " + number(o.initial_amplitude) +
                       " m is too large for the explicit Lambert recurrence with this hardening "
                       "c2: at extreme " +
                       std::to_string(i + 1) + " the argument of W0, " + number(s) +
                       ", is below -1/e, where W0 has no real value; use the "
                       "implicit or numeric method");
    if (elementary && !(s >= -0.2 && s <= 0.3))
      reject("a0", "a0 = " + number(o.initial_amplitude) +
                       " m is too large for the elementary approximation of W with this c2: at "
                       "extreme " +
                       std::to_string(i + 1) + " its argument, " + number(s) +
                       ", is outside [-0.2, 0.3], where it is accurate to 0.22 %; use the "
                       "exact W (method lambert)");
    // W(s)/s: exp(-W0(s)) exactly, or the elementary formula divided by s.
    const double w_over_s = elementary ? 1 - s + 27 * s * s / (2 * (16 * s + 9))
                                       : std::exp(-boost::math::lambert_w0(s));
    amplitude *= std::exp(-phase) * std::pow(w_over_s, 1 / v);
    amplitudes[i] = amplitude;
  }
  return amplitudes;
}

} // namespace

void validate_oscillator(const PowerLawOscillator& o) {
  require_positive("mass", o.mass);
  require_non_negative("viscous", o.viscous_damping);
  require_positive("c1", o.linear_stiffness);
  require_finite("c2", o.nonlinear_stiffness);
  require_non_negative("power", o.power);
  require_positive("a0", o.initial_amplitude);
  const double m = o.mass, k = o.viscous_damping, c1 = o.linear_stiffness;
  const double c2 = o.nonlinear_stiffness, v = o.power;
  const double critical = 2 * std::sqrt(c1 * m);
  if (!(k < critical))
    reject("viscous", "viscous damping k must be below the critical damping 2 sqrt(c1 m) = " +
                          number(critical) + " N s/m of the linear part (got " + number(k) +
                          "): the oscillator must be underdamped");
  if (v == 0) {
    if (!(c1 + c2 > 0))
      reject("c2", "for power 0 the stiffness is c1 + c2, which must be > 0 (got c2 = " +
                       number(c2) + ", c1 = " + number(c1) + ")");
    const double linear_critical = 2 * std::sqrt((c1 + c2) * m);
    if (!(k < linear_critical))
      reject("viscous", "for power 0 the viscous damping k must be below 2 sqrt((c1 + c2) m) = " +
                            number(linear_critical) + " N s/m (got " + number(k) + ")");
  } else if (c2 < 0) {
    const double barrier = std::pow(c1 / -c2, 1 / v);
    if (!(o.initial_amplitude < barrier))
      reject("a0", "with softening (c2 < 0) a0 must be below (c1/|c2|)^(1/v) = " + number(barrier) +
                       " m, where the restoring force vanishes (got " +
                       number(o.initial_amplitude) + ")");
  }
}

double damped_linear_frequency(const PowerLawOscillator& o) {
  validate_oscillator(o);
  const double m = o.mass, k = o.viscous_damping;
  return std::sqrt(o.linear_stiffness / m - (k / (2 * m)) * (k / (2 * m)));
}

double averaging_coefficient(double power) {
  require_non_negative("power", power);
  return 2 / std::sqrt(pi) * boost::math::tgamma_ratio((power + 3) / 2, (power + 4) / 2);
}

double lambert_w0_elementary(double z) {
  if (!std::isfinite(z) || !(z >= -0.2 && z <= 0.3))
    reject("z",
           "the argument of the elementary approximation of W must be in [-0.2, 0.3] "
           "(got " +
               number(z) + ")");
  return z - z * z + 27 * z * z * z / (2 * (16 * z + 9));
}

std::vector<double> free_decay_amplitudes(const PowerLawOscillator& o, int count,
                                          AmplitudeMethod method) {
  validate_oscillator(o);
  require_count(count);
  if (method == AmplitudeMethod::numeric) {
    std::vector<double> amplitudes;
    for (const auto& extreme : free_decay_extremes(o, count))
      amplitudes.push_back(extreme.amplitude);
    return amplitudes;
  }
  if (o.power == 0 || o.nonlinear_stiffness == 0) return linear_decay(o, count);
  switch (method) {
    case AmplitudeMethod::implicit:
      return implicit_recurrence(o, count);
    case AmplitudeMethod::lambert:
      return lambert_recurrence(o, count, false);
    case AmplitudeMethod::lambert_approx:
      return lambert_recurrence(o, count, true);
    case AmplitudeMethod::numeric:
      break;
  }
  reject("method", "unknown amplitude method");
}

AmplitudeMethod amplitude_method_from_name(const std::string& name) {
  if (name == "numeric") return AmplitudeMethod::numeric;
  if (name == "implicit") return AmplitudeMethod::implicit;
  if (name == "lambert") return AmplitudeMethod::lambert;
  if (name == "lambert-approx") return AmplitudeMethod::lambert_approx;
  reject("method",
         "method must be one of numeric|implicit|lambert|lambert-approx (got '" + name + "')");
}

} // namespace impact::reduced
