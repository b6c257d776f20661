#include "impact_reduced/elastic_plastic_impact.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impact::reduced {

namespace {

// Loading work between x_max - d and x_max by Gauss-Legendre in t = (x_max - x) / d, so that
// the length d of the interval is exact (the abscissas x_max - d t round, but F is not
// sensitive to that; the length would be). Split at the law's breakpoints. Only used for
// d <= x_max / 2, where F_L is smooth between breakpoints (its x^(1/2)-type singularities
// sit at x = 0, three half-widths away at least), so that 30 points reach machine precision.
double local_work(const ElasticPlasticContact& contact, double approach_max, double distance) {
  std::vector<double> ends{0.0};
  for (const double breakpoint : contact.loading_breakpoints()) {
    const double t = (approach_max - breakpoint) / distance;
    if (t > 0 && t < 1) ends.push_back(t);
  }
  ends.push_back(1.0);
  std::sort(ends.begin(), ends.end());
  double work = 0;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i)
    work += boost::math::quadrature::gauss<double, 30>::integrate(
        [&](double t) { return contact.loading_force(approach_max - distance * t); }, ends[i],
        ends[i + 1]);
  return work * distance;
}

// (2/5) B(2/5, 1/2): integral_0^1 du / sqrt(1 - u^(5/2)), the Hertz phase-time factor.
double hertz_phase_factor() {
  static const double factor = 0.4 * boost::math::beta(0.4, 0.5);
  return factor;
}

} // namespace

double ElasticPlasticContact::loading_approach(double work) const {
  if (!(work > 0)) return 0.0;
  // Bracket by doubling from a small start, then TOMS 748 on the work.
  double lower = 0, upper = 1e-9;
  for (int doublings = 0; loading_work(upper) < work; ++doublings) {
    lower = upper;
    upper *= 2;
    if (doublings > 2000)
      throw std::runtime_error("the loading curve never absorbs the impact energy");
  }
  boost::uintmax_t iterations = 200;
  const auto [low, high] =
      boost::math::tools::toms748_solve([&](double x) { return loading_work(x) - work; }, lower,
                                        upper, boost::math::tools::eps_tolerance<double>(),
                                        iterations);
  return 0.5 * (low + high);
}

double detail::hertz_work_below(double stiffness, double approach, double distance) {
  if (!(distance > 0)) return 0.0;
  distance = std::min(distance, approach);
  // x^(5/2) (1 - (1 - d/x)^(5/2)) = -x^(5/2) expm1((5/2) log1p(-d/x)).
  return -0.4 * stiffness * approach * approach * std::sqrt(approach) *
         std::expm1(2.5 * std::log1p(-distance / approach));
}

double ElasticPlasticContact::loading_work_below(double approach_max, double distance) const {
  if (distance <= 0) return 0.0;
  if (distance > 0.5 * approach_max)
    return loading_work(approach_max) - loading_work(approach_max - distance);
  return local_work(*this, approach_max, distance);
}

double loading_work_below(const ElasticPlasticContact& contact, double approach_max,
                          double distance) {
  if (distance <= 0) return 0.0;
  return contact.loading_work_below(approach_max, distance);
}

namespace {

// One impact, solved once: x_max, the unloading branch, and the time integrals.
class ImpactSolution {
public:
  ImpactSolution(double mass, double velocity, const ElasticPlasticContact& contact)
      : mass_(mass), velocity_(velocity), contact_(contact) {
    require_positive("mass", mass);
    require_positive("velocity", velocity);
    const double energy = 0.5 * mass * velocity * velocity;
    // x_max: bracket by doubling, then TOMS 748 to full precision.
    double upper = 1e-12;
    for (int doublings = 0; contact.loading_work(upper) < energy; ++doublings) {
      upper *= 2;
      if (doublings > 2000)
        throw std::runtime_error("the loading curve never absorbs the impact energy");
    }
    boost::uintmax_t iterations = 200;
    const auto [low, high] = boost::math::tools::toms748_solve(
        [&](double x) { return contact.loading_work(x) - energy; }, 0.0, upper, -energy,
        contact.loading_work(upper) - energy, boost::math::tools::eps_tolerance<double>(),
        iterations);
    approach_max_ = 0.5 * (low + high);
    force_max_ = contact.loading_force(approach_max_);
    for (const double breakpoint : contact.loading_breakpoints())
      if (breakpoint > 0 && breakpoint < approach_max_) breaks_.push_back(breakpoint);
    std::sort(breaks_.begin(), breaks_.end());
    power_law_ = contact.loading_power_law();

    // Restitution: the Hertzian branch k_u (x - x_r)^(3/2) releases (2/5) F_max (x_max - x_r)
    // down to x_r. If x_r < 0 (a loading fit above Hertz) the surfaces part at x = 0 first:
    // the branch is then followed only down to x_s = 0, u_s = (x_s - x_r) / (x_max - x_r).
    unloading_ = contact.unloading(approach_max_);
    separation_approach_ = std::max(0.0, unloading_.residual_approach);
    branch_length_ = approach_max_ - unloading_.residual_approach;
    full_speed_ = std::sqrt(0.8 * force_max_ * branch_length_ / mass);
  }

