#pragma once
// The ranking of a campaign's models (ranking.cpp) and what it shares with the fits
// (calibration.cpp).

#include "impact_postprocess/calibration/calibration.hpp"

#include <vector>

namespace impact::postprocess::detail {

/// The fit quality over several parts: RMS and R^2 weighted by their sample counts.
FitQuality combine(const std::vector<FitQuality>& parts);

/// The ranking of the campaign and reference models by out-of-sample error; the fitted
/// restitution-parametrised laws, which share one force history, as one family.
std::vector<RankedModel> rank_campaign(const CampaignCalibration& campaign,
                                       const std::vector<RunCalibration>& runs);

} // namespace impact::postprocess::detail
