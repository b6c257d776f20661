#include "impact_postprocess/models/simulated_force.hpp"

#include <impact_reduced/hunt_crossley.hpp>

#include <algorithm>
#include <cmath>
#include <exception>

namespace impact::postprocess::detail {

namespace {

// The state interpolated at t (inside the samples) and the law's force there.
double force_at(const std::vector<reduced::ImpactSample>& samples,
                const reduced::ContactForceLaw& law, double mass, double t) {
  const std::size_t last = samples.size() - 1;
  const double spacing = samples[last].time / double(last);
  std::size_t k = std::min(std::size_t(t / spacing), last - 1);
  while (k > 0 && t < samples[k].time) --k;
  while (k + 1 < last && t > samples[k + 1].time) ++k;
  const auto& a = samples[k];
  const auto& b = samples[k + 1];
  const double h = b.time - a.time;
  const double s = (t - a.time) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s);
  const double h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s);
  const double h11 = s * s * (s - 1);
  const double approach =
      h00 * a.approach + h10 * h * a.approach_rate + h01 * b.approach + h11 * h * b.approach_rate;
  const double rate = h00 * a.approach_rate - h10 * h * a.force / mass + h01 * b.approach_rate -
                      h11 * h * b.force / mass;
  return law(std::max(approach, 0.0), rate);
}

// `average_jump`: a law whose force jumps to 0 at separation (F(0, x') != 0 there, the linear
// dashpot mu x') is given, at the measured time whose cell (half-way to its neighbours) holds
// the separation, the cell's mean: the force at min(t, separation) times the share of the
// cell before separation. Point values there jump as the separation crosses a measured time,
// and so do the residuals of a fit, which then creeps from jump to jump (the plastic study's
// Kelvin–Voigt fit: over 100 iterations); the mean is continuous in the law's parameters.
bool force_from_samples(const std::vector<reduced::ImpactSample>& samples,
                        const reduced::ContactForceLaw& law, double mass,
                        const std::vector<double>& times, double* force,
                        bool average_jump = false) {
  const double separation = samples.back().time;
  double peak = 0;
  for (const auto& sample : samples) peak = std::max(peak, std::abs(sample.force));
  const bool jumps = average_jump && std::abs(samples.back().force) > 1e-9 * peak;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    force[i] = 0;
    if (jumps && t > 0) {
      const double low = i > 0 ? (times[i - 1] + t) / 2 : t;
      const double high = i + 1 < times.size() ? (t + times[i + 1]) / 2 : t;
      if (low < separation && separation < high) {
        const double share = (separation - low) / (high - low);
        force[i] =
            share * (t < separation ? force_at(samples, law, mass, t) : samples.back().force);
        if (!std::isfinite(force[i])) return false;
        continue;
      }
    }
    if (!(t > 0 && t < separation)) continue;
    force[i] = force_at(samples, law, mass, t);
    if (!std::isfinite(force[i])) return false;
  }
  return true;
}

} // namespace

bool simulate_force(const reduced::ContactForceLaw& law, double mass, double velocity,
                    const std::vector<double>& times, std::size_t points, double tolerance,
                    reduced::ContactEnd end, double* force) {
  std::vector<reduced::ImpactSample> samples;
  try {
    samples = reduced::integrate_impact_history(mass, velocity, law, points, tolerance, end);
  } catch (const std::exception&) {
    return false;
  }
  return force_from_samples(samples, law, mass, times, force, true);
}

bool simulate_hunt_crossley_force(const reduced::ContactForceLaw& law,
                                  const reduced::ContactSetup& setup, double damping,
                                  double velocity, const std::vector<double>& times,
                                  std::size_t points, double* force) {
  std::vector<reduced::ImpactSample> samples;
  try {
    const reduced::HuntCrossleyImpact impact(setup.mass, setup.stiffness, setup.exponent, damping,
                                             velocity);
    for (const auto& state : impact.history(points))
      samples.push_back({state.time, state.approach, state.approach_rate, state.force});
  } catch (const std::exception&) {
    return false;
  }
  return force_from_samples(samples, law, setup.mass, times, force);
}

double compression_tolerance(const reduced::ElasticPlasticContact& contact, double tolerance) {
  for (const double breakpoint : contact.loading_breakpoints()) {
    if (!(breakpoint > 0)) continue;
    const double below = contact.loading_force(breakpoint);
    const double above = contact.loading_force(breakpoint * (1 + 1e-12));
    // A continuous curve changes by about its local exponent x 1e-12 over that distance.
    if (std::abs(above - below) > 1e-6 * std::abs(below)) return std::min(tolerance, 1e-13);
  }
  return tolerance;
}

bool simulate_plastic_force(const reduced::ElasticPlasticContact& contact, double mass,
                            double velocity, const std::vector<double>& times, std::size_t points,
                            double tolerance, double* force) {
  std::vector<reduced::ImpactSample> samples;
  reduced::HertzianUnloading unloading{};
  try {
    const auto response = reduced::elastic_plastic_impact(mass, velocity, contact);
    unloading = contact.unloading(response.approach_max);
    const reduced::ContactForceLaw loading = [&contact](double x, double) {
      return contact.loading_force(std::max(x, 0.0));
    };
    for (const auto& sample :
         reduced::integrate_impact_history(mass, velocity, loading, points,
                                           compression_tolerance(contact, tolerance)))
      if (sample.time < response.compression_time) samples.push_back(sample);
    samples.push_back({response.compression_time, response.approach_max, 0.0, response.force_max});
    const double stiffness = unloading.stiffness;
    const reduced::ContactForceLaw hertz = [stiffness](double x, double) {
      return stiffness * std::pow(std::max(x, 0.0), 1.5);
    };
    const auto rebound = reduced::integrate_impact_history(mass, -response.rebound_velocity, hertz,
                                                           points, tolerance);
    const double peak = 0.5 * rebound.back().time;
    for (const auto& sample : rebound)
      if (sample.time > peak)
        samples.push_back({response.compression_time + sample.time - peak,
                           unloading.residual_approach + sample.approach, sample.approach_rate,
                           sample.force});
  } catch (const std::exception&) {
    return false;
  }
  const reduced::ContactForceLaw law = [&contact, unloading](double x, double rate) {
    if (rate > 0) return contact.loading_force(x);
    return unloading.stiffness * std::pow(std::max(x - unloading.residual_approach, 0.0), 1.5);
  };
  return force_from_samples(samples, law, mass, times, force);
}

bool simulate_damped_plastic_force(const DampedPlasticImpact& impact, double mass,
                                   const std::vector<double>& times, std::size_t points,
                                   double* force) {
  std::vector<reduced::ImpactSample> samples;
  try {
    samples = impact.history(points);
  } catch (const std::exception&) {
    return false;
  }
  const reduced::ContactForceLaw law = [&impact](double x, double rate) {
    return impact.force(x, rate);
  };
  return force_from_samples(samples, law, mass, times, force);
}

} // namespace impact::postprocess::detail
