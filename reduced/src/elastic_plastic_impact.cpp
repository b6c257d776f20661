#include "impact_reduced/elastic_plastic_impact.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

double loading_work_below(const ElasticPlasticContact& contact, double approach_max,
                          double distance) {
  if (distance <= 0) return 0.0;
  if (distance > 0.5 * approach_max)
    return contact.loading_work(approach_max) - contact.loading_work(approach_max - distance);
  return local_work(contact, approach_max, distance);
}

ElasticPlasticImpactResponse elastic_plastic_impact(double mass, double velocity,
                                                    const ElasticPlasticContact& contact) {
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
  const double approach_max = 0.5 * (low + high);
  const double force_max = contact.loading_force(approach_max);
  const double work_max = contact.loading_work(approach_max);

  // Compression time: x = x_max (1 - s^2), dt = 2 x_max s ds / x', with
  // x'^2 = (2/m) * (work of F_L between x and x_max): finite at s = 0, split at breakpoints.
  std::vector<double> ends{0.0, 1.0};
  for (const double breakpoint : contact.loading_breakpoints())
    if (breakpoint > 0 && breakpoint < approach_max)
      ends.push_back(std::sqrt((approach_max - breakpoint) / approach_max));
  std::sort(ends.begin(), ends.end());
  const auto density = [&](double s) {
    // work / s^2 -> F_max x_max as s -> 0 (relative error ~ s^2: exact below 1e-8).
    const double distance = approach_max * s * s;
    if (s < 1e-8) return 2 * approach_max / std::sqrt(2 * force_max * approach_max / mass);
    const double work = distance > 0.5 * approach_max
                            ? work_max - contact.loading_work(approach_max - distance)
                            : local_work(contact, approach_max, distance);
    const double work_per_s2 = work / (s * s);
    return 2 * approach_max / std::sqrt(2 * work_per_s2 / mass);
  };
  thread_local boost::math::quadrature::tanh_sinh<double> quadrature;
  double compression_time = 0;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i)
    if (ends[i + 1] > ends[i])
      compression_time += quadrature.integrate(density, ends[i], ends[i + 1], 1e-14);

  // Restitution: the Hertzian branch k_u (x - x_r)^(3/2) releases (2/5) F_max (x_max - x_r)
  // down to x_r. If x_r < 0 (a loading fit above Hertz) the surfaces part at x = 0 first: the
  // branch is then followed only down to x_s = 0, u_s = (x_s - x_r) / (x_max - x_r).
  const HertzianUnloading unloading = contact.unloading(approach_max);
  const double separation_approach = std::max(0.0, unloading.residual_approach);
  const double branch_length = approach_max - unloading.residual_approach;
  const double full_speed = std::sqrt(0.8 * force_max * branch_length / mass);
  const double separation_fraction = (separation_approach - unloading.residual_approach) /
                                     branch_length;
  const double remaining = std::pow(separation_fraction, 2.5);  // (u_s)^(5/2)
  // A branch may not return more energy than the loading absorbed. Fitted loading curves can
  // make it do so (the Jackson-Green fit jumps 0.5 % above Hertz at 1.9 omega_c): the impact
  // is then elastic, e = 1, not e > 1.
  const double rebound_speed = std::min(velocity, full_speed * std::sqrt(1 - remaining));
  const double restitution_time =
      branch_length / full_speed *
      (hertz_phase_factor() - 0.4 * (remaining > 0 ? boost::math::beta(0.4, 0.5, remaining) : 0.0));

  ElasticPlasticImpactResponse response{};
  response.approach_max = approach_max;
  response.force_max = force_max;
  response.residual_approach = separation_approach;
  response.compression_time = compression_time;
  response.contact_time = compression_time + restitution_time;
  response.rebound_velocity = -rebound_speed;
  response.restitution = rebound_speed / velocity;
  response.dissipated_energy = energy - 0.5 * mass * rebound_speed * rebound_speed;
  return response;
}

} // namespace impact::reduced
