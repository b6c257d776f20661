#pragma once
// The pieces of the report (report.hpp), one file each: the models compared
// (report_models.cpp), the verdict (report_verdict.cpp), the page as a list of blocks
// (report_document.cpp), its two renderings (report_render.cpp), the figure data
// (report_figures.cpp) and the tools' own runs of the exports (report_simulators.cpp).
// Shared here: the number formats of the page and the rule of the decisions.

#include "impact_postprocess/report/report.hpp"

#include <filesystem>
#include <functional>
#include <utility>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

// ---- Number formats -----------------------------------------------------------------------

/// Six significant digits: enough to compare with the calibration JSON to 1e-5.
std::string cell(double value);
/// "+1.23 %" (three significant digits), "n/a" when not finite.
std::string percent_cell(double fraction);
/// "1.23 %" (three significant digits, no sign), "not known" when not finite.
std::string unsigned_percent(double fraction);
/// Four significant digits.
std::string short_number(double value);
/// "V = 1 m/s".
std::string velocity_label(double velocity);
/// "0.5, 1 and 2 m/s".
std::string velocity_list(const std::vector<double>& velocities);
/// The velocity cell of every table: flagged "(yields)" where the FEM itself yields.
std::string velocity_cell(const ReportRun& run);
/// The range within a band in a table cell: "0.5 to 2 m/s; not decided at 3 m/s", "none".
std::string range_text(const ToleranceVerdict& verdict, const Report& report);

// ---- Models (report_models.cpp) ---------------------------------------------------------

/// The same run in another list: the entry with the same source file, else the only one at
/// the same velocity; -1 if none.
bool same_source(const std::string& a, const std::string& b);
bool same_velocity(double a, double b);
/// The index of the report's run at `velocity`, none if it has none.
std::optional<std::size_t> report_run(const Report& report, double velocity);

/// The models compared at the runs, calibrated Hunt–Crossley first (see report_models.cpp).
std::vector<ReportModel> report_models(const std::vector<ReportRun>& runs,
                                       const std::vector<FemRun>& fem_runs,
                                       const std::optional<Calibration>& calibration,
                                       std::vector<Problem>& problems);

// ---- Verdict (report_verdict.cpp) -------------------------------------------------------

/// The verdicts, cause, trend, plasticity and the notes on the parameters.
void add_verdict(Report& report);

/// "2 %".
std::string band_name(double tolerance);
/// The decision at one run: within when every |error| + U of `quantities` is within the
/// tolerance, outside when one |error| - U exceeds it, not decided in between (U: the FEM's
/// uncertainty of the run), unknown without values. The one rule of every decision on the page.
Decision decide(const std::optional<ImpactFigures>& judged, const ReportRun& run, double tolerance,
                const std::vector<Quantity>& quantities);
/// The decisions at every run (`judged` parallel to report.runs), the widest range within and
/// the sentence ("Within 2 %: V = ... m/s" + basis + ...).
ToleranceVerdict tolerance_verdict(const Report& report,
                                   const std::vector<std::optional<ImpactFigures>>& judged,
                                   double tolerance, const std::vector<Quantity>& quantities,
                                   const std::string& basis);

/// The law to recommend (recommendation.cpp): every ranked law judged in the loosest band,
/// into report.recommendation; nothing without a verdict. After the simulators are read (the
/// export closest to the FEM).
void add_recommendation(Report& report);

/// The elastic-plastic laws of a campaign whose material is elastic-plastic (plastic_laws.cpp);
/// none otherwise, or when the runs do not record the material's constants.
std::optional<PlasticLaws> plastic_laws(const std::vector<FemRun>& fem_runs,
                                        const std::vector<ReportRun>& runs,
                                        const std::optional<Calibration>& calibration);

/// The seed paper's measured range of (1 - e)/V [s/m] (steel, glass, brass; Goldsmith).
inline constexpr double measured_alpha_low = 0.08, measured_alpha_high = 0.32;
/// (1 - e)/V [s/m] of the FEM run (effective_alpha.cpp).
double effective_alpha(const ReportRun& run);
/// The FEM's effective alpha over the runs against the measured range, in words.
std::string effective_alpha_text(const std::vector<ReportRun>& runs);

// ---- In your simulator (report_simulators.cpp) ------------------------------------------

/// Reads the simulators' result files of `directory` into report.simulators, judges them
/// against the report's FEM runs, and records every unusable file in report.problems.
void add_simulators(Report& report, const std::filesystem::path& directory);
/// What the tools measure (x_max and t(F_max) are not among them): the quantities judged, and
/// those of the tables.
inline const std::vector<Quantity> simulator_judged_quantities = {Quantity::energy_loss,
                                                                  Quantity::contact_time,
                                                                  Quantity::force_max};
inline const std::vector<Quantity> simulator_table_quantities = {Quantity::restitution,
                                                                 Quantity::energy_loss,
                                                                 Quantity::contact_time,
                                                                 Quantity::force_max};
/// "Simbody", "MuJoCo", "LAMMPS" (another tool by its own name).
std::string simulator_tool_name(const std::string& tool);

// ---- Validity map (report_map.cpp, report_thin_plate.cpp) ------------------------------

/// The thin-plate model (Zener) at one run: Hertz contact with the run's materials on an
/// infinite Kirchhoff plate of the run's thickness and material, Hunt–Crossley damping b.
struct ThinPlatePrediction {
  std::optional<ImpactFigures> quantities;
  std::string missing;    ///< why there are none (the run does not record the plate, ...)
  std::string parameters; ///< c, Z, lambda as text
};
/// rigid: the same contact on a rigid support (Z = infinity).
ThinPlatePrediction thin_plate_prediction(const FemRun& run, double damping, bool rigid = false);
/// The Hunt–Crossley b [s/m] with which the thin-plate model (rigid: on a rigid support)
/// reproduces the run's own restitution (TOMS 748 to 40 bits; 0 when the plate alone loses
/// more than the run); none when the model cannot be evaluated for the run.
std::optional<double> thin_plate_damping(const FemRun& reference, bool rigid = false);

