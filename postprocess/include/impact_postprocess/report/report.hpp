#pragma once
/// @file
/// The model-validity report of impact-report: every number of the page, computed from a
/// campaign of FEM runs and its calibration (impact-calibrate's JSON, read through
/// calibration_from_json), and the writers of the page (HTML and a Markdown twin) and of the
/// data file from which postprocess/report_figures.py draws the figures. The Python script
/// only draws: no number of the report is computed there.
///
/// The verdict: for each model and velocity the relative errors of the energy loss 1 - e^2,
/// t_c, F_max and x_max, out of sample (each velocity predicted by the fit without it) where
/// the campaign has three velocities or more; a velocity is within a tolerance when every
/// error plus the FEM's numerical uncertainty of that quantity is within it, outside when
/// one error minus that uncertainty exceeds it, and not decided otherwise. Velocities at
/// which the FEM exceeds the yield strength are flagged: the viscoelastic model itself is not
/// valid there.

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_record.hpp"
#include "impact_postprocess/models/impact_quantities.hpp"
#include "impact_postprocess/models/family_ranges.hpp"
#include "impact_postprocess/models/velocity_trend.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impact::postprocess {

/// A time history since first contact: time [s], approach [m], contact force [N].
struct ImpactHistory {
  std::vector<double> time;
  std::vector<double> approach;
  std::vector<double> force;
};

/// One reduced model at one run.
struct ModelAtRun {
  std::optional<ImpactFigures> in_sample;     ///< fitted to all runs (or not fitted at all)
  std::optional<ImpactFigures> out_of_sample; ///< fitted without this velocity
  ImpactHistory history;                      ///< of the in-sample model
  std::vector<double> residual; ///< (F_model - F_FEM) / F_max at the FEM history's times
  std::string missing;          ///< why there are no values (empty when there are)
  /// The errors the verdict uses: out of sample when there are, else in sample.
  const std::optional<ImpactFigures>& judged() const {
    return out_of_sample ? out_of_sample : in_sample;
  }
};

/// Jackknife prediction band of a fitted model over the tested velocity range: the full
/// fit's prediction and, at each velocity, +- t_{g-1} times the jackknife standard error of
/// the held-out fits' predictions.
struct PredictionBand {
  std::vector<double> velocity;
  std::array<std::vector<double>, quantity_count> center, lower, upper; ///< by Quantity
};

struct ReportModel {
  std::string key;             ///< "calibrated", the calibration's key, "best-law", ...
  std::string label;           ///< short name for legends and tables
  std::string parameters;      ///< the parameter values, as text with units
  std::string basis;           ///< where the parameters come from
  std::string calibration_key; ///< the model's key in the calibration ("" if none)
  std::size_t free_parameters = 0;
  bool converged = true;        ///< false when its fit did not converge (numbers marked so)
  bool out_of_sample = false;   ///< its judged errors are out of sample
  std::vector<ModelAtRun> runs; ///< parallel to Report::runs
  std::optional<PredictionBand> band;
  /// The model's curve over the tested range (no band): velocity and each quantity.
  std::optional<PredictionBand> curve;
};

struct ReportEstimate {
  double value;
  double lower;
  double upper;
};

struct ReportRun {
  std::string source;
  double velocity;                 ///< m/s
  double mass;                     ///< kg
  ImpactFigures fem;               ///< measured (the calibration's numbers when it has the run)
  ImpactHistory fem_history;       ///< window around the contact, at most ~1500 samples
  bool calibrated = false;         ///< the calibration holds this run
  double damping_from_restitution; ///< b [s/m] of the run (NaN when not calibrated)
  ReportEstimate history_damping;  ///< b of the run's force-history fit
  ReportEstimate history_stiffness;
  ReportEstimate history_exponent;
  FemRunRecord record;
  FemUncertainty uncertainty; ///< of each FEM quantity (relative)
  /// The FEM exceeds the yield strength of a body without plasticity at this run: the flag
  /// "(yields)" (never set when the material is elastic-plastic, FemRunRecord::plastic_material:
  /// that FEM yields and stays valid).
  bool yields = false;
};

/// The decision for one model at one run and tolerance.
enum class Decision { within, outside, undecided, unknown };

/// Where a model holds within one tolerance.
struct ToleranceVerdict {
  double tolerance;
  std::vector<Decision> decisions;            ///< per run
  std::optional<std::array<double, 2>> range; ///< widest contiguous velocity range within
  std::string text;                           ///< the verdict in words
};

struct ModelVerdict {
  std::string model_key; ///< ReportModel::key
  bool out_of_sample = false;
  std::vector<ToleranceVerdict> tolerances;
};

