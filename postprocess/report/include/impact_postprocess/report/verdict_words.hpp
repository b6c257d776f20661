#pragma once
/// @file
/// The verdict in words (verdict_words.cpp): the sentences of the sections on the verdict, the
/// parameters, the velocity trend, the runs and the energy balance, made from the assessment's
/// numbers and decisions (assessment/verdict.hpp); the assessment itself holds no sentence.
/// Each returns "" where the assessment has nothing to say (no run). Public so that a test can
/// check a sentence against the numbers it states.

#include "impact_postprocess/report/report.hpp"

#include <string>
#include <vector>

namespace impact::postprocess {

/// " (out of sample)" or " (in sample)": the basis of a model's judged errors.
std::string sample_basis(bool out_of_sample);
/// "Within 2 %: V = 0.5 to 3 m/s (out of sample) (4 of 5 tested velocities). Outside ...":
/// one tolerance verdict, `basis` placed after the range (" (out of sample)", " in Simbody").
std::string tolerance_sentence(const Report& report, const ToleranceVerdict& verdict,
                               const std::string& basis);
/// Why the campaign has no campaign fit, as the calibration says ("" when it gives none).
std::string campaign_reason(const Report& report);
/// "No verdict: ..." and why.
std::string no_verdict_sentence(const NoVerdict& why);
/// "Summary: the calibrated Hunt–Crossley model (constant b) is within ..." ("" without a
/// verdict).
std::string summary_sentence(const Report& report);
/// Why and where the calibrated model fails, or why there is no verdict.
std::string cause_sentence(const Report& report);
/// "Velocity trend of the FEM's energy loss: 1 - e ∝ V^p with p = ...".
std::string trend_sentence(const Report& report);
/// "Which family the FEM follows ...: V = ... : ..." ("" without ranges).
std::string family_sentence(const Report& report);
/// Where the FEM yields and what that means for the verdict.
std::string plasticity_sentence(const Report& report);
/// What the FEM's numerical uncertainty does to the verdict.
std::string uncertainty_sentence(const Report& report);
/// The FEM's effective alpha against the measured range ("" when no run has one).
std::string alpha_sentence(const Report& report);
/// The notes under the calibrated parameters: the offsets of c and n from Hertz, the trend
/// of the per-run b.
std::vector<std::string> parameter_notes(const Report& report);

} // namespace impact::postprocess
