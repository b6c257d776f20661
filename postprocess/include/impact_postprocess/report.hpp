#pragma once
/// @file
/// The model-validity report of impact-report: every number of the page, computed from a
/// campaign of FEM runs and its calibration (the JSON of impact-calibrate, layout in
/// postprocess/README.md), and the writers of the page (HTML and a Markdown twin) and of the
/// data file from which postprocess/report_figures.py draws the figures. The Python script
/// only draws: no number of the report is computed there.
///
/// Models compared with the FEM at each run:
///   - calibrated Hunt–Crossley: the campaign fit (c, n, b) of the calibration (or, when there
///     is none, each run's own force-history fit, and the page says so);
///   - published Hunt–Crossley: b = 0.1 s/m, n = 3/2, c = Hertz stiffness of the scenario's
///     materials (1.7135e10 N/m^1.5, the published steel example, when the runs do not
///     record them);
///   - Hertz: the same c and n with b = 0;
///   - the best comparison law of the calibration's ranking.
/// Predicted values of the calibrated models are the calibration's (so the tables hold the
/// JSON's numbers); the curves and the published/Hertz values come from impact::reduced.

#include "impact_postprocess/fem_run.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The quantities compared between the FEM and the reduced models, in this order.
enum class ImpactQuantity : std::size_t { restitution, contact_time, force_max, approach_max };
inline constexpr std::size_t impact_quantity_count = 4;
/// restitution [1], contact_time [s], force_max [N], approach_max [m].
using QuantityValues = std::array<double, impact_quantity_count>;
/// "restitution", "contact_time", "force_max", "approach_max" (the calibration JSON's keys).
const char* quantity_key(std::size_t quantity);

/// A problem the page reports: kind "input" (a run or file missing or unusable, a campaign
/// that cannot be fitted), "convergence" (a fit did not converge) or "figures" (they could
/// not be drawn). `source` names the file, run or model concerned.
struct ReportProblem {
  std::string source;
  std::string kind;
  std::string message;
};

/// A time history since first contact: time [s], approach [m], contact force [N].
struct ImpactHistory {
  std::vector<double> time;
  std::vector<double> approach;
  std::vector<double> force;
};

/// One reduced model at one run: its predicted quantities and its history, or why not.
struct ModelAtRun {
  std::optional<QuantityValues> values;
  ImpactHistory history;
  std::string missing; ///< why there are no values (empty when there are)
};

struct ReportModel {
  std::string key;        ///< "calibrated", "published", "hertz", "best-law"
  std::string label;      ///< short name for legends and tables
  std::string parameters; ///< the parameter values, as text with units
  std::string basis;      ///< where the parameters come from
  bool converged = true;  ///< false when its fit did not converge (numbers marked so)
  std::vector<ModelAtRun> runs; ///< parallel to Report::runs
};

/// What a run records beyond the histories (summary.json or "result: ..." attributes).
struct RunRecord {
  std::optional<double> energy_error;        ///< max |balance error| / initial energy
  std::optional<double> lost_energy_fraction;
  std::optional<double> dissipated_energy_fraction;
  std::optional<double> radiated_energy_fraction;
  std::optional<double> max_von_mises;       ///< Pa
  std::optional<double> yield_strength;      ///< Pa (smallest recorded)
  std::string yield_source;                  ///< the key it was read from
};

/// A parameter estimate from the calibration JSON (NaN where absent).
struct ReportEstimate {
  double value;
  double lower;
  double upper;
};

struct ReportRun {
  std::string source;
  double velocity;                 ///< m/s
  double mass;                     ///< kg
  QuantityValues fem;              ///< measured (the calibration's numbers when it has the run)
  ImpactHistory fem_history;       ///< window around the contact, at most ~1500 samples
  bool calibrated = false;         ///< the calibration JSON holds this run
  double damping_from_restitution; ///< b [s/m] of the run (NaN when not calibrated)
  ReportEstimate history_damping;  ///< b of the run's force-history fit
  ReportEstimate history_stiffness;
  ReportEstimate history_exponent;
  RunRecord record;
};

/// The velocity range in which the calibrated Hunt–Crossley model predicts restitution,
/// contact time and peak force within `tolerance` (relative) of the FEM.
struct ToleranceVerdict {
  double tolerance;
  std::vector<int> passes;    ///< per run: 1 within, 0 outside, -1 unknown
  std::optional<std::array<double, 2>> range; ///< widest contiguous passing velocity range
  std::string text;           ///< the verdict in words
};

struct Report {
  std::string campaign_source;
  std::string calibration_source;
  std::vector<ReportProblem> problems;
  std::vector<ReportRun> runs;      ///< ordered by velocity
  std::vector<ReportModel> models;  ///< calibrated, published, hertz, best-law
  nlohmann::json calibration;       ///< as read (null when none)
  bool campaign_fitted = false;
  std::string campaign_reason;      ///< why not, when not fitted
  double hertz_stiffness;           ///< N/m^1.5
  std::string hertz_basis;          ///< how it was obtained
  std::vector<std::string> parameter_notes; ///< offsets of c, n from Hertz, trend of b, ...
  std::vector<ToleranceVerdict> verdicts;   ///< 2 % and 5 %
  std::string cause;                ///< why and where the calibrated model fails
  bool verdict_available = false;
};

/// Builds every number of the report. `calibration` is the JSON of impact-calibrate (null
/// when there is none; the page then says what is missing). `problems` are those met
/// before (reading the campaign or the calibration). Never throws for bad input: what
/// cannot be computed is recorded in Report::problems and left out of the numbers.
Report build_report(const Campaign& campaign, const nlohmann::json& calibration,
                    std::vector<ReportProblem> problems, const std::string& campaign_source,
                    const std::string& calibration_source);

/// A figure of the page: file name (in the figures directory) and caption.
struct ReportFigure {
  std::string file;
  std::string caption;
};

/// The figures of the page, each with the data to draw it (the input of
/// report_figures.py: {"figures": [{file, title, columns, panels: [...]}]}).
nlohmann::json figure_specification(const Report& report);
std::vector<ReportFigure> report_figures(const Report& report);

/// Writes the Markdown page (figures referenced as `figures_directory/<file>`, relative to
/// the page) and the HTML page (figures embedded as base64 PNG, so the file stands alone).
/// Figures whose file does not exist are replaced by a sentence saying so.
void write_report_markdown(const Report& report, const std::filesystem::path& file,
                           const std::filesystem::path& figures_directory);
void write_report_html(const Report& report, const std::filesystem::path& file,
                       const std::filesystem::path& figures_directory);

} // namespace impact::postprocess
