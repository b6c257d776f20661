// impact-drop-simbody EXPORT_DIR OUTPUT.json: drops the campaign's sphere on a half-space in
// Simbody 3.7 with the exported HuntCrossleyForce parameters (the header impact_contact.hpp
// of the export, compiled in) at each campaign velocity, measures restitution, contact time
// and peak force from Simbody's own state, and writes them with their errors (format
// "impact-simulator-run").

#include "impact_contact.hpp"
#include "simulator_run.hpp"

#include <Simbody.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using namespace SimTK;
using impact::consumers::DropFigures;
using impact::consumers::DropSample;

// Integrator accuracy and samples per contact: with these the measured figures agree with
// the closed form of Hunt-Crossley to about 1e-8 (tests/consumers).
constexpr double accuracy = 1e-10;
constexpr int samples_per_contact = 4000;

DropFigures drop(double velocity) {
  const double mass = impact_contact::sphere_mass;
  const double radius = impact_contact::sphere_radius;
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  GeneralContactSubsystem contacts(system);
  const ContactSetIndex set = contacts.createContactSet();
  // The sphere slides along ground x towards the half-space x > 0; no gravity, as in the FEM.
  Body::Rigid body(MassProperties(mass, Vec3(0), UnitInertia(1)));
  MobilizedBody::Slider sphere(matter.Ground(), Transform(), body, Transform());
  contacts.addBody(set, sphere, ContactGeometry::Sphere(radius), Transform());
  contacts.addBody(set, matter.Ground(), ContactGeometry::HalfSpace(), Transform());
  HuntCrossleyForce contact(forces, contacts, set);
  impact_contact::set_body_parameters(contact, ContactSurfaceIndex(0), ContactSurfaceIndex(1));
  system.realizeTopology();

  // Hertz's contact time of the law (c = k sqrt(2 R) / 3) sets the sampling.
  const double c = impact_contact::stiffness * std::sqrt(2 * radius) / 3;
  const double hertz_time = 2.94 * std::pow(5 * mass / (4 * c), 0.4) * std::pow(velocity, -0.2);
  const double interval = hertz_time / samples_per_contact;

  State state = system.getDefaultState();
  sphere.setQ(state, -radius - 0.5 * velocity * interval);
  sphere.setU(state, velocity);
  RungeKuttaMersonIntegrator integrator(system);
  integrator.setAccuracy(accuracy);
  TimeStepper stepper(system, integrator);
  stepper.initialize(state);
  std::vector<DropSample> samples;
  const auto record = [&](const State& s) {
    system.realize(s, Stage::Acceleration);
    samples.push_back({s.getTime(), sphere.getQ(s) + radius, -mass * sphere.getUDot(s)});
  };
  record(integrator.getState());
  for (int i = 1; i <= int(1.6 * samples_per_contact); ++i) {
    stepper.stepTo(i * interval);
    record(integrator.getState());
  }
  return impact::consumers::measure_drop(samples, velocity, -sphere.getU(integrator.getState()));
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: impact-drop-simbody EXPORT_DIR OUTPUT.json\n");
    return 2;
  }
  try {
    const auto entries = impact::consumers::read_export(argv[1], "simbody");
    const auto& entry = entries.front();
    if (std::abs(entry.mass / impact_contact::sphere_mass - 1) > 1e-12 ||
        std::abs(entry.radius / impact_contact::sphere_radius - 1) > 1e-12) {
      std::fprintf(stderr,
                   "impact-drop-simbody: the compiled impact_contact.hpp is not the one "
                   "of %s (sphere mass or radius differ): rebuild against it\n",
                   argv[1]);
      return 2;
    }
    std::vector<DropFigures> measured;
    for (double velocity : entry.velocities) measured.push_back(drop(velocity));
    int major = 0, minor = 0, build = 0;
    SimTK_version_simbody(&major, &minor, &build);
    impact::consumers::write_simulator_run(argv[2], entry,
                                           std::to_string(major) + "." + std::to_string(minor),
                                           measured);
    impact::consumers::print_simulator_run(entry, measured);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impact-drop-simbody: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
