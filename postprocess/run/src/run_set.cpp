#include "impact_postprocess/run/run_set.hpp"

#include "impact_postprocess/run/fem_run_format.hpp"

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;

// Without an index, the campaign reader finds runs by their HDF5 files, so a run directory
// whose HDF5 file is missing would go unnoticed: it is found here by its summary.json.
std::vector<InputProblem> runs_without_history(const fs::path& campaign) {
  namespace format = fem_format;
  std::vector<InputProblem> problems;
  if (!fs::is_directory(campaign) || fs::exists(campaign / format::campaign_index_json))
    return problems;
  for (const auto& item : fs::directory_iterator(campaign)) {
    const fs::path& path = item.path();
    if (item.is_directory() && fs::exists(path / format::summary_file) &&
        !fs::exists(path / format::history_file) &&
        !fs::exists(path / format::incomplete_history_file))
      problems.push_back(
          {{path.string(), ProblemKind::input,
            "run '" + path.string() + "': the directory holds " + format::summary_file +
                " but no " + format::history_file + ": the HDF5 file of the run is missing"}});
  }
  return problems;
}

} // namespace

Campaign read_run_set(const std::vector<fs::path>& runs, const std::optional<fs::path>& campaign) {
  if (!campaign) return read_runs(runs);
  Campaign input;
  try {
    input = read_campaign(*campaign);
  } catch (const RunInputError& error) {
    input.problems.push_back({{campaign->string(), ProblemKind::input, error.what()}});
  }
  const auto lost = runs_without_history(*campaign);
  input.problems.insert(input.problems.end(), lost.begin(), lost.end());
  return input;
}

std::string run_set_source(const std::vector<fs::path>& runs,
                           const std::optional<fs::path>& campaign) {
  if (campaign) return campaign->string();
  std::string source;
  for (const auto& run : runs) source += (source.empty() ? "" : ", ") + run.string();
  return source;
}

} // namespace impact::postprocess
