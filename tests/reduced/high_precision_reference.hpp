#pragma once
// High-precision references for the accuracy tests of the reduced library (Lambert W and
// Hunt-Crossley impact). Everything here is computed in 50- or 100-digit arithmetic
// (Boost.Multiprecision cpp_bin_float) from the formulas of the spec
// (doc/theory/reduced-models.md, section 1) evaluated literally, with Boost.Math's own
// Lambert W, tanh-sinh quadrature and TOMS 748 -- never with the library's formulation
// (which works in double/quad precision with the branch-point equation -y - log(1 - y) = s
// and integrates over the approach rate).
//
// Inputs are doubles, converted exactly. Closed forms are evaluated in 100 digits (the
// Lambert W argument loses up to ~35 digits to the branch point in the ranges tested, so 100
// digits leave > 60), the time integrals in 50 digits.

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/lambert_w.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace hp {

using Real50 = boost::multiprecision::cpp_bin_float_50;
using Real100 = boost::multiprecision::cpp_bin_float_100;

// ---------------------------------------------------------------------------------------
// Error bookkeeping
// ---------------------------------------------------------------------------------------

/// |value - reference| / |reference| as a double; a non-finite value gives +infinity, and a
/// zero reference gives 0 for an exact zero and +infinity otherwise.
inline double relative_error(double value, const Real100& reference) {
  if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
  if (reference == 0) return value == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  return static_cast<double>(abs((Real100(value) - reference) / reference));
}

inline std::string format(const char* pattern, double a) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a);
  return buffer;
}

/// The worst relative error of one quantity over a sweep, where it occurred, and how many
/// points missed the target.
struct WorstError {
  std::string quantity;
  double target;
  double error = 0.0;
  std::string where = "(no point)";
  int points = 0;
  int failures = 0;

  WorstError(std::string name, double target_) : quantity(std::move(name)), target(target_) {}

  void update(double e, const std::string& input) {
    if (std::isnan(e)) e = std::numeric_limits<double>::infinity();
    ++points;
    if (!(e <= target)) ++failures;
    if (points == 1 || e > error) {
      error = e;
      where = input;
    }
  }
  bool passed() const { return failures == 0; }
  std::string summary() const {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, "%-34s worst %.3e (target %.1e) %s over %d points, at %s",
                  quantity.c_str(), error, target, passed() ? "PASS" : "FAIL", points,
                  where.c_str());
    std::string text = buffer;
    if (!passed()) text += "  [" + std::to_string(failures) + " points above target]";
    return text;
  }
};

/// Prints the sweep's worst error and records it as a test property.
inline void report(const WorstError& worst) {
  std::cout << "  " << worst.summary() << "\n";
  ::testing::Test::RecordProperty(worst.quantity + " worst relative error",
                                  format("%.3e", worst.error) + " at " + worst.where);
}

/// report(), and a test failure if any point of the sweep missed the target.
inline void expect_target(const WorstError& worst) {
  report(worst);
  EXPECT_TRUE(worst.passed()) << worst.quantity << ": worst relative error " << worst.error
                              << " exceeds the target " << worst.target << " at " << worst.where
                              << " (" << worst.failures << " of " << worst.points
                              << " points above target)";
}

// ---------------------------------------------------------------------------------------
// Lambert W
// ---------------------------------------------------------------------------------------

/// The branch-point series alone (used above, and cross-checked against Boost's W).
inline Real100 one_plus_w_series(const Real100& s, bool principal) {
  Real100 p = sqrt(-2 * expm1(-s));
  if (!principal) p = -p;
  const Real100 c3 = Real100(11) / 72, c4 = Real100(43) / 540, c5 = Real100(769) / 17280,
                c6 = Real100(221) / 8505;
  return p * (1 + p * (-Real100(1) / 3 + p * (c3 + p * (-c4 + p * (c5 - p * c6)))));
}

/// 1 + W(-exp(-1 - s)) for s >= 0 (principal branch: W0, else W-1), to ~60 digits.
/// For s < 1e-30 the argument cannot be formed close enough to -1/e even in 100 digits;
/// there the branch-point series of W (Corless et al.) in p = +-sqrt(2 (1 + e z)),
/// 1 + e z = 1 - exp(-s), is used, truncated after p^6 (relative error ~ p^6 < 1e-88).
/// Elsewhere Boost's W of the literal argument in 100 digits (relative error ~ 1e-100 / s).
inline Real100 one_plus_w_reference(const Real100& s, bool principal) {
  if (s == 0) return Real100(0);
  if (s < Real100(1e-30)) return one_plus_w_series(s, principal);
  const Real100 z = -exp(-1 - s);
  return 1 + (principal ? boost::math::lambert_w0(z) : boost::math::lambert_wm1(z));
}

