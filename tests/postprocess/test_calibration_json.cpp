// The calibration JSON read back through the typed structures: what to_json writes,
// calibration_from_json returns (every number the report uses), and a file of another format
// or version, or with a key missing, is an error that names the key.

#include "synthetic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/calibration/calibration_json.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace impact::postprocess;
using json = nlohmann::json;

void expect_same(double read, double written, const char* what) {
  if (std::isnan(written))
    EXPECT_TRUE(std::isnan(read)) << what;
  else
    EXPECT_EQ(read, written) << what;
}

void expect_same_fit(const ModelFit& read, const ModelFit& written) {
  EXPECT_EQ(read.model, written.model);
  EXPECT_EQ(read.parameter_names(), written.parameter_names());
  const auto a = read.parameter_values(), b = written.parameter_values();
  for (std::size_t i = 0; i < a.size(); ++i) expect_same(a[i], b[i], "parameter");
  expect_same(read.parameter.standard_error, written.parameter.standard_error, "standard error");
  expect_same(read.parameter.lower, written.parameter.lower, "lower");
  ASSERT_EQ(read.covariance.size(), written.covariance.size());
  for (std::size_t i = 0; i < a.size() * a.size(); ++i)
    expect_same(read.covariance[i], written.covariance[i], "covariance");
  EXPECT_EQ(read.exponent_fixed, written.exponent_fixed);
  EXPECT_EQ(read.converged, written.converged);
  EXPECT_EQ(read.quality.samples, written.quality.samples);
}

Calibration small_calibration() {
  std::vector<FemRun> runs;
  for (double v : {0.5, 1.0, 2.0}) runs.push_back(impact::testing::synthetic_run({}, v));
  CalibrationOptions options;
  options.laws = {"flores"};
  return calibrate(runs, options);
}

TEST(CalibrationJson, ReadsBackWhatItWrites) {
  const Calibration written = small_calibration();
  const Calibration read = calibration_from_json(to_json(written));
  EXPECT_EQ(read.confidence_level, written.confidence_level);
  ASSERT_EQ(read.runs.size(), written.runs.size());
  for (std::size_t i = 0; i < read.runs.size(); ++i) {
    EXPECT_EQ(read.runs[i].measured.restitution, written.runs[i].measured.restitution);
    EXPECT_EQ(read.runs[i].damping_from_restitution, written.runs[i].damping_from_restitution);
    ASSERT_TRUE(read.runs[i].history);
    expect_same_fit(*read.runs[i].history, *written.runs[i].history);
  }
  const auto& a = read.campaign;
  const auto& b = written.campaign;
  ASSERT_EQ(a.models().size(), b.models().size());
  for (std::size_t m = 0; m < a.models().size(); ++m) {
    const CampaignModelFit& x = *a.models()[m];
    const CampaignModelFit& y = *b.models()[m];
    SCOPED_TRACE(y.key);
    EXPECT_EQ(x.key, y.key);
    expect_same_fit(x.fit, y.fit);
    EXPECT_EQ(x.energy_weight, y.energy_weight);
    ASSERT_EQ(x.held_out.size(), 3u);
    ASSERT_EQ(x.held_out.size(), y.held_out.size());
    for (std::size_t i = 0; i < x.held_out.size(); ++i)
      EXPECT_EQ(x.held_out[i].parameters, y.held_out[i].parameters);
    ASSERT_EQ(x.jackknife.size(), y.jackknife.size());
    for (std::size_t i = 0; i < x.jackknife.size(); ++i)
      expect_same(x.jackknife[i].standard_error, y.jackknife[i].standard_error, "jackknife");
    ASSERT_EQ(x.runs.size(), y.runs.size());
    for (std::size_t i = 0; i < x.runs.size(); ++i) {
      EXPECT_EQ(x.runs[i].prediction.force_max, y.runs[i].prediction.force_max);
      ASSERT_TRUE(x.runs[i].out_of_sample);
      EXPECT_EQ(x.runs[i].out_of_sample->restitution, y.runs[i].out_of_sample->restitution);
    }
  }
  // b(V) carries its fourth parameter q.
  ASSERT_TRUE(a.hunt_crossley_velocity_damping);
  EXPECT_EQ(a.hunt_crossley_velocity_damping->fit.parameter_names(),
            (std::vector<std::string>{"c", "n", "b_1", "q"}));
  ASSERT_EQ(a.reference_models.size(), b.reference_models.size());
  for (std::size_t i = 0; i < a.reference_models.size(); ++i) {
    EXPECT_EQ(a.reference_models[i].key, b.reference_models[i].key);
    EXPECT_EQ(a.reference_models[i].dissipation, b.reference_models[i].dissipation);
  }
  EXPECT_EQ(a.published_damping, 0.1);
  ASSERT_EQ(a.ranking.size(), b.ranking.size());
  for (std::size_t i = 0; i < a.ranking.size(); ++i) {
    EXPECT_EQ(a.ranking[i].key, b.ranking[i].key);
    expect_same(a.ranking[i].score, b.ranking[i].score, "score");
  }
  EXPECT_EQ(a.restitution_maps.size(), 5u);
}

TEST(CalibrationJson, ErrorsNameTheKey) {
  const json good = to_json(small_calibration());
  const auto message = [](const json& document) {
    try {
      calibration_from_json(document);
    } catch (const CalibrationFormatError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  json other = good;
  other["format"] = "something";
  EXPECT_NE(message(other).find("not a calibration of impact-calibrate"), std::string::npos);
  json old = good;
  old["format_version"] = 1;
  EXPECT_NE(message(old).find("run impact-calibrate again"), std::string::npos) << message(old);
  json missing = good;
  missing["campaign"]["hunt_crossley"]["parameters"].erase("b");
  EXPECT_NE(message(missing).find("campaign.hunt_crossley.parameters.b is missing"),
            std::string::npos)
      << message(missing);
  json wrong = good;
  wrong["runs"][1]["mass"] = "heavy";
  EXPECT_NE(message(wrong).find("runs[1].mass is not a number"), std::string::npos)
      << message(wrong);
}

} // namespace
