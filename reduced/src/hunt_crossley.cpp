#include "impact_reduced/hunt_crossley.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "branch_point.hpp"
#include "gauss_jacobi.hpp"
#include "hunt_crossley_phases.hpp"
#include "phase_time_map.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/lambert_w.hpp>
#include <boost/math/tools/roots.hpp>

#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace impact::reduced {

namespace {

using detail::branch_ratio;
using detail::log1p_excess_ratio;

constexpr double epsilon = std::numeric_limits<double>::epsilon();

// Both phase integrals have an integrable power singularity at u = 0 (the ends of the
// contact, where f(x) -> 0) and none elsewhere: double-exponential quadrature, which also
// keeps the abscissas next to a lower limit of 0 exact.
double integrate_density(const std::function<double(double)>& density, double lower, double upper) {
  if (upper <= lower) return 0.0;
  // (Not const: Boost 1.74 declares integrate const but defines the one-argument form without.)
  thread_local boost::math::quadrature::tanh_sinh<double> quadrature;
  return quadrature.integrate([&](double u) { return density(u); }, lower, upper, 1e-14);
}

// A piece [lower, upper] with lower > 0 between breakpoints, where the density is smooth but
// may still feel the singularity at u = 0 (a piece that starts at a breakpoint close to 0):
// adaptive Gauss-Kronrod 15/31 in s = ln u, where that singularity is at s = -infinity, to a
// relative error estimate |K31 - G15| of 1e-12 (K31 itself is far closer; the tests find the
// times within a few ulps of the 50-digit references).
double integrate_smooth_piece(const std::function<double(double)>& density, double lower,
                              double upper) {
  if (upper <= lower) return 0.0;
  const auto integrand = [&](double s) {
    const double u = std::exp(s);
    return density(u) * u;
  };
  const double from = std::log(lower), to = std::log(upper);
  if (to - from < 0.25) {
    // A short piece (from the force peak to x_max at small beta): 15 points usually meet the
    // same estimate; else the 31-point rule as below.
    double error = 0;
    const double quick =
        boost::math::quadrature::gauss_kronrod<double, 15>::integrate(integrand, from, to, 0, 0.0,
                                                                      &error);
    if (error <= 1e-12 * std::abs(quick)) return quick;
  }
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, from, to, 15,
                                                                       1e-12);
}

// The integral over [lower, upper] (lower > 0), split at the ascending `breaks` inside.
double integrate_between(const std::function<double(double)>& density, double lower, double upper,
                         const std::vector<double>& breaks) {
  double integral = 0;
  for (const double end : breaks) {
    if (end <= lower) continue;
    if (end >= upper) break;
    integral += integrate_smooth_piece(density, lower, end);
    lower = end;
  }
  return integral + integrate_smooth_piece(density, lower, upper);
}

// The integral over [0, upper], split at the ascending `breaks` inside: the first piece, with
// the singularity at u = 0, by tanh-sinh, the others by integrate_smooth_piece.
double integrate_from_zero(const std::function<double(double)>& density, double upper,
                           const std::vector<double>& breaks) {
  if (!(upper > 0)) return 0.0;
  const double first = breaks.empty() ? upper : std::min(breaks.front(), upper); // > 0
  return integrate_density(density, 0.0, first) + integrate_between(density, first, upper, breaks);
}

// (t - log(1 + t)) / t^2 in quadruple precision (series near t = 0).
__float128 quad_log1p_excess_ratio(__float128 t) {
  if (fabsq(t) < 0.25) return detail::small_branch_excess_ratio<__float128, 22>(-t);
  return (t - log1pq(t)) / (t * t);
}

double velocity_work(double damping, double lower, double width) {
  return width * detail::velocity_work_per_width(damping, lower, width);
}

// The Gauss-Jacobi fast path integrates the smooth factor g of the time density exactly
// for polynomials of degree < 2 * 24. g is analytic with its nearest singularity where
// 1 + b v = 0, about 1/b beyond the phase: far enough for beta <= 1 (the accuracy tests
// check 1e-13 there); larger beta takes the adaptive double-exponential rule.
constexpr int singular_rule_points = 24;
// On a first piece of a custom law no longer than a quarter of its phase, the nearest
// singularity of g lies at least four times as far, relative to the piece, as for the whole
// phase: 12 points reach what 24 reach there.
constexpr int short_piece_rule_points = 12;
constexpr double singular_rule_beta_limit = 1.0;

} // namespace