  double approach_max() const { return approach_max_; }
  double force_max() const { return force_max_; }
  double separation_approach() const { return separation_approach_; }
  const HertzianUnloading& unloading() const { return unloading_; }

  // Time from first contact to approach x on the loading branch, piece by piece between the
  // breakpoints. The first piece, from x = 0, where x' -> V and the force vanishes like a
  // power of x: Hertz's incomplete Beta function where the law is a power law there
  // (loading_power_law), else tanh-sinh in s, x = x_max (1 - s^2). The others by adaptive
  // Gauss-Kronrod in sigma, x = x_max exp(-sigma^2): smooth on every piece, the
  // inverse-square-root singularity at x_max removed (dt/dsigma finite there) and the
  // fits' branch points at x = 0 sent to sigma = infinity.
  double compression_time_to(double approach) const {
    approach = std::clamp(approach, 0.0, approach_max_);
    const double first_end = breaks_.empty() ? approach_max_ : breaks_.front();
    double time = first_piece_time(std::min(approach, first_end));
    for (std::size_t i = 0; i < breaks_.size() && breaks_[i] < approach; ++i) {
      const double end = i + 1 < breaks_.size() ? std::min(breaks_[i + 1], approach) : approach;
      time += sigma_piece_time(breaks_[i], end);
    }
    return time;
  }
  double compression_time() const { return compression_time_to(approach_max_); }

  // Approach rate while compressing at approach x, from the work between x and x_max.
  double compression_rate(double approach) const {
    return std::sqrt(2 * work_below(approach_max_ - approach) / mass_);
  }

  // (x - x_r) / (x_max - x_r) on the unloading branch.
  double branch_fraction(double approach) const {
    return (approach - unloading_.residual_approach) / branch_length_;
  }
  // Time from x_max down to x on the unloading branch:
  // (L / V_L) integral_u^1 du / sqrt(1 - u^(5/2)) = (L / V_L) (2/5) (B(2/5,1/2) - B(u^(5/2); 2/5,1/2)).
  double restitution_time_to(double approach) const {
    const double remaining = std::pow(std::max(0.0, branch_fraction(approach)), 2.5);
    return branch_length_ / full_speed_ *
           (hertz_phase_factor() -
            0.4 * (remaining > 0 ? boost::math::beta(0.4, 0.5, std::min(1.0, remaining)) : 0.0));
  }
  // Approach rate (negative) on the unloading branch at x.
  double restitution_rate(double approach) const {
    const double remaining = std::pow(std::max(0.0, branch_fraction(approach)), 2.5);
    return -full_speed_ * std::sqrt(std::max(0.0, 1 - remaining));
  }
  double unloading_force(double approach) const {
    return unloading_.stiffness *
           std::pow(std::max(0.0, approach - unloading_.residual_approach), 1.5);
  }

  ElasticPlasticImpactResponse response() const {
    // A branch may not return more energy than the loading absorbed. Fitted loading curves
    // can make it do so (the Jackson-Green fit jumps 0.5 % above Hertz at 1.9 omega_c): the
    // impact is then elastic, e = 1, not e > 1.
    const double rebound_speed = std::min(velocity_, -restitution_rate(separation_approach_));
    const double compression = compression_time();
    ElasticPlasticImpactResponse response{};
    response.approach_max = approach_max_;
    response.force_max = force_max_;
    response.residual_approach = separation_approach_;
    response.compression_time = compression;
    response.contact_time = compression + restitution_time_to(separation_approach_);
    response.rebound_velocity = -rebound_speed;
    response.restitution = rebound_speed / velocity_;
    response.dissipated_energy =
        0.5 * mass_ * (velocity_ - rebound_speed) * (velocity_ + rebound_speed);
    return response;
  }

private:
  // Loading work between x_max - d and x_max, without cancellation for small d.
  double work_below(double distance) const {
    if (distance <= 0) return 0.0;
    return contact_.loading_work_below(approach_max_, distance);
  }
  // Time from x = 0 to x on the first piece.
  double first_piece_time(double approach) const {
    if (!(approach > 0)) return 0.0;
    if (power_law_) {
      // f = c x^n from x = 0 at speed V: t = (x_H / V) / (n + 1) B(z; 1/(n+1), 1/2),
      // z = (x / x_H)^(n+1), x_H the approach at which c x^(n+1) / (n+1) = m V^2 / 2.
      const double n = power_law_->exponent;
      const double hertz_approach =
          std::pow((n + 1) * mass_ * velocity_ * velocity_ / (2 * power_law_->stiffness),
                   1 / (n + 1));
      const double z = std::min(1.0, std::pow(approach / hertz_approach, n + 1));
      return hertz_approach / velocity_ / (n + 1) * boost::math::beta(1 / (n + 1), 0.5, z);
    }
    thread_local boost::math::quadrature::tanh_sinh<double> quadrature;
    const double s_lower = std::sqrt(std::max(0.0, (approach_max_ - approach) / approach_max_));
    return quadrature.integrate([&](double s) { return time_density(s); }, s_lower, 1.0, 1e-14);
  }

