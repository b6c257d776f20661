// write_calibration and calibration_summary (calibrate_run_set.hpp).

#include "impact_postprocess/calibration/calibrate_run_set.hpp"
#include "impact_postprocess/number_format.hpp"

#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/run/run_set.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;

void write_json(const fs::path& path, const Calibration& calibration) {
  const fs::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary);
    // A problem may quote bytes of a damaged input (a JSON parser's "last read"): written
    // as U+FFFD where they are not UTF-8, never a failure to write.
    out << to_json(calibration).dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
        << '\n';
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  fs::rename(temporary, path);
}

} // namespace

CalibrationOutcome write_calibration(const CalibrationRequest& request) {
  const Campaign input = read_run_set(request.runs, request.campaign);
  const std::string source = request.campaign ? request.campaign->string() : "";
  CalibrationOutcome outcome;
  // The JSON lists every problem of reading a run as one of input (a run without rebound too).
  std::vector<Problem> problems;
  for (const auto& problem : input.problems)
    problems.push_back({problem.source, ProblemKind::input, problem.message});
  if (input.runs.empty()) {
    problems.push_back({source, ProblemKind::input, "no usable run: nothing was calibrated"});
    outcome.calibration.problems = std::move(problems);
    outcome.exit_code = exit_code(outcome.calibration.problems);
    return outcome;
  }
  Calibration calibration = calibrate(input.runs, request.options);
  if (!calibration.campaign.fitted && (request.campaign || request.runs.size() > 1))
    problems.push_back(campaign_not_fitted(source, calibration.campaign));
  problems.insert(problems.end(), calibration.problems.begin(), calibration.problems.end());
  calibration.problems = std::move(problems);
  write_json(request.output, calibration);
  outcome.written = true;
  outcome.exit_code = exit_code(calibration.problems);
  outcome.calibration = std::move(calibration);
  return outcome;
}

Problem campaign_not_fitted(const std::string& source, const CampaignCalibration& campaign) {
  return {source, ProblemKind::input, "campaign not fitted: " + campaign.reason};
}

bool is_campaign_not_fitted(const Problem& problem, const CampaignCalibration& campaign) {
  const Problem stated = campaign_not_fitted("", campaign);
  return problem.kind == stated.kind && problem.message == stated.message;
}

std::string calibration_summary(const Calibration& calibration) {
  std::ostringstream out;
  const auto six = [](double value) { return significant(value, 6); };
  if (const auto& hc = calibration.campaign.hunt_crossley)
    out << "Hunt-Crossley over " << calibration.runs.size()
        << " runs: c = " << six(hc->fit.stiffness.value)
        << " N/m^n, n = " << six(hc->fit.exponent.value) << ", b = " << six(hc->fit.parameter.value)
        << " s/m (RMS residual " << six(hc->fit.quality.rms_residual * 100)
        << " % of the peak force)\n";
  if (const auto& fixed = calibration.campaign.hunt_crossley_hertz_exponent)
    out << "Hunt-Crossley with n = " << six(hertz_exponent)
        << " fixed: c = " << six(fixed->fit.stiffness.value) << " N/m^" << six(hertz_exponent)
        << ", b = " << six(fixed->fit.parameter.value) << " s/m (RMS residual "
        << six(fixed->fit.quality.rms_residual * 100) << " % of the peak force)\n";
  if (const auto& energy = calibration.campaign.hunt_crossley_energy)
    out << "Hunt-Crossley fitted to force histories and energy loss: c = "
        << six(energy->fit.stiffness.value) << " N/m^n, n = " << six(energy->fit.exponent.value)
        << ", b = " << six(energy->fit.parameter.value) << " s/m\n";
  if (!calibration.campaign.ranking.empty()) {
    const auto& best = calibration.campaign.ranking.front();
    out << "ranked first by " << (best.out_of_sample ? "out-of-sample" : "in-sample")
        << " error: " << best.key << " (RMS error " << significant(best.score * 100, 4)
        << " % in 1 - e^2, t_c, F_max, x_max)\n";
  }
  return out.str();
}

} // namespace impact::postprocess
