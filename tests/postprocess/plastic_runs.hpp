#pragma once
// Runs made by Thornton's elastic-plastic law (1997), written again here and integrated by
// the library's general impact ODE with the maximum approach known from the energy, with the
// scenario recorded as impact-fem records an elastic-plastic sphere on a rigid flat.

#include "synthetic_runs.hpp"

#include <impact_reduced/impact_ode.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace impact::testing {

/// The impact of a rate-independent elastic-plastic `law` (its loading branch while x' >= 0,
/// its unloading branch after) at `velocity`, integrated by the general impact ODE at 1e-12
/// until the force returns to 0, sampled like synthetic_run.
inline postprocess::FemRun plastic_law_run(double mass, double velocity,
                                           const reduced::ContactForceLaw& law) {
  const auto impact =
      reduced::integrate_impact(mass, velocity, law, 1e-12, reduced::ContactEnd::zero_force);
  return sampled_run(mass, velocity, impact.restitution, impact.contact_time, impact.force_max,
                     impact.time_force_max, impact.approach_max, impact.approach_at_separation,
                     impact.rebound_velocity,
                     reduced::integrate_impact_history(mass, velocity, law, 301, 1e-12,
                                                       reduced::ContactEnd::zero_force));
}

/// The scenario as impact-fem records an elastic-plastic sphere (Young's modulus E, Poisson
/// ratio nu, yield strength Y, radius R) on a rigid flat.
inline void record_elastic_plastic_sphere(postprocess::FemRun& run, double youngs_modulus,
                                          double poisson_ratio, double yield_strength,
                                          double radius) {
  run.text_attributes["Sphere/Material model"] = "elastic-plastic";
  run.text_attributes["Sphere/Elastic-plastic/Young's modulus"] = exact_text(youngs_modulus);
  run.text_attributes["Sphere/Elastic-plastic/Poisson's ratio"] = exact_text(poisson_ratio);
  run.text_attributes["Sphere/Elastic-plastic/Yield strength"] = exact_text(yield_strength);
  run.text_attributes["Plate/Material model"] = "rigid";
  run.text_attributes["Scenario/Sphere radius"] = exact_text(radius);
}

constexpr double pi = 3.14159265358979323846;

// Steel ball R = 10 mm on steel (E* = 2.1e11 / 1.82 Pa), Johnson's p_y for Y = 1 GPa.
struct Truth {
  double mass = 0.1, radius = 0.01, contact_modulus = 2.1e11 / 1.82, yield_pressure = 1.6e9;
  double stiffness() const { return 4.0 / 3.0 * contact_modulus * std::sqrt(radius); }
  double yield_approach() const {
    const double ratio = pi * yield_pressure / (2 * contact_modulus);
    return radius * ratio * ratio;
  }
};

// Thornton's law at velocity V, written again: Hertz to x_y, slope pi p_y R, unloading
// (4/3) E* sqrt(R_p) (x - x_p)^(3/2) with a_p^2 = (2 F* + F_y) / (2 pi p_y),
// R_p = 4 E* a_p^3 / (3 F*), x_p = x_max - 3 F* / (4 E* a_p); x_max from the energy. At or
// below the yield velocity the impact is Hertz's (elastic, e = 1).
inline postprocess::FemRun thornton_run(const Truth& t, double velocity) {
  const double c = t.stiffness(), x_y = t.yield_approach(), f_y = c * std::pow(x_y, 1.5);
  const double slope = pi * t.yield_pressure * t.radius;
  const double plastic_energy = 0.5 * t.mass * velocity * velocity - 0.4 * f_y * x_y;
  const double excess = (-f_y + std::sqrt(f_y * f_y + 2 * slope * plastic_energy)) / slope;
  const double x_max = x_y + excess, f_max = f_y + slope * excess;
  const double a_p = std::sqrt((2 * f_max + f_y) / (2 * pi * t.yield_pressure));
  const double r_p = 4 * t.contact_modulus * a_p * a_p * a_p / (3 * f_max);
  const double x_p = x_max - 3 * f_max / (4 * t.contact_modulus * a_p);
  const double k_u = 4.0 / 3.0 * t.contact_modulus * std::sqrt(r_p);
  const bool elastic = !(plastic_energy > 0);
  const reduced::ContactForceLaw law = [=](double x, double rate) {
    if (elastic) return c * std::pow(std::max(x, 0.0), 1.5);
    if (rate >= 0) return x <= x_y ? c * std::pow(std::max(x, 0.0), 1.5) : f_y + slope * (x - x_y);
    return k_u * std::pow(std::max(x - x_p, 0.0), 1.5);
  };
  postprocess::FemRun run = plastic_law_run(t.mass, velocity, law);
  run.source = "thornton_v" + std::to_string(velocity);
  // E* = E / (1 - nu^2) of the sphere on the rigid flat, Y = p_y / 1.6.
  record_elastic_plastic_sphere(run, t.contact_modulus * (1 - 0.09), 0.3, t.yield_pressure / 1.6,
                                t.radius);
  return run;
}

} // namespace impact::testing
