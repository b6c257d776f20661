// The page of the model-validity report as one list of blocks (headings, paragraphs, tables,
// figures), built section by section from a Report; render.cpp writes it as
// Markdown and as self-contained HTML, so that the two pages say the same thing.

#include "sections.hpp"

#include <cmath>
#include <stdexcept>

namespace impact::postprocess::detail {

namespace fs = std::filesystem;

const std::array<double, quantity_count> page_scale = {1, 1, 1, 1e6, 1e-3, 1e6, 1e6};
const std::array<const char*, quantity_count> page_name = {"energy loss 1 - e^2 [1]",
                                                           "1 - e [1]",
                                                           "restitution e [1]",
                                                           "contact time t_c [µs]",
                                                           "peak force F_max [kN]",
                                                           "time of peak force t(F_max) [µs]",
                                                           "peak approach x_max [µm]"};

std::string decision_word(Decision decision) {
  switch (decision) {
    case Decision::within:
      return "yes";
    case Decision::outside:
      return "no";
    case Decision::undecided:
      return "not decided";
    case Decision::unknown:
      return "unknown";
  }
  return "?";
}

std::string error_cell(const std::optional<ImpactFigures>& model, const ImpactFigures& fem,
                       Quantity quantity) {
  return model ? percent_cell(relative_error(*model, fem, quantity)) : "n/a";
}

std::string not_converged(const ReportModel& model) {
  return model.converged ? "" : " (not converged)";
}

Document build_document(const Report& report, const fs::path& figures_directory) {
  Document doc;
  doc.heading("Impact model-validity report", 1);
  // Without runs the problems are the page; else one line under the glance says what the
  // section Status (folded after it) lists.
  if (report.runs.empty()) {
    status_section(doc, report);
    doc.paragraph(
        "No FEM run could be read: there is nothing to compare. Fix the problems "
        "above and run impact-report again.");
    return doc;
  }
  const auto figures = report_figures(report);
  std::vector<bool> placed(figures.size(), false);
  const FigurePlacer place = [&](FigureId id, const std::string& model_key) {
    for (std::size_t k = 0; k < figures.size(); ++k)
      if (figures[k].id == id && figures[k].model_key == model_key) {
        doc.figure({(figures_directory / figures[k].file).string(), figures[k].caption});
        placed[k] = true;
      }
  };
  const auto figure = [&](FigureId id) { place(id, ""); };
  glance_section(doc, report, place);
  doc.paragraph(
      "Campaign: " + report.campaign_source + ". Calibration: " +
      (report.calibration_source.empty() ? std::string("none") : report.calibration_source) +
      ". Every number below is computed by impact-report (C++, impact::reduced and "
      "the calibration JSON); the figures are drawn from them by report_figures.py.");
  doc.fold_from_here();
  status_section(doc, report);
  map_section(doc, report, place);
  verdict_section(doc, report);
  ranking_section(doc, report);
  parameters_section(doc, report);
  trend_section(doc, report, figure);
  plastic_section(doc, report, figure);
  users_section(doc, report);
  simulators_section(doc, report);
  quality_section(doc, report);
  runs_section(doc, report);
  models_section(doc, report);
  const auto figure_section = [&](const std::string& heading, const std::string& text,
                                  FigureId id) {
    doc.heading(heading);
    if (!text.empty()) doc.paragraph(text);
    figure(id);
  };
  figure_section("Force–approach loops", "", FigureId::loops);
  figure_section("Approach and force against time", "", FigureId::histories);
  figure_section("Force residuals against time",
                 "(F_model - F_FEM) / F_max against time since first contact: a residual that "
                 "follows the FEM's step-to-step oscillation is the FEM's noise, a smooth one the "
                 "model's error.",
                 FigureId::residuals);
  quantities_section(doc, report, figure);
  figure_section("Per-run damping b against V",
                 "b is constant only where Hunt–Crossley is the right law: a trend of the per-run "
                 "b with V says that the dissipation of the FEM does not have Hunt–Crossley's "
                 "velocity dependence.",
                 FigureId::damping);
  errors_section(doc, report);
  energy_section(doc, report);
  // Every declared figure is on the page: one declared and shown nowhere is a defect here.
  for (std::size_t k = 0; k < figures.size(); ++k)
    if (!placed[k])
      throw std::logic_error("the figure " + figures[k].file + " is declared but not placed");
  return doc;
}

} // namespace impact::postprocess::detail
