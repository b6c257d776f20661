// impact-drop-lammps-external EXPORT_DIR OUTPUT_DIR: drops the campaign's sphere on a wall in
// LAMMPS, through its library interface (liblammps), under the damped elastic-plastic law of
// the export's restitution table, added through LAMMPS's own extension point for forces
// computed outside it: fix external in pf/callback mode. At every step the callback reads the
// sphere's height z and velocity from LAMMPS, computes the wall's force
// F = F_s(x) (1 + b x') (damped_plastic_contact.hpp; x = R - z, x' = -v_z) with the history
// variable x_max kept between calls, and hands it back to LAMMPS, whose fix nve/sphere
// integrates the motion (velocity Verlet: the force sees the half-step velocity, as LAMMPS's
// own granular contacts do, so the integration is first order in the step). Measures e, t_c
// and F_max at each campaign velocity with N = 2000 steps per contact time of the law, and
// again with 4000 ("refined"), and writes OUTPUT_DIR/lammps-external.json (format
// "impact-simulator-run").

#include "damped_plastic_contact.hpp"
#include "simulator_run.hpp"

#include <lammps/library.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using impact::consumers::DampedPlasticContact;
using impact::consumers::DropFigures;
using impact::consumers::DropSample;

constexpr int steps_per_contact = 2000, refined_steps_per_contact = 4000;
constexpr double pi = 3.14159265358979323846;
int lammps_date = 0; // LAMMPS's version, read from the first instance

// What the callback needs between calls: the law, the LAMMPS instance (for the velocities),
// the history variable x_max and the samples of the drop.
struct Drop {
  const DampedPlasticContact* law;
  void* lammps;
  double radius, damping, time_step;
  double approach_max = 0;
  std::vector<DropSample> samples;
};

// fix external's callback (LAMMPS_SMALLBIG: int64_t step, int tags): the force on the one
// atom, along +z (away from the wall at z = 0).
void wall_force(void* context, int64_t step, int local_atoms, int*, double** positions,
                double** forces) {
  auto& drop = *static_cast<Drop*>(context);
  if (local_atoms != 1) return;
  auto** velocities = static_cast<double**>(lammps_extract_atom(drop.lammps, "v"));
  const double approach = drop.radius - positions[0][2];
  const double rate = -velocities[0][2];
  const double force = drop.law->force(approach, rate, drop.approach_max, drop.damping);
  drop.approach_max = std::max(drop.approach_max, approach);
  forces[0][0] = forces[0][1] = 0;
  forces[0][2] = force;
  drop.samples.push_back({double(step) * drop.time_step, approach, force});
}

void command(void* lammps, const std::string& line) {
  lammps_command(lammps, line.c_str());
  if (lammps_has_error(lammps)) {
    char message[2048];
    lammps_get_last_error_message(lammps, message, sizeof message);
    throw std::runtime_error("LAMMPS: '" + line + "': " + message);
  }
}

std::string text(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

DropFigures drop(const DampedPlasticContact& law, double radius, double velocity,
                 double contact_time, int steps) {
  const char* arguments[] = {"impact", "-log", "none", "-screen", "none", "-nocite"};
  void* lammps = lammps_open_no_mpi(6, const_cast<char**>(arguments), nullptr);
  if (!lammps) throw std::runtime_error("lammps_open_no_mpi failed");
  lammps_date = lammps_version(lammps);
  Drop state{&law, lammps, radius, law.damping(velocity), contact_time / steps, 0.0, {}};
  try {
    const double size = 4 * radius;
    // The sphere touches the wall half a step after the start.
    const double height = radius + 0.5 * velocity * state.time_step;
    for (const std::string& line :
         {std::string("units si"), std::string("atom_style sphere"),
          std::string("atom_modify map array"), std::string("boundary f f f"),
          "region box block " + text(-size) + " " + text(size) + " " + text(-size) + " " +
              text(size) + " " + text(-size) + " " + text(size),
          std::string("create_box 1 box"), "create_atoms 1 single 0 0 " + text(height),
          "set atom 1 diameter " + text(2 * radius),
          "set atom 1 density " + text(law.mass() / (4.0 / 3.0 * pi * radius * radius * radius)),
          "velocity all set 0 0 " + text(-velocity), std::string("fix move all nve/sphere"),
          std::string("fix contact all external pf/callback 1 1"),
          "timestep " + text(state.time_step)})
      command(lammps, line);
    lammps_set_fix_external_callback(lammps, "contact", wall_force, &state);
    command(lammps, "run " + std::to_string(int(1.3 * steps)));
    auto** velocities = static_cast<double**>(lammps_extract_atom(lammps, "v"));
    const double rebound = velocities[0][2];
    lammps_close(lammps);
    return impact::consumers::measure_drop(state.samples, velocity, rebound);
  } catch (...) {
    lammps_close(lammps);
    throw;
  }
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: impact-drop-lammps-external EXPORT_DIR OUTPUT_DIR\n");
    return 2;
  }
  try {
    const fs::path output = fs::path(argv[2]) / "lammps-external.json";
    const auto entries = impact::consumers::read_export(argv[1], "lammps-external");
    const auto& entry = entries.front();
    const DampedPlasticContact law(entry.directory / entry.file);
    std::vector<DropFigures> measured, refined;
    for (std::size_t i = 0; i < entry.velocities.size(); ++i) {
      const double velocity = entry.velocities[i],
                   contact_time = entry.reduced_model[i].contact_time;
      measured.push_back(drop(law, entry.radius, velocity, contact_time, steps_per_contact));
      refined.push_back(drop(law, entry.radius, velocity, contact_time, refined_steps_per_contact));
    }
    impact::consumers::write_simulator_run(output, entry, std::to_string(lammps_date), measured);
    // The same drops at half the step: the error's trend.
    nlohmann::json result;
    {
      std::ifstream in(output);
      result = nlohmann::json::parse(in);
    }
    nlohmann::json runs = nlohmann::json::array();
    for (std::size_t i = 0; i < refined.size(); ++i)
      runs.push_back({{"impact_velocity", entry.velocities[i]},
                      {"tool",
                       {{"restitution", refined[i].restitution},
                        {"contact_time", refined[i].contact_time},
                        {"force_max", refined[i].force_max}}}});
    result["time_steps_per_contact_time"] = steps_per_contact;
    result["refined"] = {{"time_steps_per_contact_time", refined_steps_per_contact},
                         {"runs", runs}};
    std::ofstream(output) << result.dump(2) << '\n';
    impact::consumers::print_simulator_run(entry, measured);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impact-drop-lammps-external: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
