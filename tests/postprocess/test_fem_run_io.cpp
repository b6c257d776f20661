// Reading FEM runs and campaigns: the format round trip, and every bad input gives a
// RunInputError (or a campaign problem) that names the file and the problem.

#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>

namespace {

using namespace impact::postprocess;
namespace fs = std::filesystem;

const impact::testing::HuntCrossleyTruth truth;

FemRun example(double velocity = 1) {
  return impact::testing::synthetic_run(truth, velocity);
}

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

TEST_F(FemRunIo, CampaignDirectoryMissingOrEmpty) {
  EXPECT_THROW(read_campaign(directory / "nowhere"), RunInputError);
  try {
    read_campaign(directory);
    FAIL() << "an empty campaign must be an error";
  } catch (const RunInputError& error) {
    EXPECT_NE(std::string(error.what()).find("holds no run"), std::string::npos);
  }
}

// ---- Sweep campaigns (index.json with axes and points) ----------------------------------

// Two thicknesses x two velocities; `point` edits each index entry.
fs::path sweep_campaign(const fs::path& directory,
                        const std::function<void(nlohmann::json&, double, double)>& point) {
  nlohmann::json index{{"axes",
                        {{{"parameter", "Scenario/Plate thickness"}, {"values", {0.005, 0.01}}},
                         {{"parameter", "Scenario/Impact velocity"}, {"values", {0.5, 1}}}}},
                       {"runs", nlohmann::json::array()}};
  for (double h : {0.005, 0.01})
    for (double v : {0.5, 1.0}) {
      FemRun run = example(v);
      run.text_attributes["Scenario/Plate thickness"] = h == 0.005 ? "0.005" : "0.01";
      const std::string name = "plate-thickness-" +
                               run.text_attributes["Scenario/Plate thickness"] +
                               (v == 0.5 ? "_v0.5" : "_v1");
      write_fem_run(run, directory / name);
      nlohmann::json entry{{"path", name},
                           {"velocity", v},
                           {"point",
                            {{"Scenario/Plate thickness", h}, {"Scenario/Impact velocity", v}}}};
      point(entry, h, v);
      index["runs"].push_back(entry);
    }
  std::ofstream(directory / "index.json") << index.dump(2);
  return directory;
}

std::string campaign_error(const fs::path& directory) {
  try {
    read_campaign(directory);
  } catch (const RunInputError& error) {
    return error.what();
  }
  return "";
}

TEST_F(FemRunIo, SweepIndexGivesAxesAndPoints) {
  sweep_campaign(directory, [](nlohmann::json&, double, double) {});
  const Campaign campaign = read_campaign(directory);
  EXPECT_TRUE(campaign.problems.empty());
  ASSERT_EQ(campaign.axes.size(), 2u);
  EXPECT_EQ(campaign.axes[0].parameter, "Scenario/Plate thickness");
  EXPECT_EQ(*campaign.axes[0].values[1].number, 0.01);
  ASSERT_EQ(campaign.runs.size(), 4u);
  for (const auto& run : campaign.runs) {
    const double h = *run.sweep_point.at("Scenario/Plate thickness").number;
    EXPECT_EQ(run.text_attributes.at("Scenario/Plate thickness"), h == 0.005 ? "0.005" : "0.01");
    EXPECT_EQ(*run.sweep_point.at("Scenario/Impact velocity").number, run.impact_velocity);
  }
}

TEST_F(FemRunIo, SweepPointsFromTheRunsWhenTheIndexHasNone) {
  sweep_campaign(directory, [](nlohmann::json& entry, double, double) { entry.erase("point"); });
  const Campaign campaign = read_campaign(directory);
  ASSERT_EQ(campaign.runs.size(), 4u);
  for (const auto& run : campaign.runs)
    EXPECT_EQ(run.sweep_point.at("Scenario/Plate thickness").text,
              run.text_attributes.at("Scenario/Plate thickness"));
}

TEST_F(FemRunIo, OlderIndexWithoutAxesIsReadAsBefore) {
  write_fem_run(example(1), directory / "v1");
  write_fem_run(example(2), directory / "v2");
  std::ofstream(directory / "index.json")
      << R"({"runs": [{"velocity": 1, "path": "v1"}, {"velocity": 2, "path": "v2"}]})";
  const Campaign campaign = read_campaign(directory);
  EXPECT_TRUE(campaign.axes.empty());
  ASSERT_EQ(campaign.runs.size(), 2u);
  EXPECT_TRUE(campaign.runs[0].sweep_point.empty());
}

TEST_F(FemRunIo, BadSweepIndexNamesTheFileAndTheProblem) {
  const auto expect = [&](const std::function<void(nlohmann::json&, double, double)>& edit,
                          const std::string& part, const std::string& file) {
    fs::remove_all(directory);
    fs::create_directories(directory);
    sweep_campaign(directory, edit);
    const std::string message = campaign_error(directory);
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_NE(message.find(file), std::string::npos) << message;
  };
  // A point missing an axis.
  expect([](nlohmann::json& entry, double,
            double) { entry["point"].erase("Scenario/Plate thickness"); },
         "has no value of the axis 'Scenario/Plate thickness'", "index.json");
  // A point whose value is not one of the axis's.
  expect(
      [](nlohmann::json& entry, double h, double) {
        if (h == 0.01) entry["point"]["Scenario/Plate thickness"] = 0.02;
      },
      "= '0.02', which is not one of the axis's values", "index.json");
  // A point with a parameter that is not an axis.
  expect([](nlohmann::json& entry, double, double) { entry["point"]["Sphere/Radius"] = 0.01; },
         "'Sphere/Radius', which is not an axis", "index.json");
  // A point that is not an object; a velocity that differs from the entry's.
  expect([](nlohmann::json& entry, double, double) { entry["point"] = 3; }, "is not an object",
         "index.json");
  expect(
      [](nlohmann::json& entry, double, double v) {
        if (v == 1) entry["velocity"] = 2;
      },
      "but the entry's \"velocity\" is 2", "index.json");
  // The run's own parameter differs from its point (the index swapped two thicknesses).
  expect([](nlohmann::json& entry, double h,
            double) { entry["point"]["Scenario/Plate thickness"] = h == 0.005 ? 0.01 : 0.005; },
         "differs from its point in the campaign index", "history.h5");
}

TEST_F(FemRunIo, BadSweepAxes) {
  const auto expect = [&](const std::string& axes, const std::string& part) {
    fs::remove_all(directory);
    fs::create_directories(directory);
    write_fem_run(example(1), directory / "v1");
    std::ofstream(directory / "index.json")
        << R"({"axes": )" + axes + R"(, "runs": [{"path": "v1", "velocity": 1}]})";
    const std::string message = campaign_error(directory);
    EXPECT_NE(message.find(part), std::string::npos) << message;
    EXPECT_NE(message.find("index.json"), std::string::npos) << message;
  };
  expect("{}", "\"axes\" must be a non-empty list");
  expect(R"([{"values": [1]}])", "has no \"parameter\"");
  expect(R"([{"parameter": "Scenario/Impact velocity"}])", "has no \"values\"");
  expect(R"([{"parameter": "Scenario/Impact velocity", "values": [1, 1]}])",
         "lists the value '1' twice");
  expect(R"([{"parameter": "Scenario/Impact velocity", "values": [true]}])",
         "must be a number or a string");
  // A run without point whose parameter is missing: named by its file.
  fs::remove_all(directory);
  fs::create_directories(directory);
  write_fem_run(example(1), directory / "v1");
  std::ofstream(directory / "index.json")
      << R"({"axes": [{"parameter": "Scenario/Plate thickness", "values": [0.01]},
                      {"parameter": "Scenario/Impact velocity", "values": [1]}],
             "runs": [{"path": "v1", "velocity": 1}]})";
  const std::string message = campaign_error(directory);
  EXPECT_NE(message.find("has no parameter 'Scenario/Plate thickness'"), std::string::npos)
      << message;
  EXPECT_NE(message.find("history.h5"), std::string::npos) << message;
}

} // namespace
