#pragma once
/// @file
/// One FEM impact run as the calibration sees it, and the readers of runs and campaigns
/// (the file names are in fem_run_format.hpp). A writer of the same format is included, so
/// that tests and tools can produce runs that the readers cannot tell from impact-fem's.

#include "impact_postprocess/impact_quantities.hpp"
#include "impact_postprocess/problem.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::postprocess {

/// A run that cannot be used: missing or unreadable file, incomplete run, missing dataset,
/// no contact, ... `what()` names the file and the problem in a sentence.
class RunInputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A complete run in which the sphere did not rebound within the simulated time (a thin plate
/// that holds the ball): a finding of the FEM, not a broken input, but there is no restitution
/// to calibrate or judge.
class NoRebound : public RunInputError {
public:
  using RunInputError::RunInputError;
};

/// The value of a swept parameter at one run (index.json of a sweep campaign, format in
/// postprocess/README.md, "Campaign index"): a number when its text parses completely as one, else text.
struct SweepValue {
  std::string text;             ///< as written ("0.005", "free")
  std::optional<double> number; ///< the number, when it is one
  /// Same value: numbers equal to 1e-9 (relative), else the same text.
  bool matches(const SweepValue& other) const;
};

/// One axis of a sweep campaign: a parameter ("Scenario/Plate thickness") and its values, in
/// the order of the index.
struct SweepAxis {
  std::string parameter;
  std::vector<SweepValue> values;
};

/// The parameter of the impact-velocity axis (always the last axis of a sweep).
inline constexpr const char* velocity_axis = fem_format::impact_velocity.path;

/// The measured quantities of one run. SI units; times from the start of the run. Its scalars
/// are what the run's files record, on the run's own clock (t(F_max) from the start of the
/// run, not from first contact), beside the histories they were derived from; the figures by
/// which the models are compared with it (ImpactFigures, from first contact) are
/// measured_quantities(run).
struct FemRun {
  std::string source;                ///< the HDF5 file read (or written)
  double impact_velocity;            ///< V [m/s]: the sphere's speed at first contact (x'(0) of the
                                     ///< reduced model; "contact_velocity" of impact-fem)
  double mass;                       ///< sphere mass m [kg]
  double restitution;                ///< e = rebound speed / V [-]
  double first_contact_time;         ///< t0 [s]; the reduced model's t = 0
  double contact_time;               ///< t_c [s]
  double force_max;                  ///< peak contact force [N]
  double time_force_max;             ///< its time [s] (from the start of the run)
  double approach_max;               ///< peak approach [m]
  std::vector<double> time;          ///< s, strictly increasing
  std::vector<double> contact_force; ///< N
  std::vector<double> approach;      ///< m
  std::vector<double> sphere_velocity; ///< m/s, downward positive (optional: may be empty)
  /// Root attributes of the file: the scenario parameters (text) and results (numbers).
  std::map<std::string, std::string> text_attributes;
  std::map<std::string, double> numeric_attributes;
  /// The run's point in its campaign's sweep, by axis parameter (empty outside a sweep
  /// campaign): from the index's "point", else from the run's text attributes.
  std::map<std::string, SweepValue> sweep_point;
};

/// Reads one run: `path` is the run's HDF5 file or its directory (holding history.h5).
/// The derived results come from summary.json beside the file, else from the file's
/// "result: ..." attributes; those missing from both are computed from the histories
/// (restitution excepted). Throws RunInputError naming the file and the problem: missing
/// file or directory, a run marked incomplete, not HDF5, a missing or malformed dataset
/// (time, contact_force, approach), no contact (force never positive), no separation
/// (no restitution), missing impact velocity or mass.
FemRun read_fem_run(const std::filesystem::path& path);

/// A problem with one input, kept so that the calibration JSON can say what is missing.
/// Its kind is input, or no_rebound for a complete run in which the sphere did not rebound
/// (NoRebound).
struct InputProblem : Problem {
  /// The run's sweep point as its campaign index lists it (empty when it lists none).
  std::map<std::string, SweepValue> point = {};
};

/// The runs of a campaign that could be read, and the problems with the others.
struct Campaign {
  std::vector<FemRun> runs; ///< ordered by impact velocity
  std::vector<InputProblem> problems;
  /// The axes of a sweep campaign (index.json "axes"); empty for an older index, a CSV
  /// index, a directory without index or runs given one by one.
  std::vector<SweepAxis> axes;
};

/// The figures of the run by which the reduced models are compared with it (t(F_max) since
/// first contact).
ImpactFigures measured_quantities(const FemRun& run);

/// Reads a list of runs (files or run directories), collecting the problems instead of
/// throwing, so that one bad run does not hide the others.
Campaign read_runs(const std::vector<std::filesystem::path>& paths);

/// Reads the campaign in `directory`: the runs listed in its index.json (see
/// postprocess/README.md), else every subdirectory holding history.h5 or
/// history.incomplete.h5 and every *.h5 file directly in it. A run listed in the index but
/// absent is a problem. Throws RunInputError if the directory does not exist or holds no run
/// at all, and for an index whose sweep is inconsistent (an axis without parameter or values,
/// a run's point without one of the axes or with a value that is not one of the axis's, a
/// run whose parameter differs from its point, a run without point nor the parameter),
/// naming the index or run file and the problem.
Campaign read_campaign(const std::filesystem::path& directory);

/// Writes `run` in impact-fem's format into `directory` (created if needed): history.h5 with
/// status "complete" and summary.json, or, with complete = false, history.incomplete.h5
/// with status "incomplete" and no summary. Empty histories are not written (so a file
/// without a dataset can be made on purpose). Returns the HDF5 file written.
std::filesystem::path write_fem_run(const FemRun& run, const std::filesystem::path& directory,
                                    bool complete = true);

} // namespace impact::postprocess
