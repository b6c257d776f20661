#pragma once
// The texts of the exported files (impact-export): each file starts with a comment saying
// which model it carries, over which velocities, and that model's errors against the FEM.

#include "impact_postprocess/export/simulator_export.hpp"

#include <impact_fem/as_written.h>

#include <string>
#include <vector>

namespace impact::postprocess::export_text {

/// The exported numbers reproduce the doubles: the fewest significant digits that read back
/// as the same double.
using impact_fem::as_written;
/// `value` with `digits` significant digits, for comments.
std::string rounded(double value, int digits = 6);

/// The comment block "V, e, t_c, F_max of the model and their errors against the FEM", one
/// line per campaign run, each line starting with `comment` ("//", "#", ...).
std::string error_table(const std::string& comment, const ExportCampaign& campaign,
                        const std::vector<ImpactFigures>& model);

std::string simbody_file(const ExportCampaign& campaign, const SimbodyContact& contact,
                         const std::vector<ImpactFigures>& model);
std::string mujoco_file(const ExportCampaign& campaign, const MujocoContact& contact,
                        const std::vector<ImpactFigures>& model);
std::string lammps_file(const ExportCampaign& campaign, const HertzLawFit& law,
                        const LammpsContact& contact, const std::vector<ImpactFigures>& model,
                        bool recommended);

} // namespace impact::postprocess::export_text
