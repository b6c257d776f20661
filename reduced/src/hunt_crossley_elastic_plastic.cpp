#include "impact_reduced/hunt_crossley_elastic_plastic.hpp"

#include "impact_reduced/hertz_contact.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "branch_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace impact::reduced {

namespace {

constexpr double epsilon = std::numeric_limits<double>::epsilon();

// The loading branch of a spring as the elastic law of a Hunt-Crossley compression phase.
class LoadingBranch final : public ElasticForce {
public:
  explicit LoadingBranch(std::shared_ptr<const ElasticPlasticContact> spring)
      : spring_(std::move(spring)) {}
  double force(double approach) const override { return spring_->loading_force(approach); }
  double potential(double approach) const override { return spring_->loading_work(approach); }
  double slope(double approach) const override { return spring_->loading_stiffness(approach); }
  std::pair<double, double> force_and_slope(double approach) const override {
    return spring_->loading_force_and_stiffness(approach);
  }
  double approach_at_potential(double work) const override {
    return spring_->loading_approach(work);
  }
  double force_at_potential(double work) const override {
    return spring_->loading_force_at_work(work);
  }
  std::pair<double, double> force_and_slope_at_potential(double work) const override {
    return spring_->loading_force_and_stiffness_at_work(work);
  }
  std::vector<double> breakpoints() const override { return spring_->loading_breakpoints(); }
  std::optional<PowerLawCoefficients> initial_power_law() const override {
    return spring_->loading_power_law();
  }

private:
  std::shared_ptr<const ElasticPlasticContact> spring_;
};

const std::shared_ptr<const ElasticPlasticContact>& validated(
    const std::shared_ptr<const ElasticPlasticContact>& spring) {
  if (!spring) throw InvalidInput("spring", "spring must not be null");
  return spring;
}

// The Hertz spring compresses on the power law itself, so that the whole impact is
// HuntCrossleyImpact's fast path, digit for digit.
std::shared_ptr<const ElasticForce> loading_branch(
    const std::shared_ptr<const ElasticPlasticContact>& spring) {
  if (const auto* hertz = dynamic_cast<const HertzContact*>(spring.get()))
    return std::make_shared<PowerLawForce>(hertz->stiffness(), 1.5);
  return std::make_shared<LoadingBranch>(spring);
}

} // namespace

HuntCrossleyElasticPlasticImpact::HuntCrossleyElasticPlasticImpact(
    double mass, std::shared_ptr<const ElasticPlasticContact> spring, double damping,
    double velocity)
    : spring_(validated(spring)), loading_(mass, loading_branch(spring_), damping, velocity) {
  restitution_ = loading_.restitution();
  if (dynamic_cast<const HertzContact*>(spring_.get())) return; // unloads along F_L

  const double approach_max = loading_.approach_max();
  const HertzianUnloading branch = spring_->unloading(approach_max);
  const double branch_length = approach_max - branch.residual_approach;
  // W_U over the whole branch (x_r to x_max) and the part released above x = 0.
  const double branch_work = 0.4 * branch.stiffness * std::pow(branch_length, 2.5);
  const double released =
      branch.residual_approach < 0
          ? branch_work - 0.4 * branch.stiffness * std::pow(-branch.residual_approach, 2.5)
          : branch_work;
  // A branch that would return more than the loading stored: unload along F_L (no dent).
  if (!(released < spring_->loading_work(approach_max))) return;

  unloading_ = branch;
  separation_approach_ = std::max(0.0, branch.residual_approach);
  // v_out = -u q(b u), u = sqrt(2 E / m); the branch's own impact velocity V_U = u_w q(-b u_w)
  // with u_w from the whole branch's work (the two coincide unless x_r < 0).
  const double speed = std::sqrt(2 * released / mass);
  restitution_ = speed * detail::branch_ratio(damping * speed) / velocity;
  const double branch_speed = std::sqrt(2 * branch_work / mass);
  const double branch_velocity = branch_speed * detail::branch_ratio(-damping * branch_speed);
  unloading_impact_.emplace(mass, branch.stiffness, 1.5, damping, branch_velocity);
}