// ---------------------------------------------------------------------------------------
// Hunt-Crossley impact: closed forms
// ---------------------------------------------------------------------------------------

/// k(beta) = (1 + W0(-(1 + beta) exp(-(1 + beta)))) / beta, literally (100 digits by default).
template <class Real = Real100>
Real restitution_reference(const Real& beta) {
  const Real a = 1 + beta;
  const Real z = -a * exp(-a);
  return (1 + boost::math::lambert_w0(z)) / beta;
}

/// beta with k(beta) = restitution, restitution in (0, 1): TOMS 748 on log(beta) in 100
/// digits (k is decreasing; k(beta) < 1/beta and k ~ 1 - 2 beta / 3 bracket the root).
inline Real100 impact_parameter_reference(double restitution) {
  const Real100 k = restitution;
  auto residual = [&](const Real100& log_beta) {
    return restitution_reference<Real100>(exp(log_beta)) - k;
  };
  const Real100 lower = log((1 - k) / 4);
  const Real100 upper = log(4 / k + 1);
  if (!(residual(lower) > 0 && residual(upper) < 0))
    throw std::runtime_error("impact_parameter_reference: root not bracketed");
  std::uintmax_t iterations = 300;
  const auto [low, high] =
      boost::math::tools::toms748_solve(residual, lower, upper,
                                        boost::math::tools::eps_tolerance<Real100>(250),
                                        iterations);
  return exp((low + high) / 2);
}

/// Parameters of one impact (exact doubles): power law f = c x^n.
struct ImpactInput {
  double mass;
  double stiffness;
  double exponent;
  double damping;
  double velocity;

  std::string describe() const {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, "beta=%.6g (b=%.17g, V=%.17g), n=%g", damping * velocity,
                  damping, velocity, exponent);
    return buffer;
  }
};

/// All reference quantities of one impact.
struct ImpactReference {
  Real100 beta;
  Real100 approach_max;
  Real100 restitution;
  Real100 rebound_velocity;
  Real100 force_max;
  Real100 time_force_max;
  Real100 approach_at_peak;
  Real100 rate_at_peak;
  Real100 compression_time;
  Real100 contact_time;
  /// Largest relative error estimate (error / L1) of the tanh-sinh quadratures.
  double quadrature_error = 0.0;
};

/// Hertz (b = 0) closed forms: energy conservation, and the time by the Beta function,
/// t_c = 2 (x_max / V) (1/p) B(1/p, 1/2), p = n + 1.
inline ImpactReference hertz_reference(const ImpactInput& in) {
  const Real100 m = in.mass, c = in.stiffness, n = in.exponent, V = in.velocity;
  const Real100 p = n + 1;
  ImpactReference r;
  r.beta = 0;
  r.approach_max = pow(p * m * V * V / (2 * c), 1 / p);
  r.restitution = 1;
  r.rebound_velocity = -V;
  const Real50 p50 = Real50(p);
  const Real100 beta_function = Real100(boost::math::beta(Real50(1 / p50), Real50(0.5)));
  r.contact_time = 2 * (r.approach_max / V) * beta_function / p;
  r.compression_time = r.contact_time / 2;
  r.force_max = c * pow(r.approach_max, n);
  r.time_force_max = r.compression_time;
  r.approach_at_peak = r.approach_max;
  r.rate_at_peak = 0;
  return r;
}

/// X(t) = exp(t) - 1 - t without cancellation: series for |t| < 1/8, else literal.
template <class Real>
Real expm1_excess(const Real& t) {
  if (abs(t) >= Real(0.125)) return Real(expm1(t) - t);
  Real term = t * t / 2, sum = 0;
  for (int k = 3; abs(term) > abs(sum) * std::numeric_limits<Real>::epsilon() / 4; ++k) {
    sum += term;
    term *= t / k;
  }
  return sum;
}

/// The tanh-sinh integrator in 50 digits, shared (its abscissa tables are expensive).
inline boost::math::quadrature::tanh_sinh<Real50>& quadrature50() {
  static boost::math::quadrature::tanh_sinh<Real50> integrator(15, Real50(1e-300));
  return integrator;
}

