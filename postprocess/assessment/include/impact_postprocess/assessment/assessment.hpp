#pragma once
/// @file
/// The assessment of the reduced models against a campaign of FEM runs and its calibration:
/// the runs, the models compared at them, the verdict in each tolerance band, the validity
/// map, the elastic-plastic laws, the simulators' runs of the exports and the law to
/// recommend. One entry point, assess; the report (report/report.hpp) lays it out on a page.
///
/// The verdict: for each model and velocity the relative errors of the energy loss 1 - e^2,
/// t_c, F_max and x_max, out of sample (each velocity predicted by the fit without it) where
/// the campaign has three velocities or more; a velocity is within a tolerance when every
/// error plus the FEM's numerical uncertainty of that quantity is within it, outside when
/// one error minus that uncertainty exceeds it, and not decided otherwise. Velocities at
/// which the FEM exceeds the yield strength are flagged: the viscoelastic model itself is not
/// valid there.

#include "impact_postprocess/assessment/compared_models.hpp"
#include "impact_postprocess/assessment/fem_runs.hpp"
#include "impact_postprocess/assessment/plastic_laws.hpp"
#include "impact_postprocess/assessment/recommendation.hpp"
#include "impact_postprocess/assessment/simulators.hpp"
#include "impact_postprocess/assessment/validity_map.hpp"
#include "impact_postprocess/assessment/verdict.hpp"
#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/models/family_ranges.hpp"
#include "impact_postprocess/models/velocity_trend.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impact::postprocess {

struct Assessment {
  std::string campaign_source;
  std::string calibration_source;
  std::vector<Problem> problems;   ///< includes the warnings (ProblemKind::quality)
  std::vector<ReportRun> runs;     ///< ordered by velocity
  std::vector<ReportModel> models; ///< calibrated first; see compared_models.cpp for the list
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

// Shared by the assessment and the report (namespace detail: not for a reader of the API).
namespace detail {
/// The index of the assessment's run at `velocity`, none if it has none.
std::optional<std::size_t> report_run(const Assessment& assessment, double velocity);
} // namespace detail

struct AssessmentOptions {
  std::vector<double> tolerances = default_tolerances;
  /// The directory of the simulators' result files (impact-simulator-run, every *.json in it)
  /// for the section "In your simulator"; none: the section says how to make them.
  std::optional<std::filesystem::path> simulators;
  /// The whole sweep campaign whose map is drawn, when the campaign given to assess is
  /// one row of it (map_detail_row), and that row's name.
  std::optional<Campaign> map_campaign;
  std::string detail_row;
  /// The calibration of each row of the validity map (of map_campaign, else of the campaign
  /// given to assess), parallel to its map_rows: made by the report pipeline
  /// (calibrate_map_rows, pipeline.hpp), judged by the assessment. A row without one is
  /// judged without calibration.
  std::vector<MapRowCalibration> map_calibrations;
};

/// Assesses the reduced models against a campaign: every number of the report. `calibration`
/// is the calibration read from the JSON of impact-calibrate (none when there is none; the
/// page then says what is missing).
/// `problems` are those met before (reading the campaign or the calibration). Never throws
/// for bad input: what cannot be computed is recorded in Assessment::problems and left out (a
/// missing simulators directory, a result file that is not one or that was made from another
/// campaign: kind "input", naming the file).
Assessment assess(const Campaign& campaign, const std::optional<Calibration>& calibration,
                  std::vector<Problem> problems, const std::string& campaign_source,
                  const std::string& calibration_source, const AssessmentOptions& options = {});

} // namespace impact::postprocess