namespace detail {

// Integral of t / (1 + b t) over [lower, lower + width], t > -1/b: the kinetic-energy-like
// work per unit mass between two approach rates [m^2/s^2]. Written relative to the lower
// limit so that it is exact (no cancellation) for small widths:
//   u lower / a + u^2 sigma(r) / a^2,   a = 1 + b lower,  r = b u / a,
//   sigma(r) = (r - log(1 + r)) / r^2.
double velocity_work_per_width(double damping, double lower, double width) {
  const double scale = 1.0 + damping * lower;
  const double ratio = damping * width / scale;
  return lower / scale + width * log1p_excess_ratio(ratio) / (scale * scale);
}

// For ascending targets tau_j, the u_j in [0, upper] with integral_0^u_j density = tau_j.
// Newton's method (the derivative is the density itself) safeguarded by bisection within
// [u_(j-1), upper], integrating only from the previous root.
std::vector<double> invert_cumulative_integral(const std::function<double(double)>& density,
                                               const std::vector<double>& targets, double upper) {
  std::vector<double> roots;
  roots.reserve(targets.size());
  double previous_root = 0.0;
  double previous_target = 0.0;
  for (const double target : targets) {
    auto equation = [&](double u) {
      const double increment = integrate_density(density, previous_root, u);
      return std::make_pair(previous_target + increment - target, density(u));
    };
    // Start from the local slope at the previous root (a first-order step); from the
    // singular end, where the slope is infinite, from the middle of the bracket.
    double guess = 0.5 * (previous_root + upper);
    if (previous_root > 0.0) {
      const double step = (target - previous_target) / density(previous_root);
      if (step > 0.0 && previous_root + step < upper) guess = previous_root + step;
    }
    boost::uintmax_t iterations = 100;
    const double root =
        boost::math::tools::newton_raphson_iterate(equation, guess, previous_root, upper,
                                                   std::numeric_limits<double>::digits - 6,
                                                   iterations);
    previous_target = target;
    previous_root = root;
    roots.push_back(root);
  }
  return roots;
}

} // namespace detail

using detail::velocity_work_per_width;

namespace {
// k = y / beta with S(y) = S(-beta) on the principal branch; in the ratio form
// y = p branch_ratio(p), p = beta sqrt(2 sigma), sigma = S(-beta) / beta^2, which is exact
// at beta -> 0.
double restitution_from_excess_ratio(double beta, double excess_ratio) {
  const double amplitude = std::sqrt(2.0 * excess_ratio);
  return amplitude * branch_ratio(beta * amplitude);
}
} // namespace

double restitution_from_impact_parameter(double beta) {
  require_non_negative("beta", beta);
  return restitution_from_excess_ratio(beta, log1p_excess_ratio(beta));
}

double impact_parameter_from_restitution(double restitution) {
  if (!std::isfinite(restitution) || !(restitution > 0 && restitution <= 1)) {
    std::ostringstream message;
    message.precision(17);
    message << "restitution must be a finite number in (0, 1] (got " << restitution << ")";
    throw InvalidInput("restitution", message.str());
  }
  if (restitution == 1.0) return 0.0;
  const double shortfall = 1.0 - restitution; // exact (Sterbenz) for restitution >= 1/2
  boost::uintmax_t iterations = 200;
  const auto tolerance = boost::math::tools::eps_tolerance<double>();
  if (shortfall < 0.05) {
    // Near k = 1 the map k(beta) is flat and k - e cancels. Expand S(k beta) = S(-beta):
    //   sum_{j>=2} beta^(j-2) ((-1)^j - k^j) / j = 0,
    // with 1 - k^j = -expm1(j log1p(-shortfall)) exact; beta < 0.08 here, so the series
    // converges by a factor beta per term.
    const double log_restitution = std::log1p(-shortfall);
    auto residual = [&](double beta) {
      double sum = 0.0;
      double power = 1.0; // beta^(j-2)
      for (int j = 2; j < 60; ++j) {
        const double k_power_deficit = -std::expm1(j * log_restitution); // 1 - k^j
        const double numerator = (j % 2 == 0) ? k_power_deficit : -(2.0 - k_power_deficit);
        const double term = power * numerator / j;
        sum += term;
        if (std::fabs(term) < 1e-18 * std::fabs(sum)) break;
        power *= beta;
      }
      return sum;
    };
    const double guess = 1.5 * shortfall;
    const auto [low, high] = boost::math::tools::toms748_solve(residual, 0.5 * guess, 2.0 * guess,
                                                               tolerance, iterations);
    return 0.5 * (low + high);
  }
  // Elsewhere k(beta) is steep enough: solve k(beta) = e on log(beta), with k ~ 1/beta
  // for large beta bracketing the root.
  auto residual = [&](double log_beta) {
    return restitution_from_impact_parameter(std::exp(log_beta)) - restitution;
  };
  const double lower = std::log(0.5 * shortfall);
  const double upper = std::log(2.0 / restitution);
  const auto [low, high] =
      boost::math::tools::toms748_solve(residual, lower, upper, tolerance, iterations);
  return std::exp(0.5 * (low + high));
}

