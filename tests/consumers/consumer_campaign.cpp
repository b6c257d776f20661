// consumer-campaign DIR: a small campaign in impact-fem's format made by the reduced library,
// so that the consumer tests calibrate and export without running the FEM. The sphere is a
// viscoelastic (Kuwabara–Kono) steel ball like the default study's: m = 0.1 kg,
// R = 14.52 mm, c = 1.76e10 N/m^1.5, A = 1.17 us; V = 0.5, 1, 2, 5 m/s, 300 samples per
// contact time and free flight after separation. The runs also record an elastic-plastic
// material for both bodies (the DEM export reads it; the histories stay viscoelastic): the
// Young's modulus that gives the same Hertz c, E = 2 (1 - nu^2) (3 c / (4 sqrt(R))) with
// nu = 0.3, and Y = 1.39 GPa, a test value chosen so that Thornton's yield velocity
// (p_y = 1.6 Y) is 0.343 m/s and the campaign spans V/V_y = 1.5 to 15; and the retardation
// time 1.17 us of both bodies (A = tau for equal bodies), so that the calibration has the
// damped elastic-plastic laws from the material, which yield at these velocities (the
// restitution table and its runs in Simbody and LAMMPS).

#include "impact_postprocess/run/fem_run.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer-campaign DIR\n");
    return 2;
  }
  try {
    namespace reduced = impact::reduced;
    const double mass = 0.1, stiffness = 1.76e10, dissipative_constant = 1.17e-6;
    const reduced::ContactSetup setup{mass, stiffness, 1.5};
    const auto law =
        reduced::comparison_law("kuwabara-kono").force_law(dissipative_constant, setup);
    for (double velocity : {0.5, 1.0, 2.0, 5.0}) {
      const auto result = reduced::integrate_impact(mass, velocity, law, 1e-12);
      const std::size_t steps = 300;
      const auto history = reduced::integrate_impact_history(mass, velocity, law, steps + 1, 1e-12);
      impact::postprocess::FemRun run;
      run.impact_velocity = velocity;
      run.mass = mass;
      run.restitution = result.restitution;
      run.first_contact_time = 0;
      run.contact_time = result.contact_time;
      run.force_max = result.force_max;
      run.time_force_max = result.time_force_max;
      run.approach_max = result.approach_max;
      for (const auto& sample : history) {
        run.time.push_back(sample.time);
        run.contact_force.push_back(sample.force);
        run.approach.push_back(sample.approach);
        run.sphere_velocity.push_back(sample.approach_rate);
      }
      const double step = result.contact_time / double(steps);
      for (std::size_t k = steps + 1; k <= steps + 60; ++k) {
        const double t = double(k) * step;
        run.time.push_back(t);
        run.contact_force.push_back(0);
        run.approach.push_back(result.rebound_velocity * (t - result.contact_time));
        run.sphere_velocity.push_back(result.rebound_velocity);
      }
      run.text_attributes["Scenario/Sphere radius"] = "0.01452";
      const double youngs_modulus = 2 * (1 - 0.3 * 0.3) * 3 * stiffness / (4 * std::sqrt(0.01452));
      char young[32];
      std::snprintf(young, sizeof young, "%.17g", youngs_modulus);
      for (const char* body : {"Sphere", "Plate"}) {
        const std::string name = body;
        run.text_attributes[name + "/Material model"] = "elastic-plastic";
        run.text_attributes[name + "/Elastic-plastic/Young's modulus"] = young;
        run.text_attributes[name + "/Elastic-plastic/Poisson's ratio"] = "0.3";
        run.text_attributes[name + "/Elastic-plastic/Yield strength"] = "1.39e9";
        run.text_attributes[name + "/Elastic-plastic/Retardation time"] = "1.17e-6";
      }
      impact::postprocess::write_fem_run(run, std::filesystem::path(argv[1]) /
                                                  ("v" + std::to_string(velocity)));
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "consumer-campaign: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
