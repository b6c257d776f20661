// HuntCrossleyImpact's states at given times: the history at equally spaced times (the
// power law's linear-time series, or the quadrature's inversion) and the state at one time.

#include "impact_reduced/hunt_crossley.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "hunt_crossley_phases.hpp"
#include "phase_time_map.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

namespace impact::reduced {

using detail::invert_cumulative_integral;
using detail::velocity_work_per_width;

std::vector<ImpactState> HuntCrossleyImpact::history(std::size_t points) const {
  if (points < 2)
    throw InvalidInput("points", "points must be >= 2 (got " + std::to_string(points) + ")");
  return power_law_ ? power_law_history(points) : quadrature_history(points);
}

double HuntCrossleyImpact::phase_extent(ImpactPhase phase) const {
  if (phase == ImpactPhase::restitution) return restitution_span();
  return restitution_in_log_rate_ ? log_rate_in_ : velocity_;
}

double HuntCrossleyImpact::phase_energy_ratio(ImpactPhase phase, double distance) const {
  if (!restitution_in_log_rate_) {
    if (phase == ImpactPhase::compression)
      return velocity_work_per_width(damping_, velocity_ - distance, distance);
    return -velocity_work_per_width(damping_, rebound_velocity(), distance);
  }
  // Log-rate distances (beta > 1), b^2 E / m written from the singular end:
  //   compression, psi = psi_in - d:   b^2 E = -(1 + beta) expm1(-d) - d
  //   restitution, psi = psi_out + d:  b^2 E = d - exp(-psi_out) expm1(d)
  // (the first two terms cancel at most to a factor (1 + beta) / beta < 2).
  const double b2 = damping_ * damping_;
  if (phase == ImpactPhase::compression) {
    const double growth = distance > 0 ? -std::expm1(-distance) / distance : 1.0;
    return ((1.0 + impact_parameter()) * growth - 1.0) / b2;
  }
  if (distance <= 0) return (1.0 - separation_force_factor_) / b2;
  const double decayed = distance < 1.0
                             ? separation_force_factor_ * std::expm1(distance)
                             : std::exp(distance - log_rate_span_) - separation_force_factor_;
  return (1.0 - decayed / distance) / b2;
}

double HuntCrossleyImpact::phase_rate(ImpactPhase phase, double distance) const {
  if (phase == ImpactPhase::restitution) return restitution_rate(distance);
  if (!restitution_in_log_rate_) return velocity_ - distance;
  return std::expm1(log_rate_in_ - distance) / damping_; // v = (exp(psi) - 1) / b
}

double HuntCrossleyImpact::phase_force_factor(ImpactPhase phase, double distance) const {
  if (!restitution_in_log_rate_) return 1.0 + damping_ * phase_rate(phase, distance);
  return phase == ImpactPhase::compression ? std::exp(log_rate_in_ - distance)
                                           : std::exp(distance - log_rate_span_);
}

// The time density of a phase has the end-point singularity d^(-alpha), alpha = n / (n + 1),
// where f(x) vanishes (first contact, separation): dt/dd = K_d d^(-alpha) (E / d)^(-alpha) / w,
// w = 1 + b v (rate distance) or b (log-rate distance), K_d = m / (c^(1/(n+1)) ((n+1) m)^alpha).
// In sigma = (d / D)^(1/(n+1)), D the phase's extent, d^(-alpha) dd = (n + 1) D^(1-alpha) dsigma:
//   dt/dsigma = (n + 1) D^(1-alpha) K_d (E / d)^(-alpha) / w,
// bounded and positive on [0, 1], a power series in sigma^(n+1) near sigma = 0. Each phase's
// time is accumulated piece by piece from its singular end (PhaseTimeMap: a polynomial in
// sigma^(n+1) on the first piece, Chebyshev panels beyond), the density evaluated a fixed
// number of times whatever the number of points. The state is interpolated on the same
// pieces as functions of sigma^(n+1) (the map's companions): v, x / sigma =
// ((n+1) m D e / c)^(1/(n+1)) and f (1 + b v) / sigma^n, with e = E / d; the approach
// x / sigma needs e^(1/(n+1)) = e e^(-alpha), the density's own power. A point then costs
// its location on the series and a few short series (one power in the first piece).
std::vector<ImpactState> HuntCrossleyImpact::power_law_history(std::size_t points) const {
  const double exponent = power_law_->exponent();
  const double alpha = exponent / (exponent + 1);
  const double power = exponent + 1;
  const double time_scale =
      mass_ / (std::pow(power_law_->stiffness(), 1.0 / power) * std::pow(power * mass_, alpha)) /
      (restitution_in_log_rate_ ? damping_ : 1.0);
  constexpr double tolerance = 1e-14;
  auto make_map = [&](ImpactPhase phase) {
    const double extent = phase_extent(phase);
    const double factor = power * std::pow(extent, 1.0 - alpha) * time_scale;
    // x / sigma = approach_scale e^(1/(n+1)); f / sigma^n = (n + 1) m D e / (x / sigma).
    const double approach_scale =
        std::pow(power * mass_ * extent / power_law_->stiffness(), 1.0 / power);
    const double energy_scale = power * mass_ * extent;
    const auto density = [&, extent, factor, approach_scale,
                          energy_scale](double, double sigma_power, double* state) {
      const double distance = extent * sigma_power;
      const double ratio = phase_energy_ratio(phase, distance);
      const double root = std::pow(ratio, -alpha); // e^(-alpha)
      const double force_factor = phase_force_factor(phase, distance);
      const double approach_per_sigma = approach_scale * ratio * root;
      state[0] = phase_rate(phase, distance);
      state[1] = approach_per_sigma;
      state[2] = energy_scale * ratio / approach_per_sigma * force_factor;
      const double weight = restitution_in_log_rate_ ? 1.0 : 1.0 / force_factor;
      return factor * root * weight;
    };
    return detail::PhaseTimeMap(density, power, tolerance);
  };
  const detail::PhaseTimeMap compression_map = make_map(ImpactPhase::compression);
  const detail::PhaseTimeMap restitution_map = make_map(ImpactPhase::restitution);
  const double compression = compression_map.duration();
  const double total = compression + restitution_map.duration();
  const auto time_at = [&](std::size_t i) {
    return total * static_cast<double>(i) / static_cast<double>(points - 1);
  };
  const auto state = [](double time, const detail::PhaseSample& sample) {
    return ImpactState{time, sample.quantities[1], sample.quantities[0], sample.quantities[2]};
  };

  std::vector<ImpactState> states(points);
  states.front() = {0.0, 0.0, velocity_, 0.0};
  states.back() = {total, 0.0, rebound_velocity(), 0.0};
  // Compression points forward from first contact (points 1 .. compression_points),
  // restitution points backward from separation, each from its own singular end; the
  // located points go straight into `states`.
  const double spacing = total / static_cast<double>(points - 1);
  std::size_t compression_points =
      std::min(points - 2, static_cast<std::size_t>(compression / spacing));
  while (compression_points > 0 && time_at(compression_points) > compression) --compression_points;
  while (compression_points + 2 < points && time_at(compression_points + 1) <= compression)
    ++compression_points;
  const auto locate = [spacing](const detail::PhaseTimeMap& map, std::size_t count,
                                const auto& time_of, const auto& store) {
    constexpr int batch = detail::PhaseTimeMap::Locator::batch;
    detail::PhaseTimeMap::Locator locator(map);
    for (std::size_t first = 0; first < count; first += batch) {
      const int size = static_cast<int>(std::min<std::size_t>(batch, count - first));
      double times[batch];
      detail::PhaseSample samples[batch];
      for (int k = 0; k < size; ++k) times[k] = time_of(first + k);
      locator.locate(times, size, spacing, samples);
      for (int k = 0; k < size; ++k) store(first + k, samples[k]);
    }
  };
  locate(
      compression_map, compression_points, [&](std::size_t j) { return time_at(j + 1); },
      [&](std::size_t j, const detail::PhaseSample& sample) {
        states[j + 1] = state(time_at(j + 1), sample);
      });
  locate(
      restitution_map, points - 2 - compression_points,
      [&](std::size_t j) { return total - time_at(points - 2 - j); },
      [&](std::size_t j, const detail::PhaseSample& sample) {
        states[points - 2 - j] = state(time_at(points - 2 - j), sample);
      });
  return states;
}

ImpactState HuntCrossleyImpact::state_at(double time) const {
  const double compression = compression_time();
  const double total = compression + restitution_time_from(restitution_span());
  if (!(time >= 0 && time <= total)) {
    std::ostringstream message;
    message.precision(17);
    message << "time must be in [0, contact_time = " << total << "] s (got " << time << ")";
    throw InvalidInput("time", message.str());
  }
  if (time <= compression) {
    const auto distance =
        invert_cumulative_integral([this](double u) { return compression_time_density(u); }, {time},
                                   velocity_);
    return compression_state(time, distance[0]);
  }
  const auto distance =
      invert_cumulative_integral([this](double u) { return restitution_time_density(u); },
                                 {total - time}, restitution_span());
  return restitution_state(time, distance[0]);
}

std::vector<ImpactState> HuntCrossleyImpact::states_at(const std::vector<double>& times) const {
  const double compression = compression_time();
  const double extent = restitution_span();
  const double total = compression + restitution_time_from(extent);
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] >= 0 && times[i] <= total) || (i > 0 && times[i] < times[i - 1])) {
      std::ostringstream message;
      message.precision(17);
      message << "times must ascend within [0, contact_time = " << total << "] s (got " << times[i]
              << " at index " << i << ")";
      throw InvalidInput("times", message.str());
    }
  // Compression instants forward from first contact, restitution instants backward from
  // separation, as state_at integrates each from its phase's singular end.
  std::vector<double> elapsed, remaining;
  std::vector<std::size_t> compression_index, restitution_index;
  for (std::size_t i = 0; i < times.size() && times[i] <= compression; ++i) {
    elapsed.push_back(times[i]);
    compression_index.push_back(i);
  }
  for (std::size_t i = times.size(); i-- > 0 && times[i] > compression;) {
    remaining.push_back(total - times[i]);
    restitution_index.push_back(i);
  }
  std::vector<ImpactState> states(times.size());
  const auto compression_distances =
      invert_cumulative_integral([this](double u) { return compression_time_density(u); }, elapsed,
                                 velocity_);
  for (std::size_t j = 0; j < compression_index.size(); ++j)
    states[compression_index[j]] = compression_state(elapsed[j], compression_distances[j]);
  const auto restitution_distances =
      invert_cumulative_integral([this](double u) { return restitution_time_density(u); },
                                 remaining, extent);
  for (std::size_t j = 0; j < restitution_index.size(); ++j)
    states[restitution_index[j]] =
        restitution_state(total - remaining[j], restitution_distances[j]);
  return states;
}