double damping_from_restitution(double restitution, double velocity) {
  require_positive("velocity", velocity);
  return impact_parameter_from_restitution(restitution) / velocity;
}

HuntCrossleyImpact::HuntCrossleyImpact(double mass, double stiffness, double exponent,
                                       double damping, double velocity)
    : HuntCrossleyImpact(mass, nullptr, damping, velocity, PowerLawForce(stiffness, exponent)) {}

HuntCrossleyImpact::HuntCrossleyImpact(double mass,
                                       std::shared_ptr<const ElasticForce> elastic_force,
                                       double damping, double velocity)
    : HuntCrossleyImpact(mass, std::move(elastic_force), damping, velocity, std::nullopt) {}

HuntCrossleyImpact::HuntCrossleyImpact(double mass,
                                       std::shared_ptr<const ElasticForce> custom_force,
                                       double damping, double velocity,
                                       std::optional<PowerLawForce> power_law)
    : mass_(mass),
      power_law_(std::move(power_law)),
      custom_force_(std::move(custom_force)),
      damping_(damping),
      velocity_(velocity) {
  require_positive("mass", mass);
  require_non_negative("damping", damping);
  require_positive("velocity", velocity);
  if (!power_law_) {
    if (!custom_force_) throw InvalidInput("elastic_force", "elastic_force must not be null");
    if (const auto* power = dynamic_cast<const PowerLawForce*>(custom_force_.get()))
      power_law_ = *power;
  }
  if (!std::isfinite(damping * velocity))
    throw InvalidInput("damping", "damping * velocity overflows");
  excess_ratio_ = log1p_excess_ratio(impact_parameter());
  // P(x_max) = (m / b^2) (beta - ln(1 + beta)) = m V^2 sigma(beta).
  approach_max_ =
      elastic_force().approach_at_potential(mass_ * velocity_ * velocity_ * excess_ratio_);
  restitution_ = restitution_from_excess_ratio(impact_parameter(), excess_ratio_);
  if (impact_parameter() > 1.0) {
    // psi_out = -log(-w_out) = 1 + s0 + w_out with w_out = W0(-exp(-1 - s0)); exp(-psi_out)
    // = -w_out. Both stay exact when 1 + b v_out = -w_out is far below double precision.
    const double s0 = detail::log1p_excess(impact_parameter());
    const double w_out = boost::math::lambert_w0(-std::exp(-1.0 - s0));
    restitution_in_log_rate_ = true;
    log_rate_in_ = std::log1p(impact_parameter());
    log_rate_span_ = 1.0 + s0 + w_out;
    separation_force_factor_ = -w_out;
  }
  if (!power_law_) {
    initial_power_law_ = elastic_force().initial_power_law();
    for (const double breakpoint : elastic_force().breakpoints()) {
      if (!(breakpoint > 0 && breakpoint < approach_max_)) continue;
      compression_breaks_.push_back(velocity_ -
                                    approach_rate(breakpoint, ImpactPhase::compression));
      const double rate = approach_rate(breakpoint, ImpactPhase::restitution);
      restitution_breaks_.push_back(restitution_in_log_rate_
                                        ? log_rate_span_ + std::log1p(damping_ * rate)
                                        : rate - rebound_velocity());
    }
    std::sort(compression_breaks_.begin(), compression_breaks_.end());
    std::sort(restitution_breaks_.begin(), restitution_breaks_.end());
  }
}