/// The Hunt-Crossley reference for b > 0 (b = 0: hertz_reference).
///
/// Times use the spec's w-parametrisation written in psi = ln(-w) (w = -exp(psi)), which
/// turns dt = (m/b) dw / (-w f) into dt = (m/b) |d psi| / f: psi runs from
/// psi_in = ln(1 + beta) (first contact) down through 0 (x_max) to psi_out = ln(-w_out)
/// (separation). With E = b^2 P / m = psi - exp(psi) + 1 + beta - ln(1 + beta), the energy is
/// formed from the distance delta to the singular end of each phase, exactly:
///   compression, psi = psi_in - delta:   E = -(1 + beta) expm1(-delta) - delta
///   restitution, psi = psi_out + delta:  E = delta - a expm1(delta),  a = -w_out = 1 - y
/// (using psi_out + w_out = ln(1 + beta) - 1 - beta), rearranged as
///   E = -beta expm1(-delta) - X(-delta)  and  E = y expm1(delta) - X(delta),
/// X(t) = expm1(t) - t, so that E also keeps its digits at tiny beta, where the two terms of
/// the literal forms cancel to a relative 1/beta (the restitution phase keeps the literal
/// form when y > 1/2, where the rearranged one would cancel instead). The log variable keeps
/// the restitution integrand smooth when w_out is tiny (large beta: w_out ~ -1e-432 at 1e3).
/// The force peak: dF/dt = 0 <=> m f' v = b f^2, which for the power law and v = -(1+w)/b
/// reads (n + 1) E = n (exp(psi) - 1); solved by TOMS 748 in delta (100 digits).
/// `with_times` = false skips the quadratures (times left at 0): closed forms and peak only.
inline ImpactReference hunt_crossley_reference(const ImpactInput& in, bool with_times = true) {
  if (in.damping == 0) return hertz_reference(in);
  using boost::math::tools::eps_tolerance;
  using boost::math::tools::toms748_solve;
  const Real100 m = in.mass, c = in.stiffness, n = in.exponent, b = in.damping, V = in.velocity;
  const Real100 p = n + 1;
  ImpactReference r;
  const Real100 beta = b * V; // exact: 106 bits < 333
  r.beta = beta;
  const Real100 z0 = -(1 + beta) * exp(-(1 + beta));
  const Real100 w_out = boost::math::lambert_w0(z0);
  const Real100 y = 1 + w_out;
  r.restitution = y / beta;
  r.rebound_velocity = -y / b;
  // P(x_max) = (m / b^2) (beta - ln(1 + beta)), power law.
  r.approach_max = pow(p * m / (c * b * b) * (beta - log1p(beta)), 1 / p);

  const Real100 psi_in = log1p(beta);
  const Real100 psi_out = psi_in - 1 - beta - w_out;

  // Force peak, in delta = psi_in - psi in (0, psi_in).
  auto energy_compression100 = [&](const Real100& delta) {
    return -(1 + beta) * expm1(-delta) - delta;
  };
  auto peak_condition = [&](const Real100& delta) {
    return (n + 1) * energy_compression100(delta) - n * expm1(psi_in - delta);
  };
  std::uintmax_t iterations = 300;
  const auto [low, high] = toms748_solve(peak_condition, Real100(0), psi_in, -n * beta,
                                         (n + 1) * energy_compression100(psi_in),
                                         eps_tolerance<Real100>(250), iterations);
  const Real100 delta_peak = (low + high) / 2;
  const Real100 psi_peak = psi_in - delta_peak;
  const Real100 energy_peak = energy_compression100(delta_peak);
  r.approach_at_peak = pow(p * m * energy_peak / (c * b * b), 1 / p);
  r.force_max = exp(psi_peak) * c * pow(r.approach_at_peak, n); // F = -w f(x)
  r.rate_at_peak = expm1(psi_peak) / b;                         // v = -(1 + w) / b

  if (!with_times) return r;

  // Time integrals in 50 digits.
  const Real50 m50(m), c50(c), n50(n), b50(b), p50(p), beta50(beta);
  const Real50 y50(y), a50(-w_out);
  const Real50 time_scale = m50 / b50;
  const Real50 energy_to_xp = p50 * m50 / (c50 * b50 * b50); // x^p = energy_to_xp * E
  auto force_of_energy = [&](const Real50& energy) {
    const Real50 x = pow(energy_to_xp * energy, 1 / p50);
    return c50 * pow(x, n50);
  };
  // E = beta (1 - e^-delta) - (e^-delta - 1 + delta) = y expm1(delta) - (expm1(delta) - delta):
  // the O(delta^2) parts taken by series, so that E keeps all digits also at tiny beta.
  auto compression_density = [&](const Real50& delta) {
    const Real50 energy = -beta50 * expm1(-delta) - expm1_excess(Real50(-delta));
    return time_scale / force_of_energy(energy);
  };
  auto restitution_density = [&](const Real50& delta) {
    // y expm1(delta) - X(delta) cancels when y -> 1 (large beta); then the literal
    // delta - a expm1(delta), a = -w_out <= 1/2, has no cancellation.
    const Real50 energy = y50 <= 0.5 ? Real50(y50 * expm1(delta) - expm1_excess(delta))
                                     : Real50(delta - a50 * expm1(delta));
    return time_scale / force_of_energy(energy);
  };
  auto& quadrature = quadrature50();
  const Real50 tolerance = 1e-32;
  // Each integral returns its value and its absolute error estimate; the reported quality is
  // the estimate relative to the time it contributes to (a piece may be tiny: for small beta
  // the force peak lies within ~beta^2 of x_max). Integrated over u in [0, 1], delta = lower + (upper - lower) u (scale-free: for small
  // beta the intervals are ~beta wide), with the two-argument form of tanh_sinh: uc = -u in
  // the left half, 1 - u in the right half, so delta next to either end is formed from the
  // exact complement.
  auto integrate = [&](auto density, const Real50& lower, const Real50& upper, Real50& error) {
    const Real50 width = upper - lower;
    // The tails within 1e-200 of an end are dropped (with integrands ~ u^(-n/(n+1)), n <= 2.5,
    // they weigh < 1e-57 relative): there the abscissas reach ~1e-646000000 and E underflows.
    auto integrand = [&](const Real50&, const Real50& uc) {
      if (abs(uc) < Real50(1e-200)) return Real50(0);
      return width * density(uc <= 0 ? Real50(lower - width * uc) : Real50(upper - width * uc));
    };
    Real50 l1 = 0;
    error = 0;
    const Real50 value =
        quadrature.integrate(integrand, Real50(0), Real50(1), tolerance, &error, &l1);
    if (std::getenv("HP_VERBOSE"))
      std::cout << "    quadrature [" << lower << ", " << upper << "]: " << value << " +- " << error
                << "\n";
    return value;
  };
  Real50 error_peak, error_to_max, error_restitution;
  const Real50 to_peak = integrate(compression_density, Real50(0), Real50(delta_peak), error_peak);
  const Real50 peak_to_max =
      integrate(compression_density, Real50(delta_peak), Real50(psi_in), error_to_max);
  const Real50 restitution =
      integrate(restitution_density, Real50(0), Real50(-psi_out), error_restitution);
  r.time_force_max = Real100(to_peak);
  r.compression_time = Real100(to_peak) + Real100(peak_to_max);
  r.contact_time = r.compression_time + Real100(restitution);
  r.quadrature_error = static_cast<double>(std::max(
      {error_peak / to_peak, (error_peak + error_to_max) / (to_peak + peak_to_max),
       (error_peak + error_to_max + error_restitution) / (to_peak + peak_to_max + restitution)}));
  return r;
}