/// Where the viscoelastic FEM model itself is not valid: the runs above the yield strength.
/// With an elastic-plastic material the FEM is valid above yield: then plastic_material is set
/// and first_yielding_velocity stays empty (no velocity is flagged).
struct PlasticityCheck {
  bool recorded = false;         ///< some run records a yield strength and its stress
  bool plastic_material = false; ///< the FEM's material is elastic-plastic
  std::optional<double> first_yielding_velocity; ///< m/s, the lowest tested velocity that yields
  std::optional<double>
      onset_estimate; ///< m/s, log-log interpolation of the stress to the yield strength
  std::string text;
};

/// One elastic-plastic law against an elastic-plastic FEM campaign (plastic_laws.cpp): its
/// restitution and permanent approach over the tested range and at the runs, and its
/// force-approach loop at each run (reduced::elastic_plastic_impact, _loop).
struct PlasticLawCurve {
  std::string key; ///< the calibration's key ("thornton-material", "jackson-green", ...)
  std::string label;
  bool fitted = false;                        ///< a campaign fit (else nothing fitted)
  std::string parameters;                     ///< the values used, as text with units
  std::size_t free_parameters = 0;            ///< of the campaign fit
  std::vector<double> velocity;               ///< m/s, the curve's grid
  std::vector<double> restitution;            ///< e on the grid
  std::vector<double> permanent_approach;     ///< x_p [m] on the grid (empty: a restitution fit)
  std::vector<double> run_restitution;        ///< e at each report run (NaN where it failed)
  std::vector<double> run_permanent_approach; ///< x_p [m] at each report run (likewise)
  std::vector<ImpactHistory> loops;           ///< per report run (empty where it failed)
  /// A damped elastic-plastic law (viscous and plastic loss): not a reference of the
  /// plastic family's slope.
  bool damped = false;
};

/// The elastic-plastic laws of an elastic-plastic campaign (none otherwise).
struct PlasticLaws {
  double yield_velocity;               ///< V_y [m/s], Johnson's p_y = 1.6 Y (Thornton's)
  double jackson_green_yield_velocity; ///< V_y [m/s] with p_y = C(nu) Y
  std::string yield_basis;             ///< the constants, in words
  /// No-fit Thornton and Jackson–Green, Jackson–Green–Marghitu's restitution fit (e only,
  /// no loops), then the campaign fits; then the damped elastic-plastic laws
  /// (damped_plastic_models.hpp) from the material and fitted.
  std::vector<PlasticLawCurve> laws;
  std::vector<double> fem_permanent_approach; ///< m, per report run (NaN: not recorded)
  std::string text;                           ///< the comparison in words
};

/// What a simulator measured at one velocity with a file of impact-export (a result file of
/// tests/consumers/run_in_simulators.sh, format "impact-simulator-run", postprocess/README.md).
/// The tools measure e, t_c and F_max: t(F_max) and x_max are NaN.
struct SimulatorRunAt {
  double velocity;             ///< m/s
  ImpactFigures tool;          ///< measured by the tool from its own state
  ImpactFigures reduced_model; ///< the exported model's prediction (export.json)
  ImpactFigures fem;           ///< the FEM as the file holds it (the calibration's numbers)
};

/// One result file: one tool (and deck) run at the campaign's velocities.
struct SimulatorResult {
  std::string source; ///< the result file
  std::string tool;   ///< "simbody", "mujoco", "lammps" (or another tool's name)
  std::string tool_version;
  std::string model;           ///< the exported model: "hunt-crossley", "linear-spring-damper", ...
  std::string export_manifest; ///< the export.json the file was run from
  std::string file;            ///< the exported file, relative to the export directory
  std::optional<double> reference_velocity; ///< m/s, where the export was matched (MuJoCo)
  std::vector<SimulatorRunAt> runs;         ///< ordered by velocity
  /// Against the FEM of the report's runs, judged like the verdict (with the FEM's
  /// uncertainty) in 1 - e^2, t_c and F_max: one per tolerance, decisions parallel to
  /// Report::runs.
  std::vector<ToleranceVerdict> against_fem;
};

/// A ranked law judged at every run of the report by the verdict's rule (decide, with the
/// FEM's uncertainty) in the loosest band: where it holds, and its largest error.
struct JudgedLaw {
  std::string key;   ///< the calibration's key (its ranking)
  std::string label; ///< as the page names it
  std::size_t rank;  ///< 0-based, in the calibration's ranking
  double score;      ///< the ranking's RMS error
  /// The errors judged are out of sample (fitted without the velocity, or nothing fitted). A
  /// fit scored in sample (fewer than three velocities) is never said to hold: its errors are
  /// those of the runs it was fitted to.
  bool out_of_sample = false;
  /// F = c x^n (1 + b x') with a constant b or b(V) = b_1 V^-q: the law a multibody code takes
  /// as it is (Simbody's HuntCrossleyForce, the force of the block "For a multibody code").
  bool hunt_crossley_form = false;
  std::vector<Decision> decisions; ///< per report run, in the loosest band
  /// Per report run where it is not within: the quantity that keeps it out (the largest
  /// |error| - U of those with |error| + U beyond the band; U the FEM's uncertainty); none
  /// where it is within or has no prediction.
  std::vector<std::optional<Quantity>> breaking;
  std::size_t within = 0;    ///< runs within
  double worst_error;        ///< largest |relative error| of the judged quantities (signed)
  Quantity worst_quantity;   ///< where it is
  std::size_t worst_run = 0; ///< at which report run
};