double HuntCrossleyImpact::energy_loss() const {
  return 0.5 * mass_ * velocity_ * velocity_ * (1.0 - restitution_) * (1.0 + restitution_);
}

double HuntCrossleyImpact::force(double approach, double approach_rate) const {
  return elastic_force().force(approach) * (1.0 + damping_ * approach_rate);
}

double HuntCrossleyImpact::approach_rate(double approach, ImpactPhase phase) const {
  if (!std::isfinite(approach) || approach < 0 || approach > approach_max_ * (1 + 4 * epsilon)) {
    std::ostringstream message;
    message.precision(17);
    message << "approach must be in [0, x_max = " << approach_max_ << "] m (got " << approach
            << ")";
    throw InvalidInput("approach", message.str());
  }
  // Twice the remaining energy per unit mass, 2 (P(x_max) - P(x)) / m. Close to x_max this
  // difference cancels; for the power law it is formed in quadruple precision, which keeps
  // v(x) exact to 1e-12 down to x_max - x = 1e-10 x_max and beyond.
  double energy_twice;
  if (power_law_) {
    const __float128 beta = __float128(damping_) * __float128(velocity_);
    const __float128 speed = velocity_;
    const __float128 exponent = power_law_->exponent();
    const __float128 potential_per_mass = __float128(power_law_->stiffness()) *
                                          powq(__float128(approach), exponent + 1) /
                                          ((exponent + 1) * __float128(mass_));
    energy_twice = static_cast<double>(
        2 * (speed * speed * quad_log1p_excess_ratio(beta) - potential_per_mass));
  } else {
    energy_twice =
        2.0 * (velocity_ * velocity_ * excess_ratio_ - elastic_force().potential(approach) / mass_);
  }
  const double speed = std::sqrt(std::max(energy_twice, 0.0));
  // v = -y / b with y = p branch_ratio(p), p = -+ b speed (lower branch while compressing).
  if (phase == ImpactPhase::compression) return speed * branch_ratio(-damping_ * speed);
  return -speed * branch_ratio(damping_ * speed);
}

double HuntCrossleyImpact::compression_energy(double distance) const {
  return velocity_work(damping_, velocity_ - distance, distance);
}

double HuntCrossleyImpact::restitution_energy(double distance) const {
  if (!restitution_in_log_rate_) return -velocity_work(damping_, rebound_velocity(), distance);
  // P b^2 / m = u - exp(-psi_out) expm1(u), written without overflow for large u.
  const double decayed = distance < 1.0
                             ? separation_force_factor_ * std::expm1(distance)
                             : std::exp(distance - log_rate_span_) - separation_force_factor_;
  return (distance - decayed) / (damping_ * damping_);
}

double HuntCrossleyImpact::restitution_rate(double distance) const {
  if (!restitution_in_log_rate_) return rebound_velocity() + distance;
  return std::expm1(distance - log_rate_span_) / damping_; // v = (exp(-psi) - 1) / b
}

double HuntCrossleyImpact::restitution_span() const {
  return restitution_in_log_rate_ ? log_rate_span_ : -rebound_velocity();
}

// dt = -m dv / ((1 + b v) f(x(v))): Newton's law, with x(v) from the energy balance.
double HuntCrossleyImpact::compression_time_density(double distance) const {
  const double elastic = elastic_force().force_at_potential(mass_ * compression_energy(distance));
  return mass_ / ((1.0 + damping_ * (velocity_ - distance)) * elastic);
}

double HuntCrossleyImpact::restitution_time_density(double distance) const {
  const double elastic = elastic_force().force_at_potential(mass_ * restitution_energy(distance));
  // dt = -m dv / ((1 + b v) f) = (m / b) dpsi / f.
  if (restitution_in_log_rate_) return mass_ / (damping_ * elastic);
  return mass_ / ((1.0 + damping_ * restitution_rate(distance)) * elastic);
}