  // Time from x = a to x = b (a < b) on a piece between breakpoints, in sigma.
  double sigma_piece_time(double lower, double upper) const {
    if (!(upper > lower)) return 0.0;
    const auto sigma = [this](double x) {
      return std::sqrt(std::max(0.0, -std::log1p(-(approach_max_ - x) / approach_max_)));
    };
    return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
        [this](double s) { return sigma_density(s); }, sigma(upper), sigma(lower), 15, 1e-13);
  }

  // dt/dsigma = 2 sigma x / x' at x = x_max exp(-sigma^2): -> 2 x_max / sqrt(2 F_max x_max / m)
  // as sigma -> 0 (relative error ~ sigma^2: exact below 1e-8).
  double sigma_density(double sigma) const {
    if (sigma < 1e-8) return 2 * approach_max_ / std::sqrt(2 * force_max_ * approach_max_ / mass_);
    const double distance = -approach_max_ * std::expm1(-sigma * sigma); // x_max - x
    const double approach = approach_max_ - distance;
    return 2 * sigma * approach / std::sqrt(2 * work_below(distance) / mass_);
  }

  double time_density(double s) const {
    // work / s^2 -> F_max x_max as s -> 0 (relative error ~ s^2: exact below 1e-8).
    if (s < 1e-8) return 2 * approach_max_ / std::sqrt(2 * force_max_ * approach_max_ / mass_);
    const double work_per_s2 = work_below(approach_max_ * s * s) / (s * s);
    return 2 * approach_max_ / std::sqrt(2 * work_per_s2 / mass_);
  }

  double mass_;
  double velocity_;
  const ElasticPlasticContact& contact_;
  double approach_max_ = 0;
  double force_max_ = 0;
  std::vector<double> breaks_;                    // breakpoints in (0, x_max), ascending
  std::optional<PowerLawCoefficients> power_law_; // the loading below the first breakpoint
  HertzianUnloading unloading_{};
  double separation_approach_ = 0;
  double branch_length_ = 0;
  double full_speed_ = 0;
};

} // namespace

ElasticPlasticImpactResponse elastic_plastic_impact(double mass, double velocity,
                                                    const ElasticPlasticContact& contact) {
  return ImpactSolution(mass, velocity, contact).response();
}

std::vector<ImpactSample> elastic_plastic_impact_loop(double mass, double velocity,
                                                      const ElasticPlasticContact& contact,
                                                      std::size_t points_per_phase) {
  if (points_per_phase < 2)
    throw InvalidInput("points_per_phase",
                       "points_per_phase: at least 2 points per phase are "
                       "needed (received " +
                           std::to_string(points_per_phase) + ")");
  const ImpactSolution solution(mass, velocity, contact);
  const double x_max = solution.approach_max();
  const double compression_time = solution.compression_time();
  std::vector<ImpactSample> samples;
  const double last = static_cast<double>(points_per_phase - 1);
  for (std::size_t k = 0; k < points_per_phase; ++k) {
    const double x = k + 1 == points_per_phase ? x_max : x_max * (k / last);
    samples.push_back({k == 0 ? 0.0 : solution.compression_time_to(x), x,
                       solution.compression_rate(x), contact.loading_force(x)});
  }
  const double x_s = solution.separation_approach();
  for (std::size_t k = 1; k < points_per_phase; ++k) {
    const double x = k + 1 == points_per_phase ? x_s : x_max - (x_max - x_s) * (k / last);
    samples.push_back({compression_time + solution.restitution_time_to(x), x,
                       solution.restitution_rate(x), solution.unloading_force(x)});
  }
  return samples;
}

} // namespace impact::reduced
