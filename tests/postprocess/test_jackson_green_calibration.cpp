// The Jackson–Green elastic-plastic law as a comparison model of the calibration: a campaign
// made by the law (the library's Jackson–Green contact, integrated by the general impact ODE
// with its Hertzian unloading branch written here) at V/V_y = 3, 10, 30 is calibrated; the
// fit recovers c and the yield strength Y, the no-fit model from the recorded material is the
// truth itself, and the two are ranked first, out of sample, with their numbers of free
// parameters. Without the scenario's radius the fitted law is left out, not guessed.

#include "plastic_runs.hpp"

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/models/plastic_models.hpp"

#include <impact_reduced/impact_ode.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>
#include <impact_reduced/contact_formulas.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

using namespace impact::postprocess;
namespace reduced = impact::reduced;

// Steel ball R = 10 mm on a rigid flat: E = 2.1e11 Pa, nu = 0.3 (E* = E / (1 - nu^2)),
// Y = 1 GPa.
struct Truth {
  double mass = 0.1, radius = 0.01, youngs_modulus = 2.1e11, poisson_ratio = 0.3,
         yield_strength = 1e9;
  double contact_modulus() const { return youngs_modulus / (1 - poisson_ratio * poisson_ratio); }
  double stiffness() const { return 4.0 / 3.0 * contact_modulus() * std::sqrt(radius); }
  reduced::SphereFlatContact contact() const {
    return {radius, contact_modulus(), yield_strength, poisson_ratio};
  }
  double yield_velocity() const {
    return reduced::yield_velocity(reduced::yield_pressure(reduced::YieldCriterion::jackson_green,
                                                           yield_strength, poisson_ratio),
                                   contact_modulus(), radius, mass);
  }
};

// The law at V: Jackson–Green loading while the approach grows, then the Hertzian branch
// k_u (x - x_r)^(3/2) through (x_max, F_max) of the library's unloading rule; x_max from the
// energy (elastic_plastic_impact). Integrated by the general ODE at 1e-12.
FemRun jackson_green_run(const Truth& t, double velocity) {
  const reduced::JacksonGreenContact contact(t.contact());
  const double x_max = reduced::elastic_plastic_impact(t.mass, velocity, contact).approach_max;
  const reduced::HertzianUnloading unloading = contact.unloading(x_max);
  const reduced::ContactForceLaw law = [&contact, unloading](double x, double rate) {
    if (rate >= 0) return contact.loading_force(std::max(x, 0.0));
    return unloading.stiffness * std::pow(std::max(x - unloading.residual_approach, 0.0), 1.5);
  };
  FemRun run = impact::testing::plastic_law_run(t.mass, velocity, law);
  run.source = "jackson_green_v" + std::to_string(velocity);
  impact::testing::record_elastic_plastic_sphere(run, t.youngs_modulus, t.poisson_ratio,
                                                 t.yield_strength, t.radius);
  return run;
}

TEST(JacksonGreenCalibration, CampaignRecoversTheYieldStrengthAndRanksJacksonGreenFirst) {
  const Truth truth;
  const double v_y = truth.yield_velocity();
  std::vector<FemRun> runs;
  for (double ratio : {3.0, 10.0, 30.0}) runs.push_back(jackson_green_run(truth, ratio * v_y));

  CalibrationOptions options;
  options.laws = {"thornton", "jackson-green"};
  const Calibration calibration = calibrate(runs, options);
  ASSERT_TRUE(calibration.campaign.fitted) << calibration.campaign.reason;
  const CampaignModelFit* fitted = calibration.campaign.find("jackson-green");
  ASSERT_NE(fitted, nullptr);
  ASSERT_TRUE(fitted->fit.converged) << fitted->fit.solver_message;
  EXPECT_EQ(fitted->fit.free_parameters(), 2u);
  EXPECT_EQ(fitted->fit.exponent.value, 1.5);
  EXPECT_EQ(fitted->fit.parameter_name, "Y");
  const double c = fitted->fit.stiffness.value, y = fitted->fit.parameter.value;
  EXPECT_NEAR(c / truth.stiffness(), 1, 1e-5);
  EXPECT_NEAR(y / truth.yield_strength, 1, 1e-5);
  EXPECT_LT(fitted->fit.quality.rms_residual, 1e-5);

  // The no-fit model from the material is the truth: its restitution is the runs'.
  const auto reference =
      std::find_if(calibration.campaign.reference_models.begin(),
                   calibration.campaign.reference_models.end(), [](const ReferenceModel& model) {
                     return model.key == "jackson-green-material";
                   });
  ASSERT_NE(reference, calibration.campaign.reference_models.end());
  EXPECT_NEAR(reference->stiffness / truth.stiffness(), 1, 1e-12);
  EXPECT_NEAR(reference->dissipation.at(0) / truth.yield_strength, 1, 1e-12);
  EXPECT_NE(reference->basis.find("no hardening"), std::string::npos) << reference->basis;
  for (std::size_t i = 0; i < runs.size(); ++i)
    EXPECT_NEAR(reference->runs[i].prediction.restitution / runs[i].restitution, 1, 1e-8) << i;

  const auto& ranking = calibration.campaign.ranking;
  ASSERT_GE(ranking.size(), 3u);
  const auto is_jackson_green = [](const RankedModel& model) {
    return model.key == "jackson-green" || model.key == "jackson-green-material";
  };
  EXPECT_TRUE(is_jackson_green(ranking[0])) << ranking[0].key;
  EXPECT_TRUE(is_jackson_green(ranking[1])) << ranking[1].key;
  EXPECT_TRUE(ranking[0].out_of_sample);
  EXPECT_EQ(ranking[0].free_parameters, ranking[0].key == "jackson-green" ? 2u : 0u);
  EXPECT_LT(ranking[1].score, 1e-4);
  // The other models (Hunt–Crossley, Thornton with the same material) are far behind.
  EXPECT_GT(ranking[2].score, 100 * ranking[1].score);
  std::printf(
      "Jackson-Green campaign: c recovered to %.1e, Y to %.1e; ranking %s %.2e, %s %.2e, "
      "next %s %.2e\n",
      c / truth.stiffness() - 1, y / truth.yield_strength - 1, ranking[0].key.c_str(),
      ranking[0].score, ranking[1].key.c_str(), ranking[1].score, ranking[2].key.c_str(),
      ranking[2].score);
}

