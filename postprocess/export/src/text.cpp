// Number formatting and the error table of the exported files' header comments.

#include "text.hpp"

#include "impact_postprocess/number_format.hpp"

#include <cstdio>
#include <sstream>

namespace impact::postprocess::export_text {

namespace {

// (model - FEM) / FEM in per cent, signed, two decimals.
std::string error(double model, double fem) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%+.2f %%", 100 * (model / fem - 1));
  return buffer;
}

} // namespace

std::string rounded(double value, int digits) {
  return significant(value, digits);
}

std::string error_table(const std::string& comment, const ExportCampaign& campaign,
                        const std::vector<ImpactFigures>& model) {
  std::ostringstream out;
  out << comment
      << "   V [m/s]   e (vs FEM)            t_c [s] (vs FEM)          F_max [N] (vs FEM)\n";
  for (std::size_t i = 0; i < campaign.runs.size(); ++i) {
    const auto& fem = campaign.runs[i].fem;
    char line[256];
    std::snprintf(line, sizeof line, "   %-8.4g  %-9.6f (%s)  %-11.5g (%s)  %-10.5g (%s)\n",
                  campaign.runs[i].velocity, model[i].restitution,
                  error(model[i].restitution, fem.restitution).c_str(), model[i].contact_time,
                  error(model[i].contact_time, fem.contact_time).c_str(), model[i].force_max,
                  error(model[i].force_max, fem.force_max).c_str());
    out << comment << line;
  }
  return out.str();
}

} // namespace impact::postprocess::export_text
