#pragma once
// The sections of the page, in the order build_document (document.cpp) places them, and
// what they share: the cells of the tables and the words of a decision.

#include "document.hpp"

#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/report/report.hpp"

#include <array>
#include <functional>
#include <string>

namespace impact::postprocess::detail {

// The sections of the page, in the order build_document (document.cpp) places them; a section
// that shows a figure places it through `figure`. verdict_sections.cpp:
void status_section(Document& doc, const Report& report);
void verdict_section(Document& doc, const Report& report);
void ranking_section(Document& doc, const Report& report);
void parameters_section(Document& doc, const Report& report);
void trend_section(Document& doc, const Report& report,
                   const std::function<void(FigureId)>& figure);
void users_section(Document& doc, const Report& report);
// data_sections.cpp:
void quality_section(Document& doc, const Report& report);
void runs_section(Document& doc, const Report& report);
void models_section(Document& doc, const Report& report);
void quantities_section(Document& doc, const Report& report,
                        const std::function<void(FigureId)>& figure);
void errors_section(Document& doc, const Report& report);
void energy_section(Document& doc, const Report& report);
/// "Elastic-plastic laws" (plastic_section.cpp), for a campaign whose material is elastic-
/// plastic, and its figures, declared there: e against V/V_y, the permanent approach against
/// V, the loops with the plastic unloading branch.
void plastic_section(Document& doc, const Report& report,
                     const std::function<void(FigureId)>& figure);
std::vector<ReportFigure> plastic_figures(const Report& report);

// Shared by the sections (document.cpp): each quantity's display scale and name (order of
// Quantity), a decision in a word, a model's error in a cell, the mark of a fit that did not
// converge.
extern const std::array<double, quantity_count> page_scale;
extern const std::array<const char*, quantity_count> page_name;
std::string decision_word(Decision decision);
std::string error_cell(const std::optional<ImpactFigures>& model, const ImpactFigures& fem,
                       Quantity quantity);
std::string not_converged(const ReportModel& model);

/// The velocity cell of every table: flagged "(yields)" where the FEM itself yields.
std::string velocity_cell(const ReportRun& run);
/// The range within a band in a table cell: "0.5 to 2 m/s; not decided at 3 m/s", "none".
std::string range_text(const ToleranceVerdict& verdict, const Report& report);

/// The first screen (glance_section.cpp): the verdict in three lines, the figure of every
/// model's errors against V, the recommended model's parameters in a form to copy.
void glance_section(Document& doc, const Report& report, const FigurePlacer& figure);

/// The section "Validity map" (map_section.cpp).
void map_section(Document& doc, const Report& report, const FigurePlacer& figure);

/// A simulator by its name on the page: "Simbody", "MuJoCo", "LAMMPS" (another tool by its
/// own name; simulators_section.cpp).
std::string simulator_tool_name(const std::string& tool);
/// The section "In your simulator" (simulators_section.cpp).
void simulators_section(Document& doc, const Report& report);

} // namespace impact::postprocess::detail