/// The approach rate v(x) by the spec's closed form, literally in 100 digits:
///   g = ln(1 + beta) - 1 - beta + (b^2/m) P(x),  v = -(1/b) (1 + W(-exp(g))),
/// W-1 while compressing, W0 while restoring; b = 0: +-V sqrt(1 - P(x) / (m V^2 / 2)).
/// Empty when x lies beyond x_max (no real solution).
inline std::optional<Real100> approach_rate_reference(const ImpactInput& in, double approach,
                                                      bool compression) {
  const Real100 m = in.mass, c = in.stiffness, n = in.exponent, b = in.damping, V = in.velocity,
                x = approach;
  const Real100 potential = c * pow(x, n + 1) / (n + 1);
  if (in.damping == 0) {
    const Real100 remaining = 1 - potential / (m * V * V / 2);
    if (remaining < 0) return std::nullopt;
    const Real100 speed = V * sqrt(remaining);
    return compression ? speed : Real100(-speed);
  }
  const Real100 beta = b * V;
  const Real100 g = log1p(beta) - 1 - beta + b * b / m * potential;
  if (g > -1) return std::nullopt;
  const Real100 z = -exp(g);
  const Real100 w = compression ? boost::math::lambert_wm1(z) : boost::math::lambert_w0(z);
  return Real100(-(1 + w) / b);
}

} // namespace hp
