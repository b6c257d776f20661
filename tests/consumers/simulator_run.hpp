#pragma once
// What the drop programs of the simulators share: reading their entry of an export's
// manifest (export.json of impact-export), measuring restitution, contact time and peak force
// from a sampled drop, and writing the result file that the report reads (format
// "impact-simulator-run", postprocess/README.md). Only the standard library and nlohmann_json,
// so that the Simbody driver, built against an export at run time, can use it too.

#include <filesystem>
#include <string>
#include <vector>

namespace impact::consumers {

/// One sample of a drop from the tool's own state: time [s], approach x [m] (penetration,
/// positive in contact), contact force [N] on the sphere (positive pushing it away).
struct DropSample {
  double time;
  double approach;
  double force;
};

struct DropFigures {
  double restitution;  ///< rebound speed / impact speed
  double contact_time; ///< s, first touch to the end of the contact force
  double force_max;    ///< N, largest sampled force
};

/// The figures of one drop. The contact starts where x crosses 0 (linear interpolation: the
/// speed is constant before contact) and ends at the first sample without force after it:
/// where x crosses 0 again if the sphere has left (linear interpolation), else where the
/// force, extrapolated from the last two samples with force, vanishes (a contact that stops
/// pushing before x = 0, as MuJoCo's). `rebound_velocity` is the sphere's speed away from the
/// plane after the contact. Throws std::runtime_error if the samples hold no complete contact.
DropFigures measure_drop(const std::vector<DropSample>& samples, double impact_velocity,
                         double rebound_velocity);

/// An export of the manifest: the file to run, the sphere, the velocities and the figures
/// that the export's reduced model and the FEM give at each.
struct ExportEntry {
  std::filesystem::path directory; ///< the export directory
  std::string tool, model, file;   ///< file relative to the directory
  double mass, radius;
  double reference_velocity; ///< NaN when the export has none
  std::vector<double> velocities;
  std::vector<DropFigures> reduced_model, fem;
};

/// The entries of `tool` ("simbody", "mujoco", "lammps") in `directory`/export.json. Throws
/// std::runtime_error naming the file and the key for a missing or malformed manifest.
std::vector<ExportEntry> read_export(const std::filesystem::path& directory,
                                     const std::string& tool);

/// Writes the tool's measurements (one per entry.velocities) with their errors against the
/// reduced model and the FEM to `output` (JSON, written atomically).
void write_simulator_run(const std::filesystem::path& output, const ExportEntry& entry,
                         const std::string& tool_version, const std::vector<DropFigures>& measured);

/// Prints the measurements and errors as a table on stdout.
void print_simulator_run(const ExportEntry& entry, const std::vector<DropFigures>& measured);

} // namespace impact::consumers
