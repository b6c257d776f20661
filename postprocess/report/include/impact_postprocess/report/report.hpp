#pragma once
/// @file
/// The model-validity report of impact-report: the assessment (assessment/assessment.hpp) laid
/// out on a page, and the writers of the page (HTML and a Markdown twin) and of the data file
/// from which postprocess/report_figures.py draws the figures. The assessment computes every
/// number; the report words them; the Python script only draws.

#include "impact_postprocess/assessment/assessment.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The report's numbers are the assessment's: the page lays them out.
using Report = Assessment;
using ReportOptions = AssessmentOptions;

/// The runs' FEM-quality warnings (ReportRun::quality) in words, as problems of kind quality
/// placed among the assessment's problems where each run's own problems are
/// (quality_warnings.cpp).
void place_quality_warnings(Report& report);

/// Builds every number of the report: the assessment (assess), with its quality warnings
/// worded among its problems.
inline Report build_report(const Campaign& campaign, const std::optional<Calibration>& calibration,
                           std::vector<Problem> problems, const std::string& campaign_source,
                           const std::string& calibration_source,
                           const ReportOptions& options = {}) {
  Report report = assess(campaign, calibration, std::move(problems), campaign_source,
                         calibration_source, options);
  place_quality_warnings(report);
  return report;
}

/// The figures of the page. The section that shows a figure asks for it by its identity
/// (and, for a validity map, the map model's key); a figure whose data do not exist (the
/// damping figure without a calibration, the maps without a map) is not declared.
enum class FigureId {
  loops,
  histories,
  residuals,
  quantities,
  energy_loss,
  damping,
  errors,
  validity_map,
  plastic_restitution,
  permanent_approach,
  plastic_loops
};

/// A figure, declared once: identity, file name (in the figures directory), caption and the
/// data to draw it (title, columns, panels: the input of report_figures.py).
struct ReportFigure {
  FigureId id;
  std::string model_key; ///< the map model of a validity map ("" for the others)
  std::string file;
  std::string caption;
  nlohmann::json data;
};

/// The figures of the page, in the order of the data file.
std::vector<ReportFigure> report_figures(const Report& report);
/// The data file of report_figures.py: {"figures": [{file, title, columns, panels: [...]}]}.
nlohmann::json figure_specification(const Report& report);

/// Writes the Markdown page (figures referenced as `figures_directory/<file>`, relative to
/// the page) and the HTML page (figures embedded as base64 PNG, so the file stands alone).
/// Figures whose file does not exist are replaced by a sentence saying so.
void write_report_markdown(const Report& report, const std::filesystem::path& file,
                           const std::filesystem::path& figures_directory);
void write_report_html(const Report& report, const std::filesystem::path& file,
                       const std::filesystem::path& figures_directory);

} // namespace impact::postprocess
