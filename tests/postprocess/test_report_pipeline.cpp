// The report pipeline (write_report) called as a library, without a child process: the
// figure drawer is the test's own, which records what it was asked to draw and writes a PNG
// signature for each figure. Checks: a campaign calibrated here gives a complete report
// (exit code 0), calibration.json written beside it, every declared figure handed to the
// drawer and shown on the page; a figure the drawer does not write is a figures problem
// (exit code 4, report incomplete); no usable run writes nothing (exit code 2); the page
// opens with the verdict in three lines, the errors figure and the recommended model's
// parameters (those of the calibration's first-ranked model), and every section after that
// first screen can be folded.

#include "impact_postprocess/calibration/calibrate_run_set.hpp"
#include "impact_postprocess/report/pipeline.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include "report_cli_testing.hpp"
#include "synthetic_runs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace {

namespace fs = std::filesystem;
using namespace impact::postprocess;
using impact::testing::contains;
using impact::testing::read_text;

using impact::testing::campaign_run;

struct RecordingDrawer {
  std::set<std::string> asked;    ///< figure files the report declared
  std::set<std::string> left_out; ///< not written (to test the problem it makes)
  FigureDrawer drawer() {
    return [this](const Report& report, const fs::path&, const fs::path& figures) {
      std::vector<Problem> problems;
      fs::create_directories(figures);
      for (const auto& figure : report_figures(report)) {
        asked.insert(figure.file);
        if (left_out.count(figure.file)) {
          problems.push_back(
              {(figures / figure.file).string(), ProblemKind::figures, "the figure was not drawn"});
          continue;
        }
        std::ofstream(figures / figure.file, std::ios::binary) << "\x89PNG\r\n\x1a\n";
      }
      return problems;
    };
  }
};

class ReportPipeline : public ::testing::Test {
protected:
  void SetUp() override {
    directory = impact::testing::scratch_directory("report_pipeline");
    for (double v : {0.5, 1.0, 2.0})
      write_fem_run(campaign_run(v), directory / "campaign" / ("v" + std::to_string(v)));
    request.campaign = directory / "campaign";
    request.output = directory / "report";
    request.draw_figures = drawer.drawer();
  }
  void TearDown() override { fs::remove_all(directory); }

  fs::path directory;
  RecordingDrawer drawer;
  ReportRequest request;
};

TEST_F(ReportPipeline, CalibratesDrawsAndWritesTheCompletePage) {
  const ReportOutcome outcome = write_report(request);
  EXPECT_TRUE(outcome.written);
  EXPECT_EQ(outcome.exit_code, 0);
  for (const auto& problem : outcome.report.problems)
    EXPECT_TRUE(is_warning(problem.kind)) << problem.message;
  EXPECT_EQ(outcome.report.runs.size(), 3u);
  EXPECT_TRUE(outcome.report.verdict_available);
  EXPECT_TRUE(fs::exists(request.output / "calibration.json"));
  EXPECT_TRUE(contains(outcome.report.calibration_source, "calibrated by impact-report"));
  const std::string markdown = read_text(outcome.markdown);
  EXPECT_TRUE(fs::exists(outcome.html));
  ASSERT_FALSE(drawer.asked.empty());
  for (const auto& file : drawer.asked)
    EXPECT_TRUE(contains(markdown, "figures/" + file)) << file << " is not on the page";
}

