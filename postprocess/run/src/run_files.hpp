#pragma once
// What the readers and the writer of FEM runs share (fem_run_io.cpp: one run;
// campaign_index.cpp: a campaign and its index; fem_run_writer.cpp: the writer).

#include "impact_postprocess/run/fem_run.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

/// "'path'", as the messages quote a file.
std::string quoted(const std::filesystem::path& path);
/// Throws RunInputError "run 'file': problem".
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem);
/// summary.json belongs to history.h5 in the same directory; another file NAME.h5 may have
/// NAME.summary.json beside it.
std::filesystem::path summary_path_of(const std::filesystem::path& file);
/// history.incomplete.h5 beside `file`.
std::filesystem::path incomplete_sibling(const std::filesystem::path& file);
/// The run at `path`, or none: why it cannot be read is then a problem of the campaign (a run
/// without rebound marked so), with the run's place in the sweep (`point`) when known.
std::optional<FemRun> read_or_record(const std::filesystem::path& path,
                                     std::vector<InputProblem>& problems,
                                     std::map<std::string, SweepValue> point = {});
void sort_by_velocity(std::vector<FemRun>& runs);

} // namespace impact::postprocess::detail
