// The warnings on the FEM's quality in words (report.hpp): what the assessment found beyond
// the thresholds (ReportRun::quality), said where the reader meets the run's other problems.

#include "impact_postprocess/report/report.hpp"

#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <cmath>

namespace impact::postprocess {

namespace {

// The oscillation and the release chatter of one run, in one warning.
std::string smoothness_words(const ReportRun& run) {
  const FemQualityWarnings& quality = run.quality;
  std::string message;
  if (quality.oscillation)
    message = "the contact force oscillates from step to step by " +
              unsigned_percent(*quality.oscillation) + " of its peak (" +
              run.record.smoothness_source + "; warning above " +
              unsigned_percent(force_oscillation_warning) +
              "): the peak force is uncertain by as much";
  if (quality.after_release)
    message += (message.empty() ? "" : "; ") + std::string("after the first zero that follows ") +
               "the peak the force returns to " + unsigned_percent(*quality.after_release) +
               " of the peak (release chatter): the contact time is uncertain by its length";
  return message;
}

std::string energy_balance_words(const ReportRun& run, double balance) {
  const double lost = 1 - run.fem.restitution * run.fem.restitution;
  return "V = " + short_number(run.velocity) +
         " m/s: the energy balance misses its target: at the end of the run it is off by " +
         unsigned_percent(std::abs(balance)) + " of the impact energy (" +
         fem_format::energy_error_final_key + " of summary.json; target " +
         unsigned_percent(energy_balance_target) + ")" +
         (lost > 0 ? ", " + unsigned_percent(std::abs(balance) / lost) +
                         " of the energy the impact loses (1 - e^2)"
                   : std::string()) +
         ": the time step or the contact's discretisation does work of that size, which the "
         "energy loss carries.";
}

} // namespace

void place_quality_warnings(Report& report) {
  // From the last run back, so that the positions of the earlier runs stay valid.
  for (auto run = report.runs.rbegin(); run != report.runs.rend(); ++run) {
    std::vector<Problem> warnings;
    if (const std::string message = smoothness_words(*run); !message.empty())
      warnings.push_back({run->source, ProblemKind::quality,
                          "V = " + short_number(run->velocity) + " m/s: " + message +
                              ". The verdict does not claim a smaller difference."});
    if (run->quality.energy_balance)
      warnings.push_back({run->source, ProblemKind::quality,
                          energy_balance_words(*run, *run->quality.energy_balance)});
    const std::size_t position = std::min(run->quality.problem_position, report.problems.size());
    report.problems.insert(report.problems.begin() + std::ptrdiff_t(position), warnings.begin(),
                           warnings.end());
  }
}

} // namespace impact::postprocess