TEST_F(ReportPipeline, OpensWithTheVerdictTheErrorsFigureAndTheRecommendedModel) {
  const ReportOutcome outcome = write_report(request);
  ASSERT_EQ(outcome.exit_code, 0);
  const Report& report = outcome.report;
  ASSERT_TRUE(report.calibration && !report.calibration->campaign.ranking.empty());
  const std::string markdown = read_text(outcome.markdown);
  // The first screen, before the first section: three lines, the figure, the parameters of
  // the law recommended where it holds (else of the closest, headed so).
  ASSERT_TRUE(report.recommendation);
  const LawRecommendation& recommendation = *report.recommendation;
  const auto chosen =
      recommendation.recommended ? recommendation.recommended : recommendation.closest;
  ASSERT_TRUE(chosen);
  const JudgedLaw& best = recommendation.laws[*chosen];
  const std::size_t first_section = markdown.find("\n## ");
  ASSERT_NE(first_section, std::string::npos);
  const std::string glance = markdown.substr(0, first_section);
  const std::size_t lines =
      glance.find(recommendation.recommended ? "\n- Use " : "\n- No law holds within 5 %");
  const std::size_t figure = glance.find("](figures/errors.png)");
  const std::size_t recommended = glance.find(
      recommendation.recommended ? "```\nRecommended, within 5 % at " : "```\nClosest, within ");
  ASSERT_NE(lines, std::string::npos) << glance;
  ASSERT_NE(figure, std::string::npos) << glance;
  ASSERT_NE(recommended, std::string::npos) << glance;
  EXPECT_LT(lines, figure);
  EXPECT_LT(figure, recommended);
  std::size_t items = 0;
  for (std::size_t at = glance.find("\n- "); at < figure; at = glance.find("\n- ", at + 1)) ++items;
  EXPECT_EQ(items, 3u) << glance;
  // The parameters shown are those of that law, to six digits.
  EXPECT_TRUE(contains(glance.substr(lines, figure - lines), "(" + best.key + ")")) << glance;
  std::vector<std::string> names;
  std::vector<double> values;
  if (const CampaignModelFit* fit = report.calibration->campaign.find(best.key)) {
    names = fit->fit.parameter_names();
    values = fit->fit.parameter_values();
  } else {
    for (const auto& reference : report.calibration->campaign.reference_models)
      if (reference.key == best.key) {
        names = {"c", "n", reference.parameter_name};
        values = {reference.stiffness, reference.exponent, reference.dissipation.at(0)};
      }
  }
  ASSERT_FALSE(names.empty()) << best.key;
  const std::string block = glance.substr(recommended);
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::smatch match;
    ASSERT_TRUE(std::regex_search(block, match, std::regex("\n  " + names[i] + " *= ([-+0-9.e]+)")))
        << names[i] << " not in " << block;
    EXPECT_NEAR(std::stod(match[1]), values[i], 1e-5 * std::abs(values[i])) << names[i];
  }
  // The HTML: the figure and the parameters before the first folded section, and every
  // section heading after them in one.
  const std::string html = read_text(outcome.html);
  const std::size_t folded = html.find("<details>");
  ASSERT_NE(folded, std::string::npos);
  EXPECT_LT(html.find("<img "), folded);
  EXPECT_LT(html.find(recommendation.recommended ? "<pre>Recommended, " : "<pre>Closest, "),
            folded);
  std::size_t headings = 0, sections = 0;
  for (std::size_t at = html.find("<h2>"); at != std::string::npos; at = html.find("<h2>", at + 1))
    ++headings;
  for (std::size_t at = html.find("<details><summary><h2>"); at != std::string::npos;
       at = html.find("<details><summary><h2>", at + 1))
    ++sections;
  EXPECT_GT(sections, 10u);
  EXPECT_EQ(sections, headings);
}

TEST_F(ReportPipeline, AFigureNotDrawnIsAFiguresProblem) {
  drawer.left_out = {"loops.png"};
  const ReportOutcome outcome = write_report(request);
  ASSERT_TRUE(drawer.asked.count("loops.png")) << "the report no longer declares loops.png";
  EXPECT_TRUE(outcome.written);
  EXPECT_EQ(outcome.exit_code, 4);
  EXPECT_FALSE(complete(outcome.report.problems));
  EXPECT_TRUE(contains(read_text(outcome.markdown), "INCOMPLETE"));
}

TEST_F(ReportPipeline, NoUsableRunWritesNothing) {
  request.campaign = directory / "nowhere";
  const ReportOutcome outcome = write_report(request);
  EXPECT_FALSE(outcome.written);
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(drawer.asked.empty());
  EXPECT_FALSE(fs::exists(request.output));
  bool said = false;
  for (const auto& problem : outcome.report.problems)
    said = said || contains(problem.message, "no usable run: nothing was written");
  EXPECT_TRUE(said);
}

// A campaign at one velocity cannot be fitted: the report says so once, whether it calibrates
// the runs itself or reads impact-calibrate's JSON (whose problems already say it).
TEST_F(ReportPipeline, ACampaignNotFittedIsSaidOnce) {
  fs::remove_all(directory / "campaign");
  for (const char* name : {"a", "b"})
    write_fem_run(campaign_run(1.0), directory / "campaign" / name);
  const auto statements = [](const Report& report) {
    std::size_t count = 0;
    for (const auto& problem : report.problems)
      count += contains(problem.message, "a single impact velocity") ? 1 : 0;
    return count;
  };
  const ReportOutcome here = write_report(request);
  ASSERT_TRUE(here.written);
  ASSERT_TRUE(here.report.calibration);
  EXPECT_FALSE(here.report.calibration->campaign.fitted);
  EXPECT_EQ(statements(here.report), 1u);

  CalibrationRequest calibrate;
  calibrate.campaign = request.campaign;
  calibrate.output = directory / "calibration.json";
  const CalibrationOutcome calibrated = write_calibration(calibrate);
  ASSERT_TRUE(calibrated.written);
  EXPECT_EQ(std::count_if(calibrated.calibration.problems.begin(),
                          calibrated.calibration.problems.end(),
                          [&](const Problem& problem) {
                            return is_campaign_not_fitted(problem, calibrated.calibration.campaign);
                          }),
            1);
  request.calibration = calibrate.output;
  request.output = directory / "report_of_json";
  const ReportOutcome read = write_report(request);
  ASSERT_TRUE(read.written);
  EXPECT_EQ(statements(read.report), 1u);
}

} // namespace
