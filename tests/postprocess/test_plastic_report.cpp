// The report of an elastic-plastic campaign against that of the same runs with a material
// without plasticity. Runs made by Thornton's law (plastic_runs.hpp) at V/V_y = 0.6, 2, 5, 20,
// recording a von Mises stress above the yield strength from 2 V_y on:
//   - elastic-plastic material: the FEM is valid above yield, no velocity is flagged
//     "(yields)", no "no viscoelastic model is valid" sentence; the family ranges say
//     "elastic" below V_y and "plastic" above; the plastic laws (Thornton from the material is
//     the truth) and their three figures are there; the effective alpha is given per run;
//   - elastic material with a yield strength: the runs above yield are flagged and the
//     sentence is there, no plastic laws, no plastic figures, the plastic family does not apply.

#include "plastic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/models/family_ranges.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/report/report.hpp"
#include "impact_postprocess/report/verdict_words.hpp"

#include <impact_reduced/hunt_crossley.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace impact::postprocess;
using impact::testing::Truth;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::vector<double> ratios = {0.6, 2.0, 5.0, 20.0};

double yield_velocity() {
  const Truth truth;
  return thornton_yield_velocity(truth.yield_approach(), truth.mass, truth.stiffness());
}

// The runs; the stress the FEM records: 0.9 Y below V_y, 1.05 Y above.
std::vector<FemRun> plastic_runs() {
  const Truth truth;
  std::vector<FemRun> runs;
  for (double ratio : ratios) {
    FemRun run = impact::testing::thornton_run(truth, ratio * yield_velocity());
    const double y = truth.yield_pressure / 1.6;
    run.numeric_attributes["result: max_von_mises"] = (ratio > 1 ? 1.05 : 0.9) * y;
    runs.push_back(run);
  }
  return runs;
}

// The same runs with an elastic sphere that records the strength impact-fem checks against.
std::vector<FemRun> elastic_runs(std::vector<FemRun> runs) {
  for (auto& run : runs) {
    auto& text = run.text_attributes;
    text["Sphere/Material model"] = "elastic";
    text["Sphere/Elastic/Young's modulus"] = text["Sphere/Elastic-plastic/Young's modulus"];
    text["Sphere/Elastic/Poisson's ratio"] = text["Sphere/Elastic-plastic/Poisson's ratio"];
    text["Sphere/Yield strength"] = text["Sphere/Elastic-plastic/Yield strength"];
    for (const char* key :
         {"Sphere/Elastic-plastic/Young's modulus", "Sphere/Elastic-plastic/Poisson's ratio",
          "Sphere/Elastic-plastic/Yield strength"})
      text.erase(key);
  }
  return runs;
}

bool has_figure(const Report& report, FigureId id) {
  const auto figures = report_figures(report);
  return std::any_of(figures.begin(), figures.end(),
                     [&](const ReportFigure& figure) { return figure.id == id; });
}

struct Reports {
  Report plastic, elastic;
  std::vector<Problem> calibration_problems;
};

// One calibration (through its JSON, as impact-report reads it) for both reports.
const Reports& reports() {
  static const Reports made = [] {
    Campaign plastic{plastic_runs(), {}, {}};
    Campaign elastic{elastic_runs(plastic.runs), {}, {}};
    CalibrationOptions options;
    options.laws = {"thornton"};
    const Calibration calibration =
        calibration_from_json(to_json(calibrate(plastic.runs, options)));
    return Reports{build_report(plastic, calibration, {}, "plastic", "calibration.json"),
                   build_report(elastic, calibration, {}, "elastic", "calibration.json"),
                   calibration.problems};
  }();
  return made;
}