bool HuntCrossleyImpact::uses_singular_rule() const {
  return power_law_.has_value() && impact_parameter() <= singular_rule_beta_limit;
}

// For f = c x^n the energy per mass E(u) = u e(u) with e smooth and e(0) > 0, and
//   dt/du = m / ((1 + b v) c^(1/(n+1)) ((n+1) m E)^alpha) = K u^-alpha g(u),
//   alpha = n / (n + 1),  g = e(u)^-alpha / (1 + b v),
// so the end-point singularity is exactly the Jacobi weight.
// A custom law that is c x^n below its first breakpoint has this form on its first piece.
double HuntCrossleyImpact::singular_rule_time(ImpactPhase phase, double distance,
                                              const PowerLawCoefficients& law) const {
  if (distance <= 0) return 0.0;
  const double exponent = law.exponent;
  const double alpha = exponent / (exponent + 1);
  // A custom law's first piece no longer than a quarter of its phase: the shorter rule.
  const double extent = phase == ImpactPhase::compression ? velocity_ : restitution_span();
  const int points =
      !power_law_ && distance <= 0.25 * extent ? short_piece_rule_points : singular_rule_points;
  const auto& rule = detail::gauss_jacobi_rule(points, alpha);
  const bool compressing = phase == ImpactPhase::compression;
  double sum = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double u = distance * rule.nodes[i];
    const double rate = compressing ? velocity_ - u : restitution_rate(u);
    const double energy = compressing ? compression_energy(u) : restitution_energy(u);
    sum += rule.weights[i] * std::pow(energy / u, -alpha) / (1.0 + damping_ * rate);
  }
  // K = m / (c^(1/(n+1)) ((n+1) m)^alpha) [s (m/s)^(alpha - 1)]
  const double time_scale = mass_ / (std::pow(law.stiffness, 1.0 / (exponent + 1)) *
                                     std::pow((exponent + 1) * mass_, alpha));
  return time_scale * std::pow(distance, 1.0 - alpha) * sum;
}

bool HuntCrossleyImpact::uses_initial_rule() const {
  return !power_law_ && initial_power_law_ && impact_parameter() <= singular_rule_beta_limit;
}

double HuntCrossleyImpact::compression_time_until(double distance) const {
  if (uses_singular_rule())
    return singular_rule_time(ImpactPhase::compression, distance,
                              {power_law_->stiffness(), power_law_->exponent()});
  const auto density = [this](double u) { return compression_time_density(u); };
  if (uses_initial_rule()) {
    const double first =
        std::min(distance, compression_breaks_.empty() ? distance : compression_breaks_.front());
    return singular_rule_time(ImpactPhase::compression, first, *initial_power_law_) +
           integrate_between(density, first, distance, compression_breaks_);
  }
  return integrate_from_zero(density, distance, compression_breaks_);
}

double HuntCrossleyImpact::restitution_time_from(double distance) const {
  if (uses_singular_rule())
    return singular_rule_time(ImpactPhase::restitution, distance,
                              {power_law_->stiffness(), power_law_->exponent()});
  const auto density = [this](double u) { return restitution_time_density(u); };
  if (uses_initial_rule()) {
    const double first =
        std::min(distance, restitution_breaks_.empty() ? distance : restitution_breaks_.front());
    return singular_rule_time(ImpactPhase::restitution, first, *initial_power_law_) +
           integrate_between(density, first, distance, restitution_breaks_);
  }
  return integrate_from_zero(density, distance, restitution_breaks_);
}

// The compression integral from a distance u to x_max (u = V), split at the breakpoints.
double HuntCrossleyImpact::compression_time_from(double distance) const {
  return integrate_between([this](double u) { return compression_time_density(u); }, distance,
                           velocity_, compression_breaks_);
}

double HuntCrossleyImpact::compression_time() const {
  if (!splits_compression_at_peak()) return compression_time_until(velocity_);
  double peak;
  try {
    peak = peak_distance();
  } catch (const std::runtime_error&) {
    // A law whose force peak cannot be located (force_peak() throws for it): the compression
    // time in one integral, as without damping.
    return compression_time_until(velocity_);
  }
  return compression_time_until(peak) + compression_time_from(peak);
}

