// export_run_set and sphere_radius (export_run_set.hpp).

#include "impact_postprocess/export/export_run_set.hpp"
#include "impact_postprocess/same_value.hpp"

#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/export/liggghts.hpp"
#include "impact_postprocess/export/restitution_table.hpp"
#include "impact_postprocess/export/simulator_export.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/run_set.hpp"

#include <cmath>
#include <fstream>
#include <string>

namespace impact::postprocess {

namespace {

nlohmann::json read_calibration_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ExportInputError(file.string() + ": cannot open the calibration");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw ExportInputError(file.string() + ": not valid JSON (" + error.what() + ")");
  }
}

// The restitution table of the law asked for, else of the first-ranked damped elastic-plastic
// law; none when the calibration has no such law and none was asked for.
std::optional<RestitutionTable> table_of(const nlohmann::json& json, const ExportRequest& request,
                                         const std::vector<FemRun>& runs) {
  Calibration calibration;
  try {
    calibration = calibration_from_json(json);
  } catch (const CalibrationFormatError& error) {
    throw ExportInputError(request.calibration.string() + ": " + error.what());
  }
  if (!request.table_law && restitution_table_laws(calibration).empty()) return std::nullopt;
  try {
    return restitution_table(calibration, runs, request.table_law, request.table_points);
  } catch (const RestitutionTableError& error) {
    throw ExportInputError(request.calibration.string() + ": " + error.what());
  }
}

} // namespace

double sphere_radius(const Campaign& input) {
  const std::string key = fem_format::sphere_radius.path;
  std::optional<double> radius;
  for (const auto& run : input.runs) {
    const auto found = run.text_attributes.find(key);
    if (found == run.text_attributes.end())
      throw ExportInputError(run.source +
                             ": the run does not record the sphere radius "
                             "(text attribute '" +
                             key + "')");
    double value = NAN;
    try {
      value = std::stod(found->second);
    } catch (const std::exception&) {
    }
    if (!(std::isfinite(value) && value > 0))
      throw ExportInputError(run.source + ": '" + key + "' = '" + found->second +
                             "' is not a positive length in m");
    if (radius && !same_value(value, *radius))
      throw ExportInputError(run.source + ": sphere radius " + found->second +
                             " m differs from the other runs' " + std::to_string(*radius) +
                             " m: one sphere per export");
    radius = value;
  }
  return *radius;
}

ExportOutcome export_run_set(const ExportRequest& request) {
  ExportOutcome outcome;
  const Campaign input = read_run_set(request.runs, request.campaign);
  outcome.problems.assign(input.problems.begin(), input.problems.end());
  if (!input.problems.empty() || input.runs.empty()) {
    outcome.problems.push_back({request.campaign ? request.campaign->string() : "",
                                ProblemKind::input,
                                "every run of the calibration must be readable; nothing was "
                                "written"});
    return outcome;
  }
  try {
    const nlohmann::json calibration = read_calibration_file(request.calibration);
    ExportCampaign campaign =
        read_export_campaign(calibration, request.calibration.string(), sphere_radius(input));
    if (!campaign.plastic) try {
        campaign.plastic = scenario_plastic_contact(input.runs);
      } catch (const PlasticContactError& error) {
        throw ExportInputError(error.what());
      }
    if (campaign.runs.size() != input.runs.size())
      throw ExportInputError(request.calibration.string() + ": the calibration has " +
                             std::to_string(campaign.runs.size()) + " runs, the input " +
                             std::to_string(input.runs.size()) + ": not the same campaign");
    campaign.restitution_table = table_of(calibration, request, input.runs);
    outcome.manifest = write_exports(campaign, request.reference_velocity, request.output);
  } catch (const ExportInputError& error) {
    outcome.problems.push_back(
        {"", ProblemKind::input, std::string(error.what()) + "; nothing was written"});
  }
  return outcome;
}

} // namespace impact::postprocess
