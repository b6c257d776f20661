// Thornton's elastic-plastic law as a comparison model of the calibration: a campaign made by
// Thornton's law (written again here, integrated by the library's general impact ODE with the
// maximum approach known from the energy) at V/V_y = 2, 5, 20 is calibrated with the plastic
// model among others; the fit recovers c and the yield approach, hence p_y with the sphere
// radius, and Thornton (fitted, or from the material's yield strength with nothing fitted) is
// ranked first, out of sample, with its number of free parameters.

#include "plastic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/models/plastic_models.hpp"

#include <impact_reduced/impact_ode.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/thornton.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace impact::postprocess;
namespace reduced = impact::reduced;

using impact::testing::thornton_run;
using impact::testing::Truth;

TEST(PlasticCalibration, ThorntonCampaignRecoversTheYieldPressureAndRanksThorntonFirst) {
  const Truth truth;
  const double v_y = thornton_yield_velocity(truth.yield_approach(), truth.mass, truth.stiffness());
  EXPECT_NEAR(v_y,
              reduced::ThorntonImpact({truth.mass, truth.radius, truth.contact_modulus,
                                       truth.yield_pressure},
                                      1.0)
                  .yield_velocity(),
              1e-12 * v_y);
  std::vector<FemRun> runs;
  for (double ratio : {2.0, 5.0, 20.0}) runs.push_back(thornton_run(truth, ratio * v_y));
  // The truth's restitution is Thornton's closed form (the run generator is right).
  EXPECT_NEAR(runs[1].restitution, reduced::thornton_restitution_formula(0.2), 1e-9);

  CalibrationOptions options;
  options.laws = {"kuwabara-kono", "thornton"};
  const Calibration calibration = calibrate(runs, options);
  ASSERT_TRUE(calibration.campaign.fitted) << calibration.campaign.reason;
  const CampaignModelFit* thornton = calibration.campaign.find("thornton");
  ASSERT_NE(thornton, nullptr);
  ASSERT_TRUE(thornton->fit.converged) << thornton->fit.solver_message;
  EXPECT_EQ(thornton->fit.free_parameters(), 2u);
  EXPECT_EQ(thornton->fit.exponent.value, 1.5);
  const double c = thornton->fit.stiffness.value, x_y = thornton->fit.parameter.value;
  EXPECT_NEAR(c / truth.stiffness(), 1, 1e-6);
  EXPECT_NEAR(x_y / truth.yield_approach(), 1, 1e-6);
  EXPECT_NEAR(thornton_yield_pressure(c, x_y, truth.radius) / truth.yield_pressure, 1, 1e-6);
  EXPECT_LT(thornton->fit.quality.rms_residual, 1e-6);

  // The no-fit model from the material is the truth itself.
  const auto reference =
      std::find_if(calibration.campaign.reference_models.begin(),
                   calibration.campaign.reference_models.end(),
                   [](const ReferenceModel& model) { return model.key == "thornton-material"; });
  ASSERT_NE(reference, calibration.campaign.reference_models.end());
  EXPECT_NEAR(reference->stiffness / truth.stiffness(), 1, 1e-12);
  EXPECT_NEAR(reference->dissipation.at(0) / truth.yield_approach(), 1, 1e-12);
  for (const auto& run : reference->runs)
    EXPECT_NEAR(run.prediction.restitution / runs[&run - &reference->runs[0]].restitution, 1, 1e-9);

  ASSERT_FALSE(calibration.campaign.ranking.empty());
  const RankedModel& first = calibration.campaign.ranking.front();
  // First: the fitted law or the no-fit one from the material (both the truth); then the rest,
  // far behind. Out of sample the held-out fits move the predictions by about 2e-5 (measured).
  EXPECT_TRUE(first.key == "thornton" || first.key == "thornton-material") << first.key;
  EXPECT_TRUE(first.out_of_sample);
  EXPECT_EQ(first.free_parameters, first.key == "thornton" ? 2u : 0u);
  ASSERT_GE(calibration.campaign.ranking.size(), 3u);
  const RankedModel& second = calibration.campaign.ranking[1];
  EXPECT_TRUE(second.key == "thornton" || second.key == "thornton-material") << second.key;
  EXPECT_LT(second.score, 1e-4);
  EXPECT_GT(calibration.campaign.ranking[2].score, 100 * second.score);
  std::printf("Thornton campaign: p_y recovered to %.1e; ranking %s %.2e, %s %.2e, next %s %.2e\n",
              thornton_yield_pressure(c, x_y, truth.radius) / truth.yield_pressure - 1,
              first.key.c_str(), first.score, second.key.c_str(), second.score,
              calibration.campaign.ranking[2].key.c_str(), calibration.campaign.ranking[2].score);
}

TEST(PlasticCalibration, TheModelPredictsThorntonsClosedForms) {
  const Truth truth;
  const ContactModel model = contact_model("thornton");
  ASSERT_TRUE(model.plastic_contact);
  const reduced::ThorntonParameters parameters{truth.mass, truth.radius, truth.contact_modulus,
                                               truth.yield_pressure};
  for (double velocity : {0.5, 2.0, 10.0}) {
    const auto exact = reduced::ThorntonImpact(parameters, velocity).response();
    const auto prediction = predict_impact(model, truth.mass, velocity, truth.stiffness(), 1.5,
                                           {truth.yield_approach()});
    EXPECT_NEAR(prediction.restitution / exact.restitution, 1, 1e-12) << velocity;
    EXPECT_NEAR(prediction.contact_time / exact.contact_time, 1, 1e-12) << velocity;
    EXPECT_NEAR(prediction.force_max / exact.force_max, 1, 1e-12) << velocity;
    // The starting-value map inverts the restitution.
    const double x_y = model.damping_for_restitution(exact.restitution, velocity,
                                                     {truth.mass, truth.stiffness(), 1.5});
    EXPECT_NEAR(x_y / truth.yield_approach(), 1, 1e-9) << velocity;
  }
  EXPECT_THROW(thornton_yield_pressure(1e10, 0, 0.01), reduced::InvalidInput);
}

} // namespace