double HuntCrossleyElasticPlasticImpact::approach_rate(double approach, ImpactPhase phase) const {
  if (phase == ImpactPhase::compression || !unloading_impact_)
    return loading_.approach_rate(approach, phase);
  const double top = approach_max();
  if (!std::isfinite(approach) || approach < separation_approach_ * (1 - 4 * epsilon) ||
      approach > top * (1 + 4 * epsilon)) {
    std::ostringstream message;
    message.precision(17);
    message << "approach must be in [x_s = " << separation_approach_ << ", x_max = " << top
            << "] m while restoring (got " << approach << ")";
    throw InvalidInput("approach", message.str());
  }
  const double shifted =
      std::clamp(approach - unloading_.residual_approach, 0.0, unloading_impact_->approach_max());
  return unloading_impact_->approach_rate(shifted, ImpactPhase::restitution);
}

double HuntCrossleyElasticPlasticImpact::force(double approach, double approach_rate,
                                               ImpactPhase phase) const {
  const double spring_force =
      phase == ImpactPhase::compression || !unloading_impact_
          ? spring_->loading_force(approach)
          : unloading_.stiffness *
                std::pow(std::max(0.0, approach - unloading_.residual_approach), 1.5);
  return spring_force * (1 + damping() * approach_rate);
}

ImpactState HuntCrossleyElasticPlasticImpact::force_peak() const {
  return loading_.force_peak();
}

double HuntCrossleyElasticPlasticImpact::compression_time() const {
  return loading_.compression_time();
}

double HuntCrossleyElasticPlasticImpact::restitution_time() const {
  if (!unloading_impact_) return loading_.restitution_time();
  if (unloading_.residual_approach >= 0) return unloading_impact_->restitution_time();
  // The surfaces part at x = 0, before the branch has run out.
  return unloading_impact_->time_at_approach(-unloading_.residual_approach,
                                             ImpactPhase::restitution) -
         unloading_impact_->compression_time();
}

double HuntCrossleyElasticPlasticImpact::contact_time() const {
  return compression_time() + restitution_time();
}

HuntCrossleyElasticPlasticResponse HuntCrossleyElasticPlasticImpact::response() const {
  const auto [peak, compression] = loading_.force_peak_and_compression_time();
  return {approach_max(),
          peak.force,
          peak.time,
          compression,
          compression + restitution_time(),
          rebound_velocity(),
          restitution_,
          separation_approach_};
}

std::vector<ImpactState> HuntCrossleyElasticPlasticImpact::history(std::size_t points) const {
  if (points < 2)
    throw InvalidInput("points", "points must be >= 2 (got " + std::to_string(points) + ")");
  if (!unloading_impact_) return loading_.history(points);
  const double compression = compression_time();
  const double total = compression + restitution_time();
  // The unloading impact's clock: its own compression time marks our x_max.
  const double branch_compression = unloading_impact_->compression_time();
  const double branch_total = branch_compression + unloading_impact_->restitution_time();
  std::vector<ImpactState> states(points);
  states.front() = {0.0, 0.0, velocity(), 0.0};
  // Each phase's instants in one pass (states_at), on the clock of its own impact.
  std::vector<double> loading_times, unloading_times, restoring_times;
  for (std::size_t i = 1; i + 1 < points; ++i) {
    const double time = total * static_cast<double>(i) / static_cast<double>(points - 1);
    if (time <= compression) {
      loading_times.push_back(time);
    } else {
      restoring_times.push_back(time);
      unloading_times.push_back(std::min(branch_total, branch_compression + (time - compression)));
    }
  }
  const auto loaded = loading_.states_at(loading_times);
  const auto unloaded = unloading_impact_->states_at(unloading_times);
  std::copy(loaded.begin(), loaded.end(), states.begin() + 1);
  for (std::size_t j = 0; j < unloaded.size(); ++j) {
    ImpactState state = unloaded[j];
    state.time = restoring_times[j];
    state.approach += unloading_.residual_approach;
    states[1 + loaded.size() + j] = state;
  }
  const double rate = rebound_velocity();
  states.back() = {total, separation_approach_, rate,
                   force(separation_approach_, rate, ImpactPhase::restitution)};
  return states;
}

} // namespace impact::reduced
