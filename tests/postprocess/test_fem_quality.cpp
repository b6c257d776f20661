// The FEM's own quality as the report judges it: the step-to-step oscillation and the force
// after release on histories with known answers (the definitions of impact-fem's summary keys),
// the velocity trend 1 - e ~ V^p, and the numerical uncertainty of each quantity from a
// verification.json or, without one, from the history.

#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_record.hpp"
#include "impact_postprocess/run/force_smoothness.hpp"
#include "impact_postprocess/models/velocity_trend.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace {

using namespace impact::postprocess;
namespace fs = std::filesystem;
constexpr double pi = 3.14159265358979323846;

// A half-sine contact of `steps` steps between zero-force steps.
std::vector<double> half_sine(std::size_t steps, double peak = 1000) {
  std::vector<double> force(5, 0.0);
  for (std::size_t i = 1; i < steps; ++i)
    force.push_back(peak * std::sin(pi * double(i) / double(steps)));
  for (int i = 0; i < 20; ++i) force.push_back(0.0);
  return force;
}

TEST(ForceSmoothness, SmoothHistoryHasTheCurvatureOnly) {
  const auto smoothness = force_smoothness(half_sine(300));
  // |F''| dt^2 / 2 = (pi / 300)^2 / 2 of the peak.
  EXPECT_NEAR(smoothness.oscillation, std::pow(pi / 300, 2) / 2, 1e-7);
  EXPECT_EQ(smoothness.after_release, 0.0);
}

TEST(ForceSmoothness, AlternatingForceGivesTwiceItsAmplitude) {
  auto force = half_sine(300);
  for (std::size_t i = 0; i < force.size(); ++i)
    force[i] += force[i] > 0 ? (i % 2 ? -15.0 : 15.0) : 0;
  const auto smoothness = force_smoothness(force);
  // 2 x 15 N plus the curvature, of a peak of 1000 N +- 15 N.
  EXPECT_NEAR(smoothness.oscillation, 30.0 / 1015, 2e-4);
}

TEST(ForceSmoothness, FiveStepsAtEachEndAreExcluded) {
  auto force = half_sine(300);
  force[5 + 3] += 200; // a spike among the first five steps of the contact
  EXPECT_NEAR(force_smoothness(force).oscillation, std::pow(pi / 300, 2) / 2, 1e-7);
  force[5 + 20] += 200; // inside
  EXPECT_NEAR(force_smoothness(force).oscillation, 200.0 / 1000, 1e-3);
}

TEST(ForceSmoothness, ReleaseChatterIsMeasured) {
  auto force = half_sine(300);
  const std::size_t release = 5 + 299; // the first zero after the peak
  force[release + 2] = 12.0;
  force[release + 6] = 40.0;
  std::vector<double> time;
  for (std::size_t i = 0; i < force.size(); ++i) time.push_back(1e-7 * double(i));
  const auto smoothness = force_smoothness(force);
  EXPECT_NEAR(smoothness.after_release, 0.04, 1e-12);
  EXPECT_NEAR(release_span(time, force), 6e-7, 1e-15);
  EXPECT_EQ(release_span(time, half_sine(300)), 0.0);
}

TEST(ForceSmoothness, TooShortContactHasNoOscillation) {
  EXPECT_TRUE(std::isnan(force_smoothness(half_sine(12)).oscillation));
  EXPECT_TRUE(std::isnan(force_smoothness(std::vector<double>(10, 0.0)).after_release));
}

TEST(VelocityTrend, PowerLawIsRecoveredWithItsInterval) {
  const std::vector<double> velocity = {0.5, 1, 2, 3, 4, 5};
  std::vector<double> restitution;
  for (double v : velocity) restitution.push_back(1 - 0.06 * std::pow(v, 0.2));
  const auto trend = fit_restitution_trend(velocity, restitution);
  ASSERT_TRUE(trend);
  EXPECT_NEAR(trend->exponent, 0.2, 1e-12);
  EXPECT_NEAR(trend->prefactor, 0.06, 1e-12);
  EXPECT_LT(trend->standard_error, 1e-12);
  EXPECT_EQ(trend->points, 6u);
  EXPECT_EQ(nearest_reference(*trend).family.find("Kuwabara–Kono"), 0u)
      << nearest_reference(*trend).family;
  // Scatter of 1 % in 1 - e: the 95 % interval (t with 4 degrees of freedom) holds 0.2.
  std::vector<double> noisy = restitution;
  const double scatter[] = {0.01, -0.01, 0.005, -0.008, 0.01, -0.004};
  for (std::size_t i = 0; i < noisy.size(); ++i) noisy[i] = 1 - (1 - noisy[i]) * (1 + scatter[i]);
  const auto wide = fit_restitution_trend(velocity, noisy);
  ASSERT_TRUE(wide);
  EXPECT_LT(wide->lower, 0.2);
  EXPECT_GT(wide->upper, 0.2);
  EXPECT_GT(wide->standard_error, 0);
  // Hunt–Crossley-like and constant-e data are told apart.
  std::vector<double> linear, constant;
  for (double v : velocity) {
    linear.push_back(1 - 0.02 * v);
    constant.push_back(0.9 + 1e-4 * std::sin(v));
  }
  EXPECT_EQ(
      nearest_reference(*fit_restitution_trend(velocity, linear)).family.find("Hunt–Crossley"), 0u);
  EXPECT_EQ(nearest_reference(*fit_restitution_trend(velocity, constant))
                .family.find("constant restitution"),
            0u);
  // Fewer than three usable runs, or a single velocity: no trend.
  EXPECT_FALSE(fit_restitution_trend({1, 2}, {0.9, 0.8}));
  EXPECT_FALSE(fit_restitution_trend({1, 1, 1}, {0.9, 0.91, 0.92}));
  EXPECT_FALSE(fit_restitution_trend({1, 2, 3}, {0.9, 1.0, 0.8}));
}

