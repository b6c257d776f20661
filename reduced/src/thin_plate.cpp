// Zener's model of a sphere on an infinite thin plate (see thin_plate.hpp), integrated in
// Zener's units with the library's event-located Cash–Karp stepper (event_stepping.hpp).
//
// Scaled state y = (sigma, u, s, q_plate, q_damping): approach x / x0, sphere velocity v / V,
// sphere displacement z / x0, and the energies radiated into the plate and dissipated by
// the contact damper, both over m V^2. With phi = F t0 / (m V):
//     sigma' = u - lambda phi,  u' = -phi,  s' = u,
//     q_plate' = lambda phi^2,  q_damping' = beta sigma^n sigma'^2.
// (u^2/2 + sigma^(n+1)/(n+1) + q_plate + q_damping is conserved: the tests check it.)

#include "impact_reduced/thin_plate.hpp"

#include "impact_reduced/contact_formulas.hpp"
#include "impact_reduced/invalid_input.hpp"

#include "event_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>

namespace impact::reduced {

namespace {

using detail::describe;
using Stepper = detail::EventStepper<5>;
using State = Stepper::State;

constexpr double pi = 3.14159265358979323846;
constexpr double time_limit = 1e7;          // in Zener time units t0
constexpr std::size_t step_limit = 1000000; // accepted steps

void validate(const KirchhoffPlate& plate) {
  require_positive("plate.youngs_modulus", plate.youngs_modulus);
  require_open_interval("plate.poisson_ratio", plate.poisson_ratio, -1.0, 0.5);
  require_positive("plate.density", plate.density);
  require_positive("plate.thickness", plate.thickness);
}

void require_tolerance(double relative_tolerance) {
  if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-3))
    throw InvalidInput("relative_tolerance",
                       "relative_tolerance must be a number in [1e-14, 1e-3] (got " +
                           describe(relative_tolerance) + ")");
}

class ThinPlateIntegration {
public:
  ThinPlateIntegration(const ThinPlateImpact& system, double velocity, double relative_tolerance)
      : exponent_(system.exponent()),
        beta_(system.damping() * velocity),
        lambda_(system.zener_lambda(velocity)) {
    require_tolerance(relative_tolerance);
    time_unit_ = std::pow(system.mass() * std::pow(velocity, 1 - exponent_) / system.stiffness(),
                          1 / (exponent_ + 1));
    length_unit_ = velocity * time_unit_;
    force_unit_ = system.mass() * velocity / time_unit_;
    stepper_.emplace([this](const State& y, State& dydt) { rhs(y, dydt); }, relative_tolerance,
                     time_unit_);
    run();
    std::tie(force_max_, time_force_max_) = stepper_->locate_maximum(
        separation_, [this](const State& y) { return force(y); },
        [this](const State& y) { return force_rate(y); });
  }

  ThinPlateImpactResult result() const {
    ThinPlateImpactResult result{};
    result.restitution = -separation_[1];
    result.contact_time = time_unit_ * contact_time_;
    result.force_max = force_unit_ * force_max_;
    result.time_force_max = time_unit_ * time_force_max_;
    result.approach_max = length_unit_ * approach_max_;
    result.time_approach_max = time_unit_ * time_approach_max_;
    result.plate_energy_fraction = 2 * separation_[3];
    result.damping_energy_fraction = 2 * separation_[4];
    result.plate_deflection = length_unit_ * separation_[2]; // w = z - x, x = 0
    result.number_of_contacts = 1;                           // the only one: see thin_plate.hpp
    result.zener_lambda = lambda_;
    return result;
  }

  std::vector<ThinPlateSample> history(std::size_t points) const {
    std::vector<ThinPlateSample> samples;
    for (const auto& [tau, y] : stepper_->sample_uniformly(points, contact_time_, separation_))
      samples.push_back({time_unit_ * tau, length_unit_ * y[0], length_unit_ / time_unit_ * y[1],
                         length_unit_ * (y[2] - y[0]), force_unit_ * force(y)});
    return samples;
  }

private:
  // sigma^n, 0 out of contact.
  double elastic(const State& y) const { return y[0] > 0 ? std::pow(y[0], exponent_) : 0.0; }

  // phi: the explicit solution of phi = sigma^n (1 + beta (u - lambda phi)), no tension.
  double force(const State& y) const {
    const double s = elastic(y);
    return std::max(s * (1 + beta_ * y[1]) / (1 + beta_ * lambda_ * s), 0.0);
  }

  double approach_rate(const State& y) const { return y[1] - lambda_ * force(y); }

  void rhs(const State& y, State& dydt) const {
    const double phi = force(y);
    const double rate = y[1] - lambda_ * phi;
    dydt[0] = rate;
    dydt[1] = -phi;
    dydt[2] = y[1];
    dydt[3] = lambda_ * phi * phi;
    dydt[4] = beta_ * elastic(y) * rate * rate;
  }

  // dphi/dtau = (1 + beta u) n sigma^(n-1) sigma' / (1 + beta lambda s)^2
  //             - beta s phi / (1 + beta lambda s),   s = sigma^n.
  double force_rate(const State& y) const {
    if (!(y[0] > 0)) return 0;
    const double s = elastic(y);
    const double denominator = 1 + beta_ * lambda_ * s;
    const double phi = force(y);
    return (1 + beta_ * y[1]) * exponent_ * std::pow(y[0], exponent_ - 1) * approach_rate(y) /
               (denominator * denominator) -
           beta_ * s * phi / denominator;
  }

