// Reading FEM runs and campaigns: the format round trip, and every bad input gives a
// RunInputError (or a campaign problem) that names the file and the problem.

#include "synthetic_runs.hpp"

#include "impact_postprocess/fem_run.hpp"
#include "impact_postprocess/fem_run_format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace {

using namespace impact::postprocess;
namespace fs = std::filesystem;

const impact::testing::HuntCrossleyTruth truth;

FemRun example(double velocity = 1) { return impact::testing::synthetic_run(truth, velocity); }

// The message of the RunInputError thrown by read_fem_run(path), or "" if none.
std::string read_error(const fs::path& path) {
  try {
    read_fem_run(path);
  } catch (const RunInputError& error) {
    return error.what();
  }
  return "";
}

class FemRunIo : public ::testing::Test {
protected:
  void SetUp() override {
    directory = impact::testing::scratch_directory(
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(directory); }
  fs::path directory;
};

TEST_F(FemRunIo, WrittenRunReadsBackUnchanged) {
  const FemRun run = example(2);
  const fs::path file = write_fem_run(run, directory / "run");
  EXPECT_EQ(file.filename(), fem_format::history_file);
  EXPECT_TRUE(fs::exists(directory / "run" / fem_format::summary_file));
  for (const fs::path& path : {file, directory / "run"}) {
    const FemRun read = read_fem_run(path);
    EXPECT_EQ(read.source, file.string());
    EXPECT_EQ(read.time, run.time);
    EXPECT_EQ(read.contact_force, run.contact_force);
    EXPECT_EQ(read.approach, run.approach);
    EXPECT_EQ(read.sphere_velocity, run.sphere_velocity);
    EXPECT_EQ(read.impact_velocity, run.impact_velocity);
    EXPECT_EQ(read.mass, run.mass);
    EXPECT_EQ(read.restitution, run.restitution);
    EXPECT_EQ(read.contact_time, run.contact_time);
    EXPECT_EQ(read.force_max, run.force_max);
    EXPECT_EQ(read.approach_max, run.approach_max);
    EXPECT_EQ(read.text_attributes.at(fem_format::status_attribute), fem_format::status_complete);
  }
}

TEST_F(FemRunIo, WithoutSummaryTheResultAttributesAreUsed) {
  const FemRun run = example(2);
  write_fem_run(run, directory / "run");
  fs::remove(directory / "run" / fem_format::summary_file);
  const FemRun read = read_fem_run(directory / "run");
  EXPECT_EQ(read.restitution, run.restitution);
  EXPECT_EQ(read.impact_velocity, run.impact_velocity);
  EXPECT_EQ(read.mass, run.mass);
}

TEST_F(FemRunIo, MissingFileOrDirectory) {
  EXPECT_NE(read_error(directory / "nowhere.h5").find("does not exist"), std::string::npos);
  fs::create_directories(directory / "empty");
  const std::string message = read_error(directory / "empty");
  EXPECT_NE(message.find("holds no history.h5"), std::string::npos) << message;
}

TEST_F(FemRunIo, IncompleteRun) {
  write_fem_run(example(), directory / "run", false);
  EXPECT_TRUE(fs::exists(directory / "run" / fem_format::incomplete_history_file));
  for (const fs::path& path : {directory / "run", directory / "run" / fem_format::history_file}) {
    const std::string message = read_error(path);
    EXPECT_NE(message.find("did not finish"), std::string::npos) << message;
  }
  const std::string message = read_error(directory / "run" / fem_format::incomplete_history_file);
  EXPECT_NE(message.find("marked incomplete"), std::string::npos) << message;
}

TEST_F(FemRunIo, NotAnHdf5File) {
  std::ofstream(directory / "text.h5") << "not HDF5\n";
  const std::string message = read_error(directory / "text.h5");
  EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;
  EXPECT_NE(message.find("text.h5"), std::string::npos) << message;
}

TEST_F(FemRunIo, MissingDataset) {
  FemRun run = example();
  run.approach.clear();
  write_fem_run(run, directory / "run");
  const std::string message = read_error(directory / "run");
  EXPECT_NE(message.find("no dataset 'approach'"), std::string::npos) << message;
}

TEST_F(FemRunIo, DatasetsOfDifferentLength) {
  FemRun run = example();
  run.contact_force.pop_back();
  write_fem_run(run, directory / "run");
  const std::string message = read_error(directory / "run");
  EXPECT_NE(message.find("'contact_force' has"), std::string::npos) << message;
}

TEST_F(FemRunIo, NoContact) {
  FemRun run = example();
  std::fill(run.contact_force.begin(), run.contact_force.end(), 0.0);
  write_fem_run(run, directory / "run");
  const std::string message = read_error(directory / "run");
  EXPECT_NE(message.find("no contact"), std::string::npos) << message;
}

TEST_F(FemRunIo, NoSeparation) {
  FemRun run = example();
  run.restitution = std::numeric_limits<double>::quiet_NaN();
  write_fem_run(run, directory / "run");
  const std::string message = read_error(directory / "run");
  EXPECT_NE(message.find("did not separate"), std::string::npos) << message;
}

TEST_F(FemRunIo, CampaignFromSubdirectories) {
  for (double velocity : {2.0, 0.5, 1.0})
    write_fem_run(example(velocity), directory / ("v" + std::to_string(velocity)));
  const Campaign campaign = read_campaign(directory);
  EXPECT_TRUE(campaign.problems.empty());
  ASSERT_EQ(campaign.runs.size(), 3u);
  EXPECT_EQ(campaign.runs[0].impact_velocity, 0.5); // ordered by velocity
  EXPECT_EQ(campaign.runs[2].impact_velocity, 2.0);
}

TEST_F(FemRunIo, CampaignFromSubdirectoriesGivenAsARelativePath) {
  for (double velocity : {0.5, 1.0})
    write_fem_run(example(velocity), directory / ("v" + std::to_string(velocity)));
  const fs::path here = fs::current_path();
  fs::current_path(directory.parent_path());
  const Campaign campaign = read_campaign(directory.filename());
  fs::current_path(here);
  EXPECT_TRUE(campaign.problems.empty());
  EXPECT_EQ(campaign.runs.size(), 2u);
}

TEST_F(FemRunIo, CampaignIndexListsAMissingAndAnIncompleteRun) {
  write_fem_run(example(1), directory / "v1");
  write_fem_run(example(2), directory / "v2", false);
  std::ofstream(directory / fem_format::campaign_index_json)
      << R"({"runs": [{"velocity": 1, "path": "v1"}, {"velocity": 2, "path": "v2"},
                     {"velocity": 3, "path": "v3"}]})";
  const Campaign campaign = read_campaign(directory);
  ASSERT_EQ(campaign.runs.size(), 1u);
  ASSERT_EQ(campaign.problems.size(), 2u);
  EXPECT_NE(campaign.problems[0].message.find("v3"), std::string::npos);
  EXPECT_NE(campaign.problems[0].message.find("does not exist"), std::string::npos);
  EXPECT_NE(campaign.problems[1].message.find("did not finish"), std::string::npos);
}

TEST_F(FemRunIo, CampaignCsvIndex) {
  write_fem_run(example(1), directory / "a");
  write_fem_run(example(2), directory / "b");
  std::ofstream(directory / fem_format::campaign_index_csv)
      << "# impact campaign\nvelocity,path\n1,a\n2,b/history.h5\n";
  const Campaign campaign = read_campaign(directory);
  EXPECT_TRUE(campaign.problems.empty());
  EXPECT_EQ(campaign.runs.size(), 2u);
}

TEST_F(FemRunIo, CampaignDirectoryMissingOrEmpty) {
  EXPECT_THROW(read_campaign(directory / "nowhere"), RunInputError);
  try {
    read_campaign(directory);
    FAIL() << "an empty campaign must be an error";
  } catch (const RunInputError& error) {
    EXPECT_NE(std::string(error.what()).find("holds no run"), std::string::npos);
  }
}

} // namespace
