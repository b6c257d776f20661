// impact-drop-lammps EXPORT_DIR OUTPUT_DIR: runs each exported LAMMPS deck (lammps/*.in) with
// LAMMPS itself (lmp -in DECK -var V v -var out FILE) at each campaign velocity, measures
// restitution, contact time and peak force from the sphere's z, vz, fz that the deck prints at
// every step, and writes OUTPUT_DIR/lammps-<model>.json (format "impact-simulator-run").
// The LAMMPS executable is IMPACT_LAMMPS (environment), else the one found at configure time.

#include "simulator_run.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using impact::consumers::DropFigures;
using impact::consumers::DropSample;

std::string lammps_executable() {
  const char* chosen = std::getenv("IMPACT_LAMMPS");
  return chosen ? chosen : IMPACT_LAMMPS;
}

std::string quoted(const std::string& text) {
  return "'" + text + "'";
}

std::string lammps_version(const fs::path& scratch) {
  const fs::path log = scratch / "version.txt";
  std::system((quoted(lammps_executable()) + " -h > " + quoted(log.string()) + " 2>&1").c_str());
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (line.find("Large-scale Atomic/Molecular Massively Parallel Simulator") !=
        std::string::npos) {
      const auto dash = line.find(" - ");
      return dash == std::string::npos ? line : line.substr(dash + 3);
    }
  throw std::runtime_error("'" + lammps_executable() +
                           " -h' does not name a LAMMPS version (is "
                           "the Debian package lammps installed? ./setup.sh)");
}

DropFigures drop(const fs::path& deck, double velocity, double radius, const fs::path& scratch) {
  const fs::path trace = scratch / "drop.txt", log = scratch / "lammps.log";
  fs::remove(trace);
  std::ostringstream command;
  command.precision(17);
  command << quoted(lammps_executable()) << " -in " << quoted(deck.string()) << " -var V "
          << velocity << " -var out " << quoted(trace.string()) << " -log none -echo none -screen "
          << quoted(log.string()) << " -nocite";
  if (std::system(command.str().c_str()) != 0)
    throw std::runtime_error("LAMMPS failed on " + deck.string() + " at V = " +
                             std::to_string(velocity) + " m/s (see " + log.string() + ")");
  std::ifstream in(trace);
  std::vector<DropSample> samples;
  std::string line;
  double rebound = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double time, z, vz, fz;
    if (!(fields >> time >> z >> vz >> fz))
      throw std::runtime_error("bad line in " + trace.string() + ": " + line);
    samples.push_back({time, radius - z, fz});
    rebound = vz;
  }
  return impact::consumers::measure_drop(samples, velocity, rebound);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: impact-drop-lammps EXPORT_DIR OUTPUT_DIR\n");
    return 2;
  }
  try {
    const fs::path output = argv[2];
    const fs::path scratch = output / "lammps-scratch";
    fs::create_directories(scratch);
    const std::string version = lammps_version(scratch);
    for (const auto& entry : impact::consumers::read_export(argv[1], "lammps")) {
      std::vector<DropFigures> measured;
      for (double velocity : entry.velocities)
        measured.push_back(drop(entry.directory / entry.file, velocity, entry.radius, scratch));
      impact::consumers::write_simulator_run(output / ("lammps-" + entry.model + ".json"), entry,
                                             version, measured);
      impact::consumers::print_simulator_run(entry, measured);
    }
    fs::remove_all(scratch);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impact-drop-lammps: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
