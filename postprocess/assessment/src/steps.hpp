#pragma once
// The steps of assess (assessment.cpp), in its order, and what they share: the models
// compared (compared_models.cpp), the elastic-plastic laws (plastic_laws.cpp), the verdict
// (verdict.cpp), the validity map (validity_map.cpp, map_plate_models.cpp, thin_plate.cpp,
// map_regions.cpp), the simulators' runs (simulators.cpp) and the recommendation
// (recommendation.cpp).

#include "impact_postprocess/assessment/assessment.hpp"
#include "impact_postprocess/number_format.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

/// The models compared at the runs, calibrated Hunt–Crossley first (see compared_models.cpp).
std::vector<ReportModel> report_models(const std::vector<ReportRun>& runs,
                                       const std::vector<FemRun>& fem_runs,
                                       const std::optional<Calibration>& calibration,
                                       std::vector<Problem>& problems);

/// The elastic-plastic laws of a campaign whose material is elastic-plastic (plastic_laws.cpp);
/// none otherwise, or when the runs do not record the material's constants.
std::optional<PlasticLaws> plastic_laws(const std::vector<FemRun>& fem_runs,
                                        const std::vector<ReportRun>& runs,
                                        const std::optional<Calibration>& calibration);

/// The verdicts, the cause, the trends of the energy loss and of b, the family ranges, the
/// plasticity check and the effective alpha.
void add_verdict(Assessment& report);
/// The decision at one run: within when every |error| + U of `quantities` is within the
/// tolerance, outside when one |error| - U exceeds it, not decided in between (U: the FEM's
/// uncertainty of the run), unknown without values. The one rule of every decision on the page.
Decision decide(const std::optional<ImpactFigures>& judged, const ReportRun& run, double tolerance,
                const std::vector<Quantity>& quantities);
/// The decisions at every run (`judged` parallel to report.runs) and the widest range within.
ToleranceVerdict tolerance_verdict(const Assessment& report,
                                   const std::vector<std::optional<ImpactFigures>>& judged,
                                   double tolerance, const std::vector<Quantity>& quantities);

/// The map of a campaign with sweep axes into report.map (nothing for a velocity campaign).
void add_validity_map(Assessment& report, const Campaign& campaign,
                      const AssessmentOptions& options);
/// The thin-plate model (Zener) at one run: Hertz contact with the run's materials on an
/// infinite Kirchhoff plate of the run's thickness and material, Hunt–Crossley damping b.
struct ThinPlatePrediction {
  std::optional<ImpactFigures> quantities;
  std::optional<NoValue> missing; ///< why there are none (the run does not record the plate, ...)
  std::optional<ThinPlateValues> values; ///< c, Z, lambda at the run
};
/// rigid: the same contact on a rigid support (Z = infinity).
ThinPlatePrediction thin_plate_prediction(const FemRun& run, double damping, bool rigid = false);
/// The Hunt–Crossley b [s/m] with which the thin-plate model (rigid: on a rigid support)
/// reproduces the run's own restitution (TOMS 748 to 40 bits; 0 when the plate alone loses
/// more than the run); none when the model cannot be evaluated for the run.
std::optional<double> thin_plate_damping(const FemRun& reference, bool rigid = false);

/// The runs and the assessed report of each row of a map, parallel to ValidityMap::rows.
struct MapRowReports {
  std::vector<std::vector<FemRun>> runs;
  std::vector<Assessment> reports;
};
/// The thin-plate and the massive-plate model on every row of the map, with the material's
/// damping from the row of the most massive plate (map_plate_models.cpp).
void add_plate_models(ValidityMap& map, const Assessment& report, const MapRowReports& rows);
/// Where the map's model `model` is within each band, from its cells' classes, and where it is
/// not decided or not evaluated, into map.models[model] (map_regions.cpp).
void add_map_region(ValidityMap& map, std::size_t model, std::size_t bands);
/// The class index of map_class (validity_map.hpp).
std::size_t class_index(const MapCell& cell);

/// Reads the simulators' result files of `directory` into report.simulators, judges them
/// against the report's FEM runs, and records every unusable file in report.problems.
void add_simulators(Assessment& report, const std::filesystem::path& directory);

/// The law to recommend (recommendation.cpp): every ranked law judged in the loosest band,
/// into report.recommendation; nothing without a verdict. After the simulators are read (the
/// export closest to the FEM).
void add_recommendation(Assessment& report);

} // namespace impact::postprocess::detail
