// The ranking of calibration.hpp: every campaign and reference model scored by its RMS
// relative error in the verdict's quantities, out of sample where it can be, and ordered
// (ranking_score, rank, rank_campaign).

#include "ranking.hpp"

#include "impact_postprocess/models/contact_models.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A model's ranking entry from its per-run predictions.
RankedModel ranked(const std::string& key, const std::vector<RunResidual>& residuals,
                   const std::vector<RunCalibration>& runs, std::size_t free_parameters,
                   double rms_residual, bool converged) {
  std::vector<ImpactFigures> in_sample, out_of_sample, measured;
  bool all_out_of_sample = true;
  for (const auto& residual : residuals) {
    const auto run = std::find_if(runs.begin(), runs.end(), [&](const RunCalibration& r) {
      return r.source == residual.source;
    });
    if (run == runs.end()) continue;
    measured.push_back(run->measured);
    in_sample.push_back(residual.prediction);
    if (residual.out_of_sample)
      out_of_sample.push_back(*residual.out_of_sample);
    else
      all_out_of_sample = false;
  }
  all_out_of_sample = all_out_of_sample && !out_of_sample.empty();
  const RankingScore inside = ranking_score(in_sample, measured);
  const RankingScore outside = all_out_of_sample ? ranking_score(out_of_sample, measured) : inside;
  return {key,          free_parameters, outside.rms, all_out_of_sample, outside.worst, inside.rms,
          rms_residual, converged,       {}};
}

} // namespace

namespace detail {

std::vector<RankedModel> rank_campaign(const CampaignCalibration& campaign,
                                       const std::vector<RunCalibration>& runs) {
  std::vector<RankedModel> ranking;
  std::optional<std::size_t> family;
  const auto& maps = restitution_parametrised_laws();
  for (const CampaignModelFit* model : campaign.models()) {
    const bool in_family = std::find(maps.begin(), maps.end(), model->key) != maps.end();
    if (in_family && family) {
      ranking[*family].family.push_back(model->key);
      continue;
    }
    ranking.push_back(ranked(model->key, model->runs, runs, model->fit.free_parameters(),
                             model->fit.quality.rms_residual, model->fit.converged));
    if (in_family) {
      ranking.back().family = {model->key};
      family = ranking.size() - 1;
    }
  }
  for (const auto& reference : campaign.reference_models) {
    FitQuality quality{0, 0, 0};
    std::vector<FitQuality> parts;
    for (const auto& run : reference.runs) parts.push_back(run.quality);
    if (!parts.empty()) quality = combine(parts);
    ranking.push_back(ranked(reference.key, reference.runs, runs, 0, quality.rms_residual, true));
  }
  rank(ranking);
  return ranking;
}

} // namespace detail

RankingScore ranking_score(const std::vector<ImpactFigures>& predicted,
                           const std::vector<ImpactFigures>& measured) {
  double squares = 0, worst = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < predicted.size() && i < measured.size(); ++i)
    for (Quantity quantity : verdict_quantities) {
      const double error = relative_error(predicted[i], measured[i], quantity);
      if (!std::isfinite(error)) continue;
      squares += error * error;
      worst = std::max(worst, std::abs(error));
      ++count;
    }
  if (count == 0) return {nan, nan};
  return {std::sqrt(squares / double(count)), worst};
}

void rank(std::vector<RankedModel>& models, double tie) {
  std::vector<std::pair<std::size_t, RankedModel>> indexed;
  for (std::size_t i = 0; i < models.size(); ++i) indexed.emplace_back(i, models[i]);
  // A fitted model scored in sample (fewer than three velocities, or a held-out fit missing)
  // is judged on the runs it was fitted to: it ranks after every model scored out of sample
  // (the models that fit nothing always are), whatever its score.
  const auto in_sample_fit = [](const RankedModel& model) {
    return !model.out_of_sample && model.free_parameters > 0;
  };
  std::stable_sort(indexed.begin(), indexed.end(), [&](const auto& a, const auto& b) {
    if (in_sample_fit(a.second) != in_sample_fit(b.second)) return in_sample_fit(b.second);
    if (std::isnan(a.second.score)) return false;
    if (std::isnan(b.second.score)) return true;
    return a.second.score < b.second.score;
  });
  // Groups of scores within `tie` of the group's best (and scored alike): fewer free
  // parameters first, then the given order.
  for (std::size_t begin = 0; begin < indexed.size();) {
    std::size_t end = begin + 1;
    while (end < indexed.size() && std::isfinite(indexed[begin].second.score) &&
           in_sample_fit(indexed[end].second) == in_sample_fit(indexed[begin].second) &&
           indexed[end].second.score - indexed[begin].second.score <= tie)
      ++end;
    std::sort(indexed.begin() + std::ptrdiff_t(begin), indexed.begin() + std::ptrdiff_t(end),
              [](const auto& a, const auto& b) {
                if (a.second.free_parameters != b.second.free_parameters)
                  return a.second.free_parameters < b.second.free_parameters;
                return a.first < b.first;
              });
    begin = end;
  }
  for (std::size_t i = 0; i < models.size(); ++i) models[i] = indexed[i].second;
}

} // namespace impact::postprocess
