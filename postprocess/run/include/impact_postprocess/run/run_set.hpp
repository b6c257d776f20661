#pragma once
/// @file
/// The runs a tool is given: the run files named on its command line, or the runs of a
/// campaign directory, read into one Campaign (runs, sweep axes, problems).

#include "impact_postprocess/run/fem_run.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace impact::postprocess {

/// The runs of `campaign` (read_campaign) when given, else the run files `runs` (read_runs).
/// A campaign that cannot be read is an input problem naming the directory, like a run that
/// cannot be read. Run directories of a campaign without index that hold summary.json but no
/// history file are input problems too (the reader finds runs by their HDF5 files, so such a
/// run would otherwise go unnoticed). Never throws for bad input.
Campaign read_run_set(const std::vector<std::filesystem::path>& runs,
                      const std::optional<std::filesystem::path>& campaign);

/// How the run set is named on the page and in messages: the campaign directory, or the run
/// files separated by ", ".
std::string run_set_source(const std::vector<std::filesystem::path>& runs,
                           const std::optional<std::filesystem::path>& campaign);

} // namespace impact::postprocess