TEST(JacksonGreenCalibration, TheModelPredictsTheLibrarysImpactAndInvertsTheRestitution) {
  const Truth truth;
  const ContactModel model = jackson_green_model(truth.radius, truth.poisson_ratio);
  ASSERT_TRUE(model.plastic_contact);
  const reduced::JacksonGreenContact contact(truth.contact());
  for (double ratio : {3.0, 10.0, 100.0}) {
    const double velocity = ratio * truth.yield_velocity();
    const auto exact = reduced::elastic_plastic_impact(truth.mass, velocity, contact);
    const auto prediction =
        predict_impact(model, truth.mass, velocity, truth.stiffness(), 1.5, {truth.yield_strength});
    EXPECT_NEAR(prediction.restitution / exact.restitution, 1, 1e-12) << ratio;
    EXPECT_NEAR(prediction.contact_time / exact.contact_time, 1, 1e-12) << ratio;
    EXPECT_NEAR(prediction.force_max / exact.force_max, 1, 1e-12) << ratio;
    const double y = model.damping_for_restitution(exact.restitution, velocity,
                                                   {truth.mass, truth.stiffness(), 1.5});
    EXPECT_NEAR(y / truth.yield_strength, 1, 1e-6) << ratio;
  }
  EXPECT_THROW(jackson_green_model(0, 0.3), reduced::InvalidInput);
  EXPECT_THROW(jackson_green_model(0.01, 0.5), reduced::InvalidInput);
  // By name it needs the runs' scenario.
  EXPECT_THROW(plastic_model("jackson-green"), reduced::InvalidInput);
  EXPECT_FALSE(model_formula("jackson-green").empty());
}

TEST(JacksonGreenCalibration, LeftOutWhenTheRunsDoNotRecordTheScenario) {
  const Truth truth;
  FemRun run = jackson_green_run(truth, 5 * truth.yield_velocity());
  run.text_attributes.erase("Scenario/Sphere radius");
  std::vector<std::string> left_out;
  const auto models = comparison_models({"thornton", "jackson-green"}, {run}, left_out);
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(models.front().name, "thornton");
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_EQ(left_out.front(), "jackson-green");
  EXPECT_FALSE(material_jackson_green({run}));
  EXPECT_THROW(comparison_model("jackson-green", std::vector<FemRun>{run}), reduced::InvalidInput);
}

// A campaign whose materials cannot yield (Kelvin–Voigt sphere and plate): the plastic and
// damped plastic laws are left out, the viscoelastic ones kept.
TEST(JacksonGreenCalibration, PlasticLawsLeftOutWhenNoMaterialCanYield) {
  const Truth truth;
  FemRun run = jackson_green_run(truth, 5 * truth.yield_velocity());
  EXPECT_TRUE(runs_can_yield({run}));
  run.text_attributes["Sphere/Material model"] = "kelvin-voigt";
  run.text_attributes["Plate/Material model"] = "kelvin-voigt";
  EXPECT_FALSE(runs_can_yield({run}));
  std::vector<std::string> left_out;
  const auto models = comparison_models({"kuwabara-kono", "thornton", "jackson-green",
                                         "hunt-crossley-jackson-green"},
                                        {run}, left_out);
  ASSERT_EQ(models.size(), 1u);
  EXPECT_EQ(models.front().name, "kuwabara-kono");
  EXPECT_EQ(left_out,
            (std::vector<std::string>{"thornton", "jackson-green", "hunt-crossley-jackson-green"}));
}

} // namespace