/// The map of a campaign with sweep axes into report.map (nothing for a velocity campaign).
void add_validity_map(Report& report, const Campaign& campaign, const ReportOptions& options);
/// The runs and the assessed report of each row of a map, parallel to ValidityMap::rows.
struct MapRowReports {
  std::vector<std::vector<FemRun>> runs;
  std::vector<Report> reports;
};
/// The thin-plate and the massive-plate model on every row of the map, with the material's
/// damping from the row of the most massive plate (map_plate_models.cpp).
void add_plate_models(ValidityMap& map, const Report& report, const MapRowReports& rows);
/// Where the map's model `model` is within each band, in a sentence (map_regions.cpp).
std::string map_region(const ValidityMap& map, std::size_t model,
                       const std::vector<double>& tolerances);
/// "Plate thickness" of "Scenario/Plate thickness".
std::string short_name(const std::string& parameter);
/// A sweep value with its unit ("0.05 m"; a text value as it is).
std::string with_unit(const SweepValue& value, const std::string& unit);
/// The class index of map_class (report.hpp).
std::size_t class_index(const MapCell& cell);
/// The judged quantity with the largest |error| at the cell, and that error.
std::optional<std::pair<Quantity, double>> map_worst_error(const MapCell& cell);

// ---- Page (report_document.cpp, report_render.cpp) --------------------------------------

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// A figure placed on the page: its path relative to the page, and caption.
struct PageFigure {
  std::string file;
  std::string caption;
};

struct Block {
  enum class Kind { heading, paragraph, warning, list, table, figure, code } kind;
  int level = 2;
  std::string text;
  std::vector<std::string> items;
  Table table;
  PageFigure figure;
  /// A section heading (level 2) that opens a section the reader can fold (HTML <details>,
  /// closed until opened); the section ends at the next level-2 heading.
  bool foldable = false;
};

/// The page as a list of blocks. The first screen (the title, the verdict in three lines,
/// the first figure, the recommended model) comes first; after fold_from_here() every
/// section (level-2 heading) can be folded.
class Document {
public:
  void heading(const std::string& text, int level = 2) {
    blocks.push_back({Block::Kind::heading, level, text, {}, {}, {}, folding && level == 2});
  }
  /// Every section from here on can be folded.
  void fold_from_here() { folding = true; }
  void paragraph(const std::string& text) {
    blocks.push_back({Block::Kind::paragraph, 0, text, {}, {}, {}});
  }
  /// A paragraph shown as a warning (red in the HTML).
  void warning(const std::string& text) {
    blocks.push_back({Block::Kind::warning, 0, text, {}, {}, {}});
  }
  void list(std::vector<std::string> items) {
    if (!items.empty()) blocks.push_back({Block::Kind::list, 0, "", std::move(items), {}, {}});
  }
  void table(Table table) {
    blocks.push_back({Block::Kind::table, 0, "", {}, std::move(table), {}});
  }
  void figure(const PageFigure& figure) {
    blocks.push_back({Block::Kind::figure, 0, "", {}, {}, figure});
  }
  void code(const std::string& text) { blocks.push_back({Block::Kind::code, 0, text, {}, {}, {}}); }
  std::vector<Block> blocks;

private:
  bool folding = false;
};

Document build_document(const Report& report, const std::filesystem::path& figures_directory);

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

/// Places a declared figure on the page (nothing when it is not declared); the key names
/// the map model of a validity map.
using FigurePlacer = std::function<void(FigureId, const std::string& model_key)>;

/// A law of the calibration in a form to copy (glance_section.cpp): its name and origin, its
/// force law, and each parameter's symbol, value and unit.
struct LawBlock {
  struct Parameter {
    std::string name;
    double value;
    std::string unit;
  };
  bool found = false; ///< the calibration holds the law
  std::string name;
  std::string law;
  std::vector<Parameter> parameters;
};
LawBlock law_block(const Report& report, const std::string& key);
/// heading + name, then the law and one parameter per line, "  c = 1.2e+10 N/m^1.5".
std::string law_block_text(const std::string& heading, const LawBlock& block);
/// "its largest error is -12.3 % (peak approach x_max at V = 5 m/s)".
std::string largest_error(const Report& report, const JudgedLaw& law);
/// What keeps a law out of the band, by quantity: "1 - e^2 at V = 0.1 and 0.2 m/s, x_max at
/// V = 5 m/s".
std::string breaking_text(const Report& report, const JudgedLaw& law);
/// Where a law is within the band: "over the whole tested range, V = 0.5 to 5 m/s" or
/// "at V = 0.5 to 1 and 3 to 5 m/s".
std::string where_within(const Report& report, const JudgedLaw& law);
/// "Label (key)".
std::string law_name(const JudgedLaw& law);
/// The velocities of report runs.
std::vector<double> velocities_of(const Report& report, const std::vector<std::size_t>& runs);

/// The first screen (glance_section.cpp): the verdict in three lines, the figure of every
/// model's errors against V, the recommended model's parameters in a form to copy.
void glance_section(Document& doc, const Report& report, const FigurePlacer& figure);

/// The section "Validity map" (validity_map.cpp).
void map_section(Document& doc, const Report& report, const FigurePlacer& figure);

/// The section "In your simulator" (report_simulators.cpp).
void simulators_section(Document& doc, const Report& report);

} // namespace impact::postprocess::detail