TEST(PlasticReport, AnElasticPlasticFemIsValidAboveYieldAndFollowsThePlasticFamily) {
  const Report& report = reports().plastic;
  // Every per-run fit converges, also the Hunt–Crossley fits of the elastic run (b = 0 at the
  // bound: forward differences there). (The campaign's b(V) fit without the fastest run may
  // not: these runs are not Hunt–Crossley's.)
  for (const auto& problem : reports().calibration_problems)
    if (problem.source.rfind("thornton_v", 0) == 0) {
      EXPECT_NE(problem.kind, ProblemKind::convergence)
          << problem.source << ": " << problem.message;
    }
  ASSERT_EQ(report.runs.size(), ratios.size());
  for (const auto& run : report.runs) {
    EXPECT_TRUE(run.record.plastic_material);
    EXPECT_FALSE(run.yields) << run.velocity;
    // The yield check reads the elastic-plastic material's strength.
    ASSERT_TRUE(run.record.yield_strength);
    EXPECT_EQ(*run.record.yield_strength, Truth().yield_pressure / 1.6);
  }
  EXPECT_TRUE(report.plasticity.plastic_material);
  EXPECT_FALSE(report.plasticity.first_yielding_velocity);
  EXPECT_TRUE(contains(plasticity_sentence(report), "stays valid above yield"))
      << plasticity_sentence(report);
  EXPECT_FALSE(contains(summary_sentence(report), "no viscoelastic model"))
      << summary_sentence(report);
  for (const auto& verdict : report.verdicts)
    for (const auto& band : verdict.tolerances)
      EXPECT_FALSE(contains(tolerance_sentence(report, band, ""), "exceeds the yield strength"))
          << tolerance_sentence(report, band, "");

  ASSERT_TRUE(report.plastic_laws);
  const PlasticLaws& laws = *report.plastic_laws;
  EXPECT_NEAR(laws.yield_velocity / yield_velocity(), 1, 1e-12);
  ASSERT_GE(laws.laws.size(), 3u); // Thornton and Jackson–Green from the material, Thornton fitted
  EXPECT_EQ(laws.laws[0].key, "thornton-material");
  EXPECT_EQ(laws.laws[1].key, "jackson-green-material");
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    // Thornton from the material is the truth.
    EXPECT_NEAR(laws.laws[0].run_restitution[i] / report.runs[i].fem.restitution, 1, 1e-8) << i;
    EXPECT_FALSE(laws.laws[0].loops[i].approach.empty());
    // Below V_y no dent, above it one.
    EXPECT_EQ(laws.laws[0].run_permanent_approach[i] > 0, ratios[i] > 1) << i;
    // The FEM's permanent approach: measured on the history at the end of contact.
    EXPECT_NEAR(laws.fem_permanent_approach[i], laws.laws[0].run_permanent_approach[i],
                1e-3 * laws.laws[0].run_permanent_approach.back())
        << i;
  }

  // Below V_y elastic, above it the plastic family (Thornton's local slope is -0.16 to -0.24).
  ASSERT_EQ(report.family_ranges.size(), 2u);
  EXPECT_EQ(report.family_ranges[0].family, "elastic");
  EXPECT_FALSE(report.family_ranges[0].above_yield);
  EXPECT_EQ(report.family_ranges[1].family, "plastic");
  EXPECT_TRUE(report.family_ranges[1].above_yield);
  EXPECT_EQ(report.family_ranges[1].runs, 3u);
  EXPECT_LT(report.family_ranges[1].slope, -0.1);
  EXPECT_GT(report.family_ranges[1].slope, -0.25);
  EXPECT_TRUE(contains(summary_sentence(report), "the plastic family")) << summary_sentence(report);
  std::printf("%s\n", family_sentence(report).c_str());

  // The campaign made by Thornton's law: its fit (the best comparison law) is valid
  // everywhere, within the tightest tolerance at every velocity, out of sample.
  const ReportModel* best = report.model(model_keys::best_law);
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->calibration_key, "thornton");
  const ModelVerdict* verdict = report.verdict(best->key);
  ASSERT_NE(verdict, nullptr);
  EXPECT_TRUE(verdict->out_of_sample);
  ASSERT_FALSE(verdict->tolerances.empty());
  for (const auto& band : verdict->tolerances)
    for (std::size_t i = 0; i < band.decisions.size(); ++i)
      EXPECT_EQ(band.decisions[i], Decision::within)
          << "tolerance " << band.tolerance << ", V = " << report.runs[i].velocity << ": "
          << tolerance_sentence(report, band, "");
  // Jackson–Green–Marghitu's restitution fit is drawn beside the laws: e only, no loops.
  const auto jgm = std::find_if(laws.laws.begin(), laws.laws.end(), [](const PlasticLawCurve& law) {
    return law.key == model_keys::jackson_green_marghitu_material;
  });
  ASSERT_NE(jgm, laws.laws.end());
  EXPECT_FALSE(jgm->fitted);
  EXPECT_EQ(jgm->run_restitution.size(), report.runs.size());
  EXPECT_TRUE(jgm->loops.empty() && jgm->permanent_approach.empty());
  EXPECT_EQ(jgm->run_restitution.front(), 1.0); // below V_y (and V_c)
  EXPECT_LT(jgm->run_restitution.back(), 1.0);

  // The effective alpha against the measured range.
  ASSERT_TRUE(report.effective_alpha);
  EXPECT_EQ(report.effective_alpha->count, report.runs.size());
  EXPECT_TRUE(contains(alpha_sentence(report), "0.08–0.32 s/m")) << alpha_sentence(report);
  EXPECT_TRUE(has_figure(report, FigureId::plastic_restitution));
  EXPECT_TRUE(has_figure(report, FigureId::permanent_approach));
  EXPECT_TRUE(has_figure(report, FigureId::plastic_loops));
}

