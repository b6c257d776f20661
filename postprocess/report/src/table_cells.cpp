// The cells of the tables that several sections share (sections.hpp).

#include "sections.hpp"

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

} // namespace impact::postprocess::detail
