// The number formats of the page (report_parts.hpp).

#include "report/report_parts.hpp"

#include <cmath>
#include <cstdio>

namespace impact::postprocess::detail {

std::string velocity_cell(const ReportRun& run) {
  return cell(run.velocity) + (run.yields ? " (yields)" : "");
}

std::string range_text(const ToleranceVerdict& verdict, const Report& report) {
  std::string text =
      !verdict.range ? std::string("none")
      : (*verdict.range)[0] == (*verdict.range)[1]
          ? short_number((*verdict.range)[0]) + " m/s only"
          : short_number((*verdict.range)[0]) + " to " + short_number((*verdict.range)[1]) + " m/s";
  std::vector<double> undecided;
  for (std::size_t i = 0; i < verdict.decisions.size(); ++i)
    if (verdict.decisions[i] == Decision::undecided) undecided.push_back(report.runs[i].velocity);
  if (!undecided.empty()) text += "; not decided at " + velocity_list(undecided);
  return text;
}

// ---- Number formats -----------------------------------------------------------------------

std::string cell(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string percent_cell(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%+.3g %%", fraction * 100);
  return text;
}

std::string unsigned_percent(double fraction) {
  if (!std::isfinite(fraction)) return "not known";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", fraction * 100);
  return text;
}

std::string short_number(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string velocity_label(double velocity) {
  return "V = " + short_number(velocity) + " m/s";
}

std::string velocity_list(const std::vector<double>& velocities) {
  std::string text;
  for (std::size_t i = 0; i < velocities.size(); ++i)
    text += (i == 0                       ? ""
             : i + 1 == velocities.size() ? " and "
                                          : ", ") +
            short_number(velocities[i]);
  return text + " m/s";
}

} // namespace impact::postprocess::detail