TEST(PlasticReport, WithoutPlasticityTheRunsAboveYieldAreFlagged) {
  const Report& report = reports().elastic;
  ASSERT_EQ(report.runs.size(), ratios.size());
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    EXPECT_FALSE(report.runs[i].record.plastic_material);
    EXPECT_EQ(report.runs[i].yields, ratios[i] > 1) << report.runs[i].velocity;
  }
  EXPECT_FALSE(report.plasticity.plastic_material);
  ASSERT_TRUE(report.plasticity.first_yielding_velocity);
  EXPECT_NEAR(*report.plasticity.first_yielding_velocity, 2 * yield_velocity(), 1e-12);
  EXPECT_TRUE(contains(summary_sentence(report), "no viscoelastic model"))
      << summary_sentence(report);
  EXPECT_FALSE(report.plastic_laws);
  EXPECT_FALSE(has_figure(report, FigureId::plastic_restitution));
  ASSERT_EQ(report.family_ranges.size(), 1u);
  EXPECT_FALSE(report.family_ranges[0].plastic_possible);
  EXPECT_TRUE(contains(family_sentence(report), "does not apply")) << family_sentence(report);
}

TEST(FamilyRanges, AViscoelasticCampaignWithoutYieldVelocityIsOneRange) {
  std::vector<double> velocity, restitution;
  for (double v : {0.5, 1.0, 2.0, 5.0}) {
    velocity.push_back(v);
    restitution.push_back(
        impact::reduced::HuntCrossleyImpact(0.1, 1e10, 1.5, 0.05, v).response().restitution);
  }
  const auto ranges = family_ranges(velocity, restitution, std::nullopt);
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0].family, reference_slopes()[0].family); // Hunt–Crossley, slope 1
  EXPECT_EQ(ranges[0].slope_of, "1 - e");
  EXPECT_NEAR(ranges[0].slope, 1, 0.1);
  EXPECT_EQ(ranges[0].low, 0.5);
  EXPECT_EQ(ranges[0].high, 5.0);
  // Split at a yield velocity: two runs on each side, slopes through two points.
  const auto split = family_ranges(velocity, restitution, 1.5);
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0].runs, 2u);
  EXPECT_FALSE(split[0].trend);
  // Through two points: a slope without an interval ("two runs: no interval" on the page).
  EXPECT_EQ(split[0].basis, FamilyBasis::nearest);
  EXPECT_TRUE(std::isfinite(split[0].loss_slope));
  EXPECT_FALSE(split[0].loss_trend);
  EXPECT_EQ(split[1].slope_of, "e");
  EXPECT_TRUE(family_ranges({}, {}, std::nullopt).empty());
}

} // namespace
