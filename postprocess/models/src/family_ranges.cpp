// Which family the FEM's restitution follows in which velocity range (family_ranges.hpp).

#include "impact_postprocess/models/family_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Slope of ln y against ln V through the runs with 0 < e < 1 (y = e or 1 - e): the fit with
// its interval from three runs on, the line through two; NaN below.
double slope_of(const std::vector<double>& v, const std::vector<double>& e, bool of_loss,
                std::optional<PowerLawTrend>& trend, double level) {
  trend = of_loss ? fit_restitution_trend(v, e, level) : fit_restitution_power_law(v, e, level);
  if (trend) return trend->exponent;
  std::vector<std::size_t> inside;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (e[i] > 0 && e[i] < 1) inside.push_back(i);
  if (inside.size() != 2 || v[inside[0]] == v[inside[1]]) return nan;
  const auto y = [&](std::size_t i) { return std::log(of_loss ? 1 - e[i] : e[i]); };
  return (y(inside[1]) - y(inside[0])) / (std::log(v[inside[1]]) - std::log(v[inside[0]]));
}

FamilyRange judge(const std::vector<double>& v, const std::vector<double>& e, bool above_yield,
                  bool plastic_possible, double level, const std::vector<PlasticReference>& laws) {
  FamilyRange range;
  range.low = v.front();
  range.high = v.back();
  range.runs = v.size();
  range.above_yield = above_yield;
  range.slope = nan;
  range.plastic_possible = plastic_possible;
  for (double restitution : e) range.largest_loss = std::max(range.largest_loss, 1 - restitution);
  if (range.largest_loss < elastic_loss_limit) {
    range.family = "elastic";
    range.basis = FamilyBasis::elastic;
    return range;
  }
  std::optional<PowerLawTrend> restitution_trend;
  range.loss_slope = slope_of(v, e, true, range.loss_trend, level);
  const double s = slope_of(v, e, false, restitution_trend, level);
  if (!std::isfinite(range.loss_slope)) return range;
  if (plastic_possible && above_yield) {
    range.basis = FamilyBasis::plastic;
    range.slope = s;
    range.slope_of = "e";
    range.trend = restitution_trend;
    for (const auto& law : laws) {
      std::optional<PowerLawTrend> ignored;
      const double slope = slope_of(v, law.restitution, false, ignored, level);
      if (!std::isfinite(slope)) continue;
      range.plastic_low = range.law_slopes.empty() ? slope : std::min(range.plastic_low, slope);
      range.plastic_high = range.law_slopes.empty() ? slope : std::max(range.plastic_high, slope);
      range.law_slopes.push_back({law.law, slope});
    }
    // Distance to the plastic band and to a constant e (slope 0).
    const double to_plastic = s < range.plastic_low
                                  ? range.plastic_low - s
                                  : (s > range.plastic_high ? s - range.plastic_high : 0.0);
    range.family = to_plastic < std::abs(s) ? "plastic" : "constant restitution";
    return range;
  }
  const double p = range.loss_slope;
  range.basis = FamilyBasis::nearest;
  range.slope = p;
  range.slope_of = "1 - e";
  range.trend = range.loss_trend;
  const ReferenceSlope* nearest = nullptr;
  for (const auto& reference : reference_slopes())
    if (!nearest || std::abs(reference.slope - p) < std::abs(nearest->slope - p))
      nearest = &reference;
  range.family = nearest->family;
  range.reference_slope = nearest->slope;
  return range;
}

} // namespace

std::vector<FamilyRange> family_ranges(const std::vector<double>& velocity,
                                       const std::vector<double>& restitution,
                                       std::optional<double> yield_velocity, double level,
                                       const std::vector<PlasticReference>& plastic_laws) {
  std::vector<std::size_t> order(std::min(velocity.size(), restitution.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return velocity[a] < velocity[b]; });
  std::vector<double> below_v, below_e, above_v, above_e;
  std::vector<PlasticReference> above_laws;
  for (const auto& law : plastic_laws) above_laws.push_back({law.law, {}});
  for (std::size_t i : order) {
    const bool above = yield_velocity && velocity[i] > *yield_velocity;
    (above ? above_v : below_v).push_back(velocity[i]);
    (above ? above_e : below_e).push_back(restitution[i]);
    if (above)
      for (std::size_t k = 0; k < plastic_laws.size(); ++k)
        above_laws[k].restitution.push_back(
            i < plastic_laws[k].restitution.size() ? plastic_laws[k].restitution[i] : nan);
  }
  std::vector<FamilyRange> ranges;
  const bool plastic = yield_velocity.has_value();
  if (!below_v.empty()) ranges.push_back(judge(below_v, below_e, false, plastic, level, {}));
  if (!above_v.empty()) ranges.push_back(judge(above_v, above_e, true, plastic, level, above_laws));
  return ranges;
}

} // namespace impact::postprocess
