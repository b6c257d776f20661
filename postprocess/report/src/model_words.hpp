#pragma once
// The compared models in words (model_words.cpp): their values, where the values come from,
// why a model has no value. The sections, the figure data and the map's words use them.

#include "impact_postprocess/report/report.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

/// A compared model's values, "c = 1.2e+10 N/m^n, n = 1.5, b = 0.3 s/m" (no unit for a pure
/// number); for per-run fits "c, n, b of each run's force-history fit (table of runs)",
/// without values "n/a".
std::string parameters_words(ModelBasis basis, const std::vector<ModelParameter>& parameters);
/// Where a compared model's values come from; the calibration's own words (its reason for not
/// fitting the campaign, a fit's label, a reference model's basis) where it has them.
std::string basis_words(const ReportModel& model, const std::optional<Calibration>& calibration);
/// Why a model has no value ("" when it has one). The map's reason that names its reference
/// row is worded by map_no_value_words (map_words.hpp).
std::string no_value_words(const std::optional<NoValue>& missing);

} // namespace impact::postprocess::detail
