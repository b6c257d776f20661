#pragma once
/// @file
/// The names in the result files of impact-fem that the run readers use: those of the FEM's
/// own contract header (impact_fem/result_files.h, written by impact-fem with the same
/// names), so that a name changed on one side changes the other.

#include <impact_fem/result_files.h>

namespace impact::postprocess {
namespace fem_format = impact_fem::result_files;
} // namespace impact::postprocess
