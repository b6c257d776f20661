// impact-drop-simbody-custom EXPORT_DIR OUTPUT.json: drops the campaign's sphere on a plane in
// Simbody 3.7 under the damped elastic-plastic law of the export's restitution table, added
// to Simbody through its own extension point, SimTK::Force::Custom: the force
// F = F_s(x) (1 + b x') (damped_plastic_contact.hpp) on a one-degree-of-freedom slider, and
// the history variable x_max as a continuous state z of the force, z' = max(x', 0) (z = x
// while the sphere approaches, held once it recedes: integrated and error-controlled with the
// rest of the state). Measures e, t_c, F_max from Simbody's state at each campaign velocity
// and writes them with their errors (format "impact-simulator-run").

#include "damped_plastic_contact.hpp"
#include "simulator_run.hpp"

#include <Simbody.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace SimTK;
using impact::consumers::DampedPlasticContact;
using impact::consumers::DropFigures;
using impact::consumers::DropSample;

// The law as a Force::Custom on the slider's one mobility: approach x = q, rate x' = u.
class DampedPlasticForce : public Force::Custom::Implementation {
public:
  DampedPlasticForce(const GeneralForceSubsystem& forces, const MobilizedBody::Slider& sphere,
                     const DampedPlasticContact& law, double damping)
      : forces_(forces), sphere_(sphere), law_(law), damping_(damping) {}

  void realizeTopology(State& state) const override {
    // x_max starts at the initial approach (z = max of x over the past, x' > 0 before contact).
    approach_max_ = forces_.allocateZ(state, Vector(1, 0.0));
  }
  void realizeAcceleration(const State&) const override {}
  void realizeDynamics(const State& state) const override {
    forces_.updZDot(state)[approach_max_] =
        std::max(sphere_.getOneU(state, MobilizerUIndex(0)), 0.0);
  }
  double contact_force(const State& state) const {
    const double x = sphere_.getOneQ(state, MobilizerQIndex(0));
    const double rate = sphere_.getOneU(state, MobilizerUIndex(0));
    return law_.force(x, rate, forces_.getZ(state)[approach_max_], damping_);
  }
  void calcForce(const State& state, Vector_<SpatialVec>&, Vector_<Vec3>&,
                 Vector& mobilityForces) const override {
    sphere_.applyOneMobilityForce(state, MobilizerUIndex(0), -contact_force(state), mobilityForces);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }
  bool dependsOnlyOnPositions() const override { return false; }
  ZIndex z_index() const { return approach_max_; }

private:
  const GeneralForceSubsystem& forces_;
  const MobilizedBody::Slider& sphere_;
  const DampedPlasticContact& law_;
  double damping_;
  mutable ZIndex approach_max_;
};

// Integrator accuracy and samples per contact time, as the HuntCrossleyForce drop.
constexpr double accuracy = 1e-10;
constexpr int samples_per_contact = 4000;

DropFigures drop(const DampedPlasticContact& law, double velocity, double contact_time) {
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  // No gravity, as in the FEM: the sphere slides along ground x onto the plane at x = 0.
  Body::Rigid body(MassProperties(law.mass(), Vec3(0), UnitInertia(1)));
  MobilizedBody::Slider sphere(matter.Ground(), Transform(), body, Transform());
  auto* implementation = new DampedPlasticForce(forces, sphere, law, law.damping(velocity));
  Force::Custom force(forces, implementation); // owns the implementation
  system.realizeTopology();

  const double interval = contact_time / samples_per_contact;
  State state = system.getDefaultState();
  const double start = -0.5 * velocity * interval;
  sphere.setOneQ(state, MobilizerQIndex(0), start);
  sphere.setOneU(state, MobilizerUIndex(0), velocity);
  forces.updZ(state)[implementation->z_index()] = start;
  RungeKuttaMersonIntegrator integrator(system);
  integrator.setAccuracy(accuracy);
  TimeStepper stepper(system, integrator);
  stepper.initialize(state);
  std::vector<DropSample> samples;
  const auto record = [&](const State& s) {
    system.realize(s, Stage::Dynamics);
    samples.push_back(
        {s.getTime(), sphere.getOneQ(s, MobilizerQIndex(0)), implementation->contact_force(s)});
  };
  record(integrator.getState());
  for (int i = 1; i <= int(1.3 * samples_per_contact); ++i) {
    stepper.stepTo(i * interval);
    record(integrator.getState());
  }
  return impact::consumers::measure_drop(samples, velocity,
                                         -sphere.getOneU(integrator.getState(),
                                                         MobilizerUIndex(0)));
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: impact-drop-simbody-custom EXPORT_DIR OUTPUT.json\n");
    return 2;
  }
  try {
    const auto entries = impact::consumers::read_export(argv[1], "simbody-custom");
    const auto& entry = entries.front();
    const DampedPlasticContact law(entry.directory / entry.file);
    std::vector<DropFigures> measured;
    for (std::size_t i = 0; i < entry.velocities.size(); ++i)
      measured.push_back(drop(law, entry.velocities[i], entry.reduced_model[i].contact_time));
    int major = 0, minor = 0, build = 0;
    SimTK_version_simbody(&major, &minor, &build);
    const std::string version = std::to_string(major) + "." + std::to_string(minor);
    impact::consumers::write_simulator_run(argv[2], entry, version, measured);
    impact::consumers::print_simulator_run(entry, measured);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impact-drop-simbody-custom: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
