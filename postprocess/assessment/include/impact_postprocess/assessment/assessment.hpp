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

#include <array>
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
  /// The calibration's campaign fit holds Hunt–Crossley (its reason when not: the
  /// calibration's CampaignCalibration::reason).
  bool campaign_fitted = false;
  double hertz_stiffness;             ///< N/m^1.5 (the calibration's; NaN without one)
  std::vector<ModelVerdict> verdicts; ///< one per model, parallel to models
  /// The calibrated model converged and was judged: the verdicts decide (else the page says
  /// why not: no campaign fit, or a fit that did not converge).
  bool verdict_available = false;
  /// Why there is no verdict (with runs and without verdict_available).
  std::optional<NoVerdict> no_verdict;
  /// Why and where the calibrated model fails (with verdict_available).
  std::optional<FailureCause> cause;
  /// The smallest and largest signed error of the calibrated model's energy loss over the
  /// runs it predicts (with verdict_available).
  std::optional<std::array<double, 2>> energy_loss_errors;
  /// How the per-run b varies with V (none with fewer than two runs that have a b).
  std::optional<DampingTrend> damping_trend;
  std::optional<PowerLawTrend> trend; ///< 1 - e ~ V^p of the FEM
  PlasticityCheck plasticity;
  /// Which family the FEM follows in which velocity range (family_ranges.hpp).
  std::vector<FamilyRange> family_ranges;
  /// The elastic-plastic laws, for a campaign whose material is elastic-plastic.
  std::optional<PlasticLaws> plastic_laws;
  /// The FEM's effective alpha (1 - e)/V over the runs against the measured 0.08–0.32 s/m
  /// (none when no run has one).
  std::optional<EffectiveAlpha> effective_alpha;
  /// The directory of the simulators' result files (--simulators), none when not given.
  std::optional<std::string> simulators_source;
  std::vector<SimulatorResult> simulators; ///< the usable result files, Simbody, MuJoCo, LAMMPS
  /// The validity map, for a campaign with sweep axes (none for a velocity-only campaign).
  std::optional<ValidityMap> map;
  /// The law the first screen and the block for a multibody code recommend (none without a
  /// verdict).
  std::optional<LawRecommendation> recommendation;
  /// The row of a map campaign that the sections after the map detail (none when they show
  /// every run).
  std::optional<MapRowAt> detail_row;

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
  /// one row of it (map_detail_row), and where that row lies.
  std::optional<Campaign> map_campaign;
  std::optional<MapRowAt> detail_row;
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
