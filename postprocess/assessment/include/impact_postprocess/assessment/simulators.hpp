#pragma once
/// @file
/// The exports run in their simulators (simulators.cpp): what each tool measured, judged
/// against the FEM like the verdict.

#include "impact_postprocess/assessment/verdict.hpp"
#include "impact_postprocess/impact_quantities.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// What a simulator measured at one velocity with a file of impact-export (a result file of
/// tests/consumers/run_in_simulators.sh, format "impact-simulator-run", postprocess/README.md).
/// The tools measure e, t_c and F_max: t(F_max) and x_max are NaN.
struct SimulatorRunAt {
  double velocity;             ///< m/s
  ImpactFigures tool;          ///< measured by the tool from its own state
  ImpactFigures reduced_model; ///< the exported model's prediction (export.json)
  ImpactFigures fem;           ///< the FEM as the file holds it (the calibration's numbers)
};

/// One result file: one tool (and deck) run at the campaign's velocities.
struct SimulatorResult {
  std::string source; ///< the result file
  std::string tool;   ///< "simbody", "mujoco", "lammps" (or another tool's name)
  std::string tool_version;
  std::string model;           ///< the exported model: "hunt-crossley", "linear-spring-damper", ...
  std::string export_manifest; ///< the export.json the file was run from
  std::string file;            ///< the exported file, relative to the export directory
  std::optional<double> reference_velocity; ///< m/s, where the export was matched (MuJoCo)
  std::vector<SimulatorRunAt> runs;         ///< ordered by velocity
  /// Against the FEM of the report's runs, judged like the verdict (with the FEM's
  /// uncertainty) in 1 - e^2, t_c and F_max: one per tolerance, decisions parallel to
  /// Assessment::runs.
  std::vector<ToleranceVerdict> against_fem;
};

// Shared by the assessment and the report (namespace detail: not for a reader of the API).
namespace detail {

/// What the tools measure (x_max and t(F_max) are not among them): the quantities judged, and
/// those of the tables.
inline const std::vector<Quantity> simulator_judged_quantities = {Quantity::energy_loss,
                                                                  Quantity::contact_time,
                                                                  Quantity::force_max};
inline const std::vector<Quantity> simulator_table_quantities = {Quantity::restitution,
                                                                 Quantity::energy_loss,
                                                                 Quantity::contact_time,
                                                                 Quantity::force_max};

} // namespace detail

} // namespace impact::postprocess