// Any elastic law: each point's time inverted by Newton's method on the adaptive quadrature.
std::vector<ImpactState> HuntCrossleyImpact::quadrature_history(std::size_t points) const {
  const auto compression_density = [this](double u) { return compression_time_density(u); };
  const auto restitution_density = [this](double u) { return restitution_time_density(u); };
  const double compression = compression_time();
  const double restitution_extent = restitution_span();
  const double total = compression + restitution_time_from(restitution_extent);
  const auto time_at = [&](std::size_t i) {
    return total * static_cast<double>(i) / static_cast<double>(points - 1);
  };

  std::vector<ImpactState> states(points);
  states.front() = {0.0, 0.0, velocity_, 0.0};
  states.back() = {total, 0.0, rebound_velocity(), 0.0};
  // Compression points forward from first contact, restitution points backward from
  // separation: each phase integrates away from its singular end, so every state is
  // computed from an exact small distance u.
  std::vector<double> compression_elapsed, restitution_remaining;
  std::vector<std::size_t> compression_index, restitution_index;
  for (std::size_t i = 1; i + 1 < points; ++i) {
    if (time_at(i) <= compression) {
      compression_elapsed.push_back(time_at(i));
      compression_index.push_back(i);
    }
  }
  for (std::size_t i = points - 2; i >= 1 && time_at(i) > compression; --i) {
    restitution_remaining.push_back(total - time_at(i));
    restitution_index.push_back(i);
  }
  const auto compression_distances =
      invert_cumulative_integral(compression_density, compression_elapsed, velocity_);
  for (std::size_t j = 0; j < compression_index.size(); ++j)
    states[compression_index[j]] =
        compression_state(compression_elapsed[j], compression_distances[j]);
  const auto restitution_distances =
      invert_cumulative_integral(restitution_density, restitution_remaining, restitution_extent);
  for (std::size_t j = 0; j < restitution_index.size(); ++j)
    states[restitution_index[j]] =
        restitution_state(total - restitution_remaining[j], restitution_distances[j]);
  return states;
}

} // namespace impact::reduced
