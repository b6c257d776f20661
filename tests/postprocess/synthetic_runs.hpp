#pragma once
// FEM-format runs made by the reduced library itself: the Hunt–Crossley impact with known
// (c, n, b), sampled like impact-fem (300 steps per contact time, continued after
// separation), optionally with Gaussian noise of a given fraction of each history's peak;
// and the same for any comparison law (e.g. Kuwabara–Kono without tension), with the
// bodies' materials recorded as impact-fem records its parameters.

#include "impact_postprocess/run/fem_run.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

namespace impact::testing {

struct HuntCrossleyTruth {
  double mass = 0.1;         // kg
  double stiffness = 1.0e10; // N/m^n
  double exponent = 1.45;
  double damping = 0.1; // s/m
};

// The samples of an impact (first contact to separation, `steps` + 1 of them), then 60 more
// steps of free flight after separation (the plate is rigid here, so approach rate = sphere
// velocity), in impact-fem's format.
template <class Sample>
postprocess::FemRun sampled_run(double mass, double velocity, double restitution,
                                double contact_time, double force_max, double time_force_max,
                                double approach_max, double approach_at_separation,
                                double rebound_velocity, const std::vector<Sample>& history) {
  postprocess::FemRun run;
  run.impact_velocity = velocity;
  run.mass = mass;
  run.restitution = restitution;
  run.first_contact_time = 0;
  run.contact_time = contact_time;
  run.force_max = force_max;
  run.time_force_max = time_force_max;
  run.approach_max = approach_max;
  for (const auto& sample : history) {
    run.time.push_back(sample.time);
    run.contact_force.push_back(std::max(sample.force, 0.0));
    run.approach.push_back(sample.approach);
    run.sphere_velocity.push_back(sample.approach_rate);
  }
  const std::size_t steps = history.size() - 1;
  const double step = contact_time / double(steps);
  for (std::size_t k = steps + 1; k <= steps + 60; ++k) {
    const double t = double(k) * step;
    run.time.push_back(t);
    run.contact_force.push_back(0);
    run.approach.push_back(approach_at_separation + rebound_velocity * (t - contact_time));
    run.sphere_velocity.push_back(rebound_velocity);
  }
  return run;
}

inline postprocess::FemRun synthetic_run(const HuntCrossleyTruth& truth, double velocity,
                                         double noise = 0, unsigned seed = 1) {
  const reduced::HuntCrossleyImpact impact(truth.mass, truth.stiffness, truth.exponent,
                                           truth.damping, velocity);
  const auto response = impact.response();
  postprocess::FemRun run =
      sampled_run(truth.mass, velocity, response.restitution, response.contact_time,
                  response.force_max, response.time_force_max, response.approach_max, 0.0,
                  response.rebound_velocity, impact.history(301));
  if (noise > 0) {
    std::mt19937 generator(seed);
    std::normal_distribution<double> normal(0, 1);
    for (std::size_t i = 0; i < run.time.size(); ++i) {
      run.contact_force[i] += noise * response.force_max * normal(generator);
      run.approach[i] += noise * response.approach_max * normal(generator);
      run.sphere_velocity[i] += noise * velocity * normal(generator);
    }
  }
  return run;
}

/// An impact of comparison law `law` (damping constant `damping`, c and n of `setup`) at
/// `velocity`, sampled like synthetic_run: 300 steps over the contact, 60 after separation
/// (free flight at the rebound speed from the approach at separation).
inline postprocess::FemRun synthetic_law_run(const reduced::ComparisonLaw& law,
                                             const reduced::ContactSetup& setup, double damping,
                                             double velocity) {
  const auto force = law.force_law(damping, setup);
  const auto impact =
      reduced::integrate_impact(setup.mass, velocity, force, 1e-12, law.contact_end);
  return sampled_run(setup.mass, velocity, impact.restitution, impact.contact_time,
                     impact.force_max, impact.time_force_max, impact.approach_max,
                     impact.approach_at_separation, impact.rebound_velocity,
                     reduced::integrate_impact_history(setup.mass, velocity, force, 301, 1e-12,
                                                       law.contact_end));
}

/// A number as text with every digit (impact-fem's parameters are text attributes).
/// The report tests' campaign run: Hunt–Crossley with b growing with V (so that one constant b
/// cannot hold everywhere), and the scenario's materials (steel on steel) and sphere radius
/// recorded as impact-fem records them.
inline postprocess::FemRun campaign_run(double velocity) {
  HuntCrossleyTruth truth;
  truth.damping = 0.06 + 0.03 * velocity;
  postprocess::FemRun run = synthetic_run(truth, velocity);
  for (const std::string body : {"Sphere", "Plate"}) {
    run.text_attributes[body + "/Material model"] = "elastic";
    run.text_attributes[body + "/Elastic/Young's modulus"] = "2e11";
    run.text_attributes[body + "/Elastic/Poisson's ratio"] = "0.25";
  }
  run.text_attributes["Scenario/Sphere radius"] = "0.01452";
  return run;
}

inline std::string exact_text(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

/// The scenario parameters of two Kelvin–Voigt bodies and the sphere radius, as impact-fem
/// stores them (text attributes of the run file).
inline void record_kelvin_voigt_materials(postprocess::FemRun& run, double youngs_modulus,
                                          double poisson_ratio, double deviatoric_time,
                                          double volumetric_time, double sphere_radius) {
  for (const std::string body : {"Sphere", "Plate"}) {
    run.text_attributes[body + "/Material model"] = "kelvin-voigt";
    run.text_attributes[body + "/Kelvin-voigt/Young's modulus"] = exact_text(youngs_modulus);
    run.text_attributes[body + "/Kelvin-voigt/Poisson's ratio"] = exact_text(poisson_ratio);
    run.text_attributes[body + "/Kelvin-voigt/Retardation time"] = exact_text(deviatoric_time);
    run.text_attributes[body + "/Kelvin-voigt/Volumetric retardation time"] =
        exact_text(volumetric_time);
  }
  run.text_attributes["Scenario/Sphere radius"] = exact_text(sphere_radius);
}

/// A fresh directory for one test's files.
inline std::filesystem::path scratch_directory(const std::string& name) {
  const auto directory = std::filesystem::temp_directory_path() /
                         ("impact_postprocess_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

/// One quantity of impact-fem's verification.json, the same on every level: its value `fine`,
/// relative GCI `relative` (a number, or null where impact-fem has none) and absolute GCI.
inline nlohmann::json verification_quantity(double fine, nlohmann::json relative, double absolute) {
  return nlohmann::json{{"unit", "1"},
                        {"fine", fine},
                        {"medium", fine},
                        {"coarse", fine},
                        {"observed_order", 2.0},
                        {"extrapolated", fine},
                        {"gci_fine", std::move(relative)},
                        {"gci_fine_absolute", absolute},
                        {"convergence", "monotone"}};
}

/// impact-fem's verification.json of `run` with these quantities (verification_quantity).
inline nlohmann::json verification_json(nlohmann::json quantities) {
  return nlohmann::json{{"format", "impact-verification"},
                        {"format_version", 1},
                        {"refinement_ratio", 1.5},
                        {"levels", nlohmann::json::array()},
                        {"quantities", std::move(quantities)}};
}

/// The verification.json of impact-fem in `directory` (a run's folder), with relative GCI `gci`
/// of t_c, t(F_max) and x_max, 2 gci of F_max and gci / 2 of e.
inline void write_verification(const std::filesystem::path& directory,
                               const postprocess::FemRun& run, double gci) {
  const auto quantity = [](double fine, double relative) {
    return verification_quantity(fine, relative, relative * fine);
  };
  std::ofstream(directory / "verification.json")
      << verification_json({{"contact_time", quantity(run.contact_time, gci)},
                            {"force_max", quantity(run.force_max, 2 * gci)},
                            {"time_force_max", quantity(run.time_force_max, gci)},
                            {"approach_max", quantity(run.approach_max, gci)},
                            {"restitution", quantity(run.restitution, 0.5 * gci)}})
             .dump(2);
}

} // namespace impact::testing
