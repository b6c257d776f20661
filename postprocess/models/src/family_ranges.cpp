// Which family the FEM's restitution follows in which velocity range (family_ranges.hpp).

#include "impact_postprocess/models/family_ranges.hpp"
#include "impact_postprocess/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

std::string slope_words(const std::string& of, double slope,
                        const std::optional<PowerLawTrend>& trend) {
  std::string text = of + " ∝ V^" + significant(slope, 3);
  if (trend)
    text += " [" + significant(trend->lower, 3) + ", " + significant(trend->upper, 3) + "]";
  else
    text += " (two runs: no interval)";
  return text;
}

FamilyRange judge(const std::vector<double>& v, const std::vector<double>& e, bool above_yield,
                  bool plastic_possible, std::optional<double> yield_velocity, double level,
                  const std::vector<PlasticReference>& laws) {
  FamilyRange range{v.front(),
                    v.back(),
                    v.size(),
                    above_yield,
                    "",
                    nan,
                    "",
                    std::nullopt,
                    plastic_restitution_slope,
                    plastic_restitution_slope,
                    ""};
  std::string where = "V = " + significant(range.low, 3) +
                      (range.high > range.low ? " to " + significant(range.high, 3) : "") + " m/s";
  if (yield_velocity)
    where += " (" + std::string(above_yield ? "above" : "at or below") +
             " V_y, V/V_y = " + significant(range.low / *yield_velocity, 3) +
             (range.high > range.low ? " to " + significant(range.high / *yield_velocity, 3) : "") +
             ", " + std::to_string(v.size()) + (v.size() == 1 ? " run)" : " runs)");
  else
    where += " (" + std::to_string(v.size()) + (v.size() == 1 ? " run)" : " runs)");
  double largest_loss = 0;
  for (double restitution : e) largest_loss = std::max(largest_loss, 1 - restitution);
  if (largest_loss < elastic_loss_limit) {
    range.family = "elastic";
    range.text = where + ": elastic, 1 - e below " + significant(largest_loss * 100, 2) +
                 " % at every run (the limit is " + significant(elastic_loss_limit * 100, 6) +
                 " %).";
    return range;
  }
  std::optional<PowerLawTrend> loss_trend, restitution_trend;
  const double p = slope_of(v, e, true, loss_trend, level);
  const double s = slope_of(v, e, false, restitution_trend, level);
  if (!std::isfinite(p)) {
    range.text = where + ": no trend (it needs two runs with 0 < e < 1 at two velocities).";
    return range;
  }
  if (plastic_possible && above_yield) {
    range.slope = s;
    range.slope_of = "e";
    range.trend = restitution_trend;
    std::string laws_words;
    bool first = true;
    for (const auto& law : laws) {
      std::optional<PowerLawTrend> ignored;
      const double slope = slope_of(v, law.restitution, false, ignored, level);
      if (!std::isfinite(slope)) continue;
      range.plastic_low = first ? slope : std::min(range.plastic_low, slope);
      range.plastic_high = first ? slope : std::max(range.plastic_high, slope);
      first = false;
      laws_words += (laws_words.empty() ? "" : ", ") + law.law + " " + significant(slope, 3);
    }
    // Distance to the plastic band and to a constant e (slope 0).
    const double to_plastic = s < range.plastic_low
                                  ? range.plastic_low - s
                                  : (s > range.plastic_high ? s - range.plastic_high : 0.0);
    const bool plastic = to_plastic < std::abs(s);
    const std::string reference =
        laws_words.empty()
            ? "the plastic family (reference slope -1/4 far above V_y, Thornton 1997)"
            : "the plastic family (the plastic laws' own slopes over these "
              "velocities: " +
                  laws_words + "; -1/4 far above V_y)";
    range.family = plastic ? "plastic" : "constant restitution";
    range.text = where + ": " + slope_words("e", s, restitution_trend) + ": " +
                 (plastic ? reference + ", not a constant e (slope 0)"
                          : "nearer a constant e (slope 0) than " + reference) +
                 "; there " + slope_words("1 - e", p, loss_trend) + ".";
    return range;
  }
  range.slope = p;
  range.slope_of = "1 - e";
  range.trend = loss_trend;
  const ReferenceSlope* nearest = nullptr;
  for (const auto& reference : reference_slopes())
    if (!nearest || std::abs(reference.slope - p) < std::abs(nearest->slope - p))
      nearest = &reference;
  range.family = nearest->family;
  range.text = where + ": " + slope_words("1 - e", p, loss_trend) + ", nearest " + nearest->family +
               " (slope " + significant(nearest->slope, 3) + ")" +
               (plastic_possible ? ""
                                 : "; the plastic family does not apply (the FEM's "
                                   "material does not yield)") +
               ".";
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
  if (!below_v.empty())
    ranges.push_back(judge(below_v, below_e, false, plastic, yield_velocity, level, {}));
  if (!above_v.empty())
    ranges.push_back(judge(above_v, above_e, true, plastic, yield_velocity, level, above_laws));
  return ranges;
}

std::string family_ranges_text(const std::vector<FamilyRange>& ranges,
                               std::optional<double> yield_velocity) {
  if (ranges.empty()) return "";
  std::string text = "Which family the FEM follows";
  text += yield_velocity
              ? " (split at the yield velocity V_y = " + significant(*yield_velocity, 4) +
                    " m/s of the material, Johnson's p_y = 1.6 Y):"
              : ":";
  for (const auto& range : ranges) text += " " + range.text;
  return text;
}

} // namespace impact::postprocess