std::pair<ImpactState, double> HuntCrossleyImpact::force_peak_and_compression_time() const {
  if (!splits_compression_at_peak()) return {force_peak(), compression_time()};
  const double peak = peak_distance();
  const double to_peak = compression_time_until(peak);
  return {compression_state(to_peak, peak), to_peak + compression_time_from(peak)};
}

double HuntCrossleyImpact::contact_time() const {
  return compression_time() + restitution_time_from(restitution_span());
}

double HuntCrossleyImpact::restitution_time() const {
  return restitution_time_from(restitution_span());
}

double HuntCrossleyImpact::time_at_approach(double approach, ImpactPhase phase) const {
  const double rate = approach_rate(approach, phase); // validates the approach
  if (phase == ImpactPhase::compression) return compression_time_until(velocity_ - rate);
  // The restitution distance from separation: u = v - v_out, or psi_out - psi with
  // psi = -log(1 + b v) where the phase is parametrised by the log rate.
  const double distance = restitution_in_log_rate_ ? log_rate_span_ + std::log1p(damping_ * rate)
                                                   : rate - rebound_velocity();
  const double span = restitution_span();
  return compression_time() + restitution_time_from(span) -
         restitution_time_from(std::clamp(distance, 0.0, span));
}

ImpactState HuntCrossleyImpact::force_peak() const {
  if (damping_ == 0.0)
    return {compression_time(), approach_max_, 0.0, elastic_force().force(approach_max_)};
  const double distance = peak_distance();
  return compression_state(compression_time_until(distance), distance);
}

double HuntCrossleyImpact::peak_distance() const {
  // dF/dt = 0  <=>  m f'(x) v = b f(x)^2 (while compressing). In the distance u = V - v
  // the left side dominates near first contact and the right side at x_max.
  auto condition = [this](double distance) {
    const auto [elastic, slope] =
        elastic_force().force_and_slope_at_potential(mass_ * compression_energy(distance));
    return mass_ * (velocity_ - distance) * slope / elastic - damping_ * elastic;
  };
  boost::uintmax_t iterations = 200;
  const auto tolerance = boost::math::tools::eps_tolerance<double>();
  if (power_law_) {
    // For f = c x^n the condition is polynomial-free: n v = b (n + 1) P(x) / m.
    const double exponent = power_law_->exponent();
    auto power_law_condition = [&](double distance) {
      return exponent * (velocity_ - distance) -
             damping_ * (exponent + 1) * compression_energy(distance);
    };
    const auto [low, high] =
        boost::math::tools::toms748_solve(power_law_condition, 0.0, velocity_, exponent * velocity_,
                                          power_law_condition(velocity_), tolerance, iterations);
    return 0.5 * (low + high);
  }
  double lower = velocity_ * 1e-6;
  double at_lower = condition(lower);
  while (!(at_lower > 0)) {
    lower *= 1e-3;
    if (lower < velocity_ * 1e-290)
      throw std::runtime_error("the force peak could not be bracketed");
    at_lower = condition(lower);
  }
  const auto [low, high] =
      boost::math::tools::toms748_solve(condition, lower, velocity_, at_lower, condition(velocity_),
                                        tolerance, iterations);
  return 0.5 * (low + high);
}

ImpactState HuntCrossleyImpact::compression_state(double time, double distance) const {
  const double approach =
      elastic_force().approach_at_potential(mass_ * compression_energy(distance));
  const double rate = velocity_ - distance;
  return {time, approach, rate, force(approach, rate)};
}

ImpactState HuntCrossleyImpact::restitution_state(double time, double distance) const {
  const double approach =
      elastic_force().approach_at_potential(mass_ * restitution_energy(distance));
  const double rate = restitution_rate(distance);
  return {time, approach, rate, force(approach, rate)};
}

ImpactResponse HuntCrossleyImpact::response() const {
  const auto [peak, compression] = force_peak_and_compression_time();
  return {approach_max_,
          peak.force,
          peak.time,
          compression,
          compression + restitution_time_from(restitution_span()),
          rebound_velocity(),
          restitution_,
          energy_loss()};
}

} // namespace impact::reduced
