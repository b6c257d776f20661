// impact-drop-liggghts EXPORT_DIR OUTPUT_DIR: runs the exported LIGGGHTS deck
// (liggghts/thornton_ning.in) with LIGGGHTS itself (liggghts -in DECK -var V v -var N n
// -var out FILE) at each campaign velocity, measures restitution, contact time and peak force
// from the sphere's approach, vz and fz that the deck prints at every step, and writes
// OUTPUT_DIR/liggghts-thornton.json (format "impact-simulator-run") for the deck's time step
// (N = 5000 steps per Hertz contact time). LIGGGHTS integrates the contact force in explicit
// increments of the overlap, first order in the step, so the file also holds the same drops
// at half the step ("refined": N = 10000), from which the test checks the convergence.
// The LIGGGHTS executable is IMPACT_LIGGGHTS (environment), else the one found at configure
// time.

#include "simulator_run.hpp"

#include <nlohmann/json.hpp>

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
using json = nlohmann::json;

constexpr int deck_steps = 5000, refined_steps = 10000;

std::string liggghts_executable() {
  const char* chosen = std::getenv("IMPACT_LIGGGHTS");
  return chosen ? chosen : IMPACT_LIGGGHTS;
}

std::string quoted(const std::string& text) {
  return "'" + text + "'";
}

// "3.8.0" from the banner "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, compiled ...)" of a run.
std::string liggghts_version(const fs::path& log) {
  std::ifstream in(log);
  std::string line;
  const std::string marker = "LIGGGHTS-PUBLIC ";
  while (std::getline(in, line)) {
    const auto at = line.find(marker);
    if (at != std::string::npos) {
      const auto begin = at + marker.size();
      return line.substr(begin, line.find_first_of(", )", begin) - begin);
    }
  }
  throw std::runtime_error(log.string() +
                           " does not name a LIGGGHTS version (is the Debian "
                           "package liggghts installed? ./setup.sh)");
}

DropFigures drop(const fs::path& deck, double velocity, int steps, const fs::path& scratch) {
  const fs::path trace = scratch / "drop.txt", log = scratch / "liggghts.log";
  fs::remove(trace);
  std::ostringstream command;
  command.precision(17);
  command << quoted(liggghts_executable()) << " -in " << quoted(deck.string()) << " -var V "
          << velocity << " -var N " << steps << " -var out " << quoted(trace.string())
          << " -log none -echo none -screen " << quoted(log.string());
  if (std::system(command.str().c_str()) != 0)
    throw std::runtime_error("LIGGGHTS failed on " + deck.string() + " at V = " +
                             std::to_string(velocity) + " m/s (see " + log.string() + ")");
  std::ifstream in(trace);
  if (!in)
    throw std::runtime_error("LIGGGHTS wrote no " + trace.string() + " (see " + log.string() + ")");
  std::vector<DropSample> samples;
  std::string line;
  double rebound = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double time, approach, vz, fz;
    if (!(fields >> time >> approach >> vz >> fz))
      throw std::runtime_error("bad line in " + trace.string() + ": " + line);
    samples.push_back({time, approach, fz});
    rebound = vz;
  }
  return impact::consumers::measure_drop(samples, velocity, rebound);
}

json figures_json(const DropFigures& figures) {
  return {{"restitution", figures.restitution},
          {"contact_time", figures.contact_time},
          {"force_max", figures.force_max}};
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: impact-drop-liggghts EXPORT_DIR OUTPUT_DIR\n");
    return 2;
  }
  try {
    const fs::path output = argv[2];
    const fs::path scratch = output / "liggghts-scratch";
    fs::create_directories(scratch);
    for (const auto& entry : impact::consumers::read_export(argv[1], "liggghts")) {
      const fs::path deck = entry.directory / entry.file;
      std::vector<DropFigures> measured;
      json refined = json::array();
      for (double velocity : entry.velocities) {
        measured.push_back(drop(deck, velocity, deck_steps, scratch));
        refined.push_back({{"impact_velocity", velocity},
                           {"tool", figures_json(drop(deck, velocity, refined_steps, scratch))}});
      }
      const std::string version = liggghts_version(scratch / "liggghts.log");
      const fs::path file = output / ("liggghts-" + entry.model + ".json");
      impact::consumers::write_simulator_run(file, entry, version, measured);
      // The time-step study beside the runs (the report reads only "runs").
      json result;
      {
        std::ifstream in(file);
        result = json::parse(in);
      }
      result["time_steps_per_hertz_time"] = deck_steps;
      result["refined"] = {{"time_steps_per_hertz_time", refined_steps}, {"runs", refined}};
      const fs::path temporary = file.string() + ".tmp";
      {
        std::ofstream out(temporary);
        out << result.dump(2) << '\n';
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
      }
      fs::rename(temporary, file);
      impact::consumers::print_simulator_run(entry, measured);
    }
    fs::remove_all(scratch);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impact-drop-liggghts: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