  // Separation: x back at 0 or, first (which the model excludes), 1 + b v at 0.
  double contact_margin(const State& y) const { return std::min(y[0], 1 + beta_ * y[1]); }

  void run() {
    State y{0.0, 1.0, 0.0, 0.0, 0.0};
    double tau = 0;
    double dtau = 1e-3;
    bool compressing = true;
    while (true) {
      if (stepper_->steps().size() >= step_limit || tau > time_limit) {
        std::ostringstream message;
        message.precision(6);
        message << "the sphere does not leave the plate: after " << stepper_->steps().size()
                << " steps, at t = " << time_unit_ * tau << " s, approach " << length_unit_ * y[0]
                << " m, sphere velocity " << length_unit_ / time_unit_ * y[1] << " m/s";
        throw std::runtime_error(message.str());
      }
      const auto& step = stepper_->step(y, tau, dtau);
      const State start = step.state;
      double event_start = 0;
      if (compressing && approach_rate(y) <= 0) {
        const double h = stepper_->locate(start, 0.0, step.length,
                                          [this](const State& s) { return approach_rate(s); });
        time_approach_max_ = step.start + h;
        approach_max_ = stepper_->advance(start, h)[0];
        compressing = false;
        event_start = h;
      }
      if (!compressing && contact_margin(y) <= 0) {
        const double h = stepper_->locate(start, event_start, step.length,
                                          [this](const State& s) { return contact_margin(s); });
        separation_ = stepper_->advance(start, h);
        if (separation_[0] < 0) separation_[0] = 0; // the located root, without its rounding
        stepper_->truncate_last_step(h);
        contact_time_ = step.start + h;
        return;
      }
    }
  }

  double exponent_;
  double beta_;
  double lambda_;
  double time_unit_ = 0;
  double length_unit_ = 0;
  double force_unit_ = 0;
  std::optional<Stepper> stepper_;
  double approach_max_ = 0;
  double time_approach_max_ = 0;
  double contact_time_ = 0;
  State separation_{};
  double force_max_ = 0;
  double time_force_max_ = 0;
};

} // namespace

double flexural_rigidity(const KirchhoffPlate& plate) {
  validate(plate);
  const double h = plate.thickness;
  return plate.youngs_modulus * h * h * h / (12 * (1 - plate.poisson_ratio * plate.poisson_ratio));
}

double plate_point_impedance(const KirchhoffPlate& plate) {
  return 8 * std::sqrt(flexural_rigidity(plate) * plate.density * plate.thickness);
}

ThinPlateImpact::ThinPlateImpact(double stiffness, double exponent, double damping, double mass,
                                 double impedance)
    : stiffness_(stiffness),
      exponent_(exponent),
      damping_(damping),
      mass_(mass),
      impedance_(impedance) {
  require_positive("stiffness", stiffness);
  require_positive("exponent", exponent);
  require_non_negative("damping", damping);
  require_positive("mass", mass);
  if (!(impedance > 0)) // NaN fails too; +infinity is the rigid plate
    throw InvalidInput("impedance",
                       "impedance must be a number > 0, +infinity for a rigid "
                       "plate (got " +
                           describe(impedance) + ")");
}

double ThinPlateImpact::zener_lambda(double velocity) const {
  require_positive("velocity", velocity);
  const double t0 =
      std::pow(mass_ * std::pow(velocity, 1 - exponent_) / stiffness_, 1 / (exponent_ + 1));
  return mass_ / (impedance_ * t0);
}

ThinPlateImpactResult ThinPlateImpact::impact(double velocity, double relative_tolerance) const {
  require_positive("velocity", velocity);
  return ThinPlateIntegration(*this, velocity, relative_tolerance).result();
}

std::vector<ThinPlateSample> ThinPlateImpact::history(double velocity, std::size_t points,
                                                      double relative_tolerance) const {
  require_positive("velocity", velocity);
  if (points < 2)
    throw InvalidInput("points",
                       "points must be a whole number >= 2 (got " + std::to_string(points) + ")");
  return ThinPlateIntegration(*this, velocity, relative_tolerance).history(points);
}

double zener_lambda(double sphere_radius, double sphere_density, double sphere_youngs_modulus,
                    double sphere_poisson_ratio, const KirchhoffPlate& plate, double velocity) {
  require_positive("sphere_radius", sphere_radius);
  require_positive("sphere_density", sphere_density);
  require_positive("sphere_youngs_modulus", sphere_youngs_modulus);
  require_open_interval("sphere_poisson_ratio", sphere_poisson_ratio, -1.0, 0.5);
  validate(plate);
  require_positive("velocity", velocity);
  const double mass =
      4.0 / 3.0 * pi * sphere_radius * sphere_radius * sphere_radius * sphere_density;
  const double stiffness =
      hertz_stiffness({sphere_youngs_modulus, sphere_poisson_ratio, sphere_radius},
                      {plate.youngs_modulus, plate.poisson_ratio});
  return ThinPlateImpact(stiffness, 1.5, 0.0, mass, plate_point_impedance(plate))
      .zener_lambda(velocity);
}

} // namespace impact::reduced