/// An export run in its simulator (Report::simulators) against the FEM: its largest error.
struct ExportError {
  std::size_t simulator; ///< index in Report::simulators
  double worst_error;    ///< largest |relative error| of the tool's own measurement (signed)
  Quantity worst_quantity;
  double velocity; ///< m/s, where it is
};

/// The law to recommend, by the verdict's rule in the loosest band (5 %): one that holds where
/// it is recommended, or none, with the law and the export that come closest.
struct LawRecommendation {
  double tolerance = 0;        ///< the loosest band of the report
  std::vector<JudgedLaw> laws; ///< every ranked law that could be judged, in rank order
  /// Index in laws: the out-of-sample law within at the most tested velocities, the better
  /// ranked among equals; none when no law holds anywhere.
  std::optional<std::size_t> recommended;
  /// Index in laws: the same among the Hunt–Crossley forms (the block for a multibody code).
  std::optional<std::size_t> multibody;
  /// Report runs at which no out-of-sample law is within the band.
  std::vector<std::size_t> uncovered;
  /// Index in laws: the law ranked first (out of sample where one is), the closest when
  /// none holds; none without a ranking.
  std::optional<std::size_t> closest;
  /// The export closest to the FEM in its simulator, when the simulators' runs are given.
  std::optional<ExportError> closest_export;
};

/// One cell of a validity map: one run (a value of the other axis, a velocity) and one model.
struct MapCell {
  double velocity;                  ///< m/s
  std::string source;               ///< the FEM run
  std::optional<ImpactFigures> fem; ///< measured
  std::optional<ImpactFigures>
      judged; ///< the model's prediction judged (out of sample where the row allows)
  FemUncertainty uncertainty;      ///< the FEM's, of each quantity (relative)
  std::vector<Decision> decisions; ///< per tolerance of the report (increasing)
  bool yields = false;
  std::string missing; ///< why the model has no value here ("" if it has)
};

/// A model on one row (the runs at one value of the other axis).
struct MapModelRow {
  std::string parameters; ///< the values used on this row, as text with units
  bool out_of_sample = false;
  std::string missing;        ///< why the model cannot be evaluated on this row ("" if it can)
  std::vector<MapCell> cells; ///< one per run of the row, ordered by velocity
};

struct MapRow {
  SweepValue value;                 ///< of the other axis
  std::vector<MapModelRow> models;  ///< parallel to ValidityMap::models
  std::string calibration_problems; ///< the row calibration's problems, in words ("" if none)
};

/// A model of the map.
struct MapModel {
  std::string key; ///< "calibrated", "best-law", "thin-plate"
  std::string label;
  std::string basis;  ///< how it is obtained on each row
  std::string region; ///< where it is valid, in a sentence
};

/// The validity map of a two-axis campaign (velocity x one other parameter): every row is
/// calibrated and judged as a velocity campaign, by the verdict's rule (postprocess/README.md).
struct ValidityMap {
  bool available = false;
  std::string reason;             ///< why there is no map, when not available
  std::string parameter;          ///< the other axis ("Scenario/Plate thickness")
  std::string unit;               ///< its unit, when known ("m")
  bool logarithmic = false;       ///< the other axis drawn on a log scale
  std::vector<double> velocities; ///< every velocity of the campaign, increasing
  std::vector<MapModel> models;
  std::vector<MapRow> rows;      ///< in the order of the axis's values
  std::size_t reference_row = 0; ///< the row whose Hunt–Crossley b the thin-plate model takes
};

/// A cell's class by the verdict's decisions: 0 .. bands-1 within that band (the tightest one
/// in which it is within), bands outside the loosest, bands + 1 not decided (the FEM's
/// uncertainty as large as the margin), bands + 2 not evaluated (no prediction); and its
/// name ("within 2 %", "outside 5 %", "not decided", "not evaluated").
std::size_t map_class(const MapCell& cell);
std::string map_class_name(const MapCell& cell, const std::vector<double>& tolerances);
/// The largest FEM uncertainty (relative) of the judged quantities at the cell, NaN if none
/// is known.
double map_uncertainty(const MapCell& cell);

