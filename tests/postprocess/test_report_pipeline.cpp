// The report pipeline (write_report) called as a library, without a child process: the
// figure drawer is the test's own, which records what it was asked to draw and writes a PNG
// signature for each figure. Checks: a campaign calibrated here gives a complete report
// (exit code 0), calibration.json written beside it, every declared figure handed to the
// drawer and shown on the page; a figure the drawer does not write is a figures problem
// (exit code 4, report incomplete); no usable run writes nothing (exit code 2).

#include "impact_postprocess/report/pipeline.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include "report_cli_testing.hpp"
#include "synthetic_runs.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace {

namespace fs = std::filesystem;
using namespace impact::postprocess;
using impact::testing::contains;
using impact::testing::read_text;

using impact::testing::campaign_run;

struct RecordingDrawer {
  std::set<std::string> asked;     ///< figure files the report declared
  std::set<std::string> left_out;  ///< not written (to test the problem it makes)
  FigureDrawer drawer() {
    return [this](const Report& report, const fs::path&, const fs::path& figures) {
      std::vector<Problem> problems;
      fs::create_directories(figures);
      for (const auto& figure : report_figures(report)) {
        asked.insert(figure.file);
        if (left_out.count(figure.file)) {
          problems.push_back({(figures / figure.file).string(), ProblemKind::figures,
                              "the figure was not drawn"});
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

} // namespace