class FemRunRecordTest : public ::testing::Test {
protected:
  void SetUp() override {
    directory = impact::testing::scratch_directory(
        std::string("record_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(directory); }
  FemRun written(const FemRun& run, const nlohmann::json& extra = {}) {
    const fs::path file = write_fem_run(run, directory / "run");
    if (!extra.is_null()) {
      nlohmann::json summary;
      std::ifstream(directory / "run" / "summary.json") >> summary;
      summary.update(extra);
      std::ofstream(directory / "run" / "summary.json") << summary.dump(2);
    }
    return read_fem_run(file);
  }
  fs::path directory;
};

// Without verification: F_max from the oscillation, t_c from one step, the rest not known.
TEST_F(FemRunRecordTest, UncertaintyWithoutVerificationComesFromTheHistory) {
  const FemRun run = written(impact::testing::synthetic_run({}, 1.0));
  const FemRunRecord record = read_fem_run_record(run);
  EXPECT_EQ(record.smoothness_source, "measured on the force history");
  EXPECT_FALSE(record.verification);
  const double step = run.contact_time / 300;
  EXPECT_NEAR(record.time_step, step, 1e-9 * step);
  const ImpactFigures fem{run.restitution, run.contact_time, run.force_max, run.time_force_max,
                          run.approach_max};
  const FemUncertainty u = fem_uncertainty(record, fem);
  EXPECT_NEAR(u[std::size_t(Quantity::contact_time)].relative, 1.0 / 300, 1e-9);
  EXPECT_EQ(u[std::size_t(Quantity::force_max)].relative, record.smoothness.oscillation);
  for (Quantity quantity : {Quantity::energy_loss, Quantity::restitution, Quantity::approach_max})
    EXPECT_TRUE(std::isnan(u[std::size_t(quantity)].relative)) << quantity_key(quantity);
}

// The summary's own measures and the FEM's yield keys are used when present.
TEST_F(FemRunRecordTest, SummaryKeysOfTheFemAreRead) {
  const FemRun run =
      written(impact::testing::synthetic_run({}, 1.0), {{"force_oscillation", 0.077},
                                                        {"force_after_release", 0.012},
                                                        {"von_mises_max_sphere", 2.1e9},
                                                        {"von_mises_max_plate", 2.14e9},
                                                        {"yield_strength_sphere", 2.03e9},
                                                        {"yield_strength_plate", 2.03e9},
                                                        {"yield_exceeded", true},
                                                        {"yield_time_sphere", 4.9e-5}});
  const FemRunRecord record = read_fem_run_record(run);
  EXPECT_EQ(record.smoothness_source, "summary.json");
  EXPECT_EQ(record.smoothness.oscillation, 0.077);
  EXPECT_EQ(record.smoothness.after_release, 0.012);
  EXPECT_EQ(record.max_von_mises, 2.14e9);
  EXPECT_EQ(record.yield_strength, 2.03e9); // not the yield time
  EXPECT_EQ(record.yields, true);
}

// A verification: its GCIs are the uncertainty; the restitution's absolute GCI gives 1 - e^2's.
TEST_F(FemRunRecordTest, VerificationGivesTheUncertainty) {
  const FemRun made = impact::testing::synthetic_run({}, 1.0);
  written(made);
  const auto quantity = impact::testing::verification_quantity;
  const double e = made.restitution;
  std::ofstream(directory / "run" / "verification.json")
      << impact::testing::verification_json(
             {{"contact_time", quantity(made.contact_time, 0.002, 2e-7)},
              {"force_max", quantity(made.force_max, 0.004, 14.0)},
              {"time_force_max", quantity(made.time_force_max, 0.003, 1.5e-7)},
              {"approach_max", quantity(made.approach_max, 0.001, 3e-8)},
              {"restitution", quantity(e, nullptr, 0.001)}})
             .dump(2);
  const FemRun run = read_fem_run(directory / "run");
  const FemRunRecord record = read_fem_run_record(run);
  ASSERT_TRUE(record.verification) << record.verification_problem;
  EXPECT_EQ(record.verification->refinement_ratio, 1.5);
  const ImpactFigures fem{e, run.contact_time, run.force_max, run.time_force_max, run.approach_max};
  const FemUncertainty u = fem_uncertainty(record, fem);
  EXPECT_EQ(u[std::size_t(Quantity::contact_time)].relative, 0.002);
  EXPECT_EQ(u[std::size_t(Quantity::force_max)].relative, 0.004);
  EXPECT_EQ(u[std::size_t(Quantity::approach_max)].relative, 0.001);
  EXPECT_NEAR(u[std::size_t(Quantity::restitution)].relative, 0.001 / e, 1e-15);
  EXPECT_NEAR(u[std::size_t(Quantity::energy_loss)].relative, 2 * e * 0.001 / (1 - e * e), 1e-14);
  EXPECT_TRUE(u[std::size_t(Quantity::force_max)].source.find("GCI") != std::string::npos);

  // A file that is not a verification is named, not used.
  std::ofstream(directory / "run" / "verification.json") << R"({"format": "something else"})";
  const FemRunRecord broken = read_fem_run_record(read_fem_run(directory / "run"));
  EXPECT_FALSE(broken.verification);
  EXPECT_TRUE(broken.verification_problem.find("verification.json") != std::string::npos)
      << broken.verification_problem;
}

} // namespace