struct Report {
  std::string campaign_source;
  std::string calibration_source;
  std::vector<Problem> problems;          ///< includes the warnings (ProblemKind::quality)
  std::vector<ReportRun> runs;            ///< ordered by velocity
  std::vector<ReportModel> models;        ///< calibrated first; see report.cpp for the list
  std::optional<Calibration> calibration; ///< as read
  std::vector<double> tolerances;         ///< of the verdict, increasing
  bool campaign_fitted = false;
  std::string campaign_reason;              ///< why not, when not fitted
  double hertz_stiffness;                   ///< N/m^1.5
  std::string hertz_basis;                  ///< how it was obtained
  std::vector<std::string> parameter_notes; ///< offsets of c, n from Hertz, trend of b, ...
  std::vector<ModelVerdict> verdicts;       ///< one per model, parallel to models
  std::string cause;                        ///< why and where the calibrated model fails
  bool verdict_available = false;
  std::optional<PowerLawTrend> trend; ///< 1 - e ~ V^p of the FEM
  std::string trend_text;
  PlasticityCheck plasticity;
  /// Which family the FEM follows in which velocity range (family_ranges.hpp).
  std::vector<FamilyRange> family_ranges;
  std::string family_text;
  /// The elastic-plastic laws, for a campaign whose material is elastic-plastic.
  std::optional<PlasticLaws> plastic_laws;
  /// The FEM's effective alpha (1 - e)/V per run against the measured 0.08–0.32 s/m.
  std::string alpha_text;
  std::string uncertainty_text; ///< what the FEM's uncertainty does to the verdict
  std::string summary;          ///< the verdict in a few sentences
  /// The directory of the simulators' result files (--simulators), none when not given.
  std::optional<std::string> simulators_source;
  std::vector<SimulatorResult> simulators; ///< the usable result files, Simbody, MuJoCo, LAMMPS
  /// The validity map, for a campaign with sweep axes (none for a velocity-only campaign).
  std::optional<ValidityMap> map;
  /// The law the first screen and the block for a multibody code recommend (none without a
  /// verdict).
  std::optional<LawRecommendation> recommendation;
  /// The row of a map campaign that the sections after the map detail ("Plate thickness =
  /// 0.05 m"); empty when they show every run.
  std::string detail_row;

  /// The model of this key, or null.
  const ReportModel* model(std::string_view key) const;
  const ModelVerdict* verdict(std::string_view key) const;
};

/// One row of a validity map: a value of the other axis and the campaign's runs there.
struct MapRowRuns {
  SweepValue value;
  std::string name; ///< "Plate thickness = 0.05"
  std::vector<FemRun> runs;
};

/// The calibration of one row of a validity map.
struct MapRowCalibration {
  std::optional<Calibration>
      calibration;   ///< none when the row has no run or could not be calibrated
  std::string error; ///< why it could not be calibrated ("" otherwise)
};

struct ReportOptions {
  std::vector<double> tolerances = default_tolerances;
  /// The directory of the simulators' result files (impact-simulator-run, every *.json in it)
  /// for the section "In your simulator"; none: the section says how to make them.
  std::optional<std::filesystem::path> simulators;
  /// The whole sweep campaign whose map is drawn, when the campaign given to build_report is
  /// one row of it (map_detail_row), and that row's name.
  std::optional<Campaign> map_campaign;
  std::string detail_row;
  /// The calibration of each row of the validity map (of map_campaign, else of the campaign
  /// given to build_report), parallel to its map_rows: made by the report pipeline
  /// (calibrate_map_rows, pipeline.hpp), judged by the assessment. A row without one is
  /// judged without calibration.
  std::vector<MapRowCalibration> map_calibrations;
};

/// The rows of the validity map of a two-axis campaign (velocity x one other parameter): each
/// value of the other axis, in the map's order (increasing when every value is a number), with
/// its runs; none for any other campaign.
std::vector<MapRowRuns> map_rows(const Campaign& campaign);

/// The row of a two-axis campaign (velocity x one other parameter) that the report's sections
/// after the map detail, as a velocity campaign of its own: the runs with the largest
/// Scenario/Plate thickness (the most massive plate, nearest to the reduced models'
/// assumption), else those at the other axis's first value; and the row's name ("Plate
/// thickness = 0.05 m"). Nothing for any other campaign (its sections show every run).
std::optional<std::pair<Campaign, std::string>> map_detail_row(const Campaign& campaign);

/// Builds every number of the report. `calibration` is the calibration read from the JSON
/// of impact-calibrate (none when there is none; the page then says what is missing).
/// `problems` are those met before (reading the campaign or the calibration). Never throws
/// for bad input: what cannot be computed is recorded in Report::problems and left out (a
/// missing simulators directory, a result file that is not one or that was made from another
/// campaign: kind "input", naming the file).
Report build_report(const Campaign& campaign, const std::optional<Calibration>& calibration,
                    std::vector<Problem> problems, const std::string& campaign_source,
                    const std::string& calibration_source, const ReportOptions& options = {});

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
