// impact-report --simulators: the section "In your simulator" from result files of format
// "impact-simulator-run" (postprocess/README.md) with known numbers. A two-velocity synthetic
// campaign (V = 0.5 and 2 m/s, Hunt–Crossley, `--laws none`: a few seconds) is calibrated; the
// test writes a Simbody and a MuJoCo result whose tool values are the calibration's FEM values
// times known errors, and checks that the Markdown tables hold exactly those numbers and
// errors, the ranges within 2 % and 5 % that the errors imply, the MuJoCo sentence and the
// file to use; then that bad result files, a missing directory and an empty one are reported
// (exit 2, the file and the problem named, the report INCOMPLETE).

#include "report_cli_testing.hpp"
#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace {

using namespace impact::postprocess;
using namespace impact::testing;
using json = nlohmann::json;
namespace fs = std::filesystem;

const std::vector<double> velocities = {0.5, 2.0};

struct Figures {
  double restitution, contact_time, force_max;
  double energy_loss() const { return 1 - restitution * restitution; }
};

// Relative errors of the energy loss 1 - e^2, t_c and F_max.
struct Errors {
  double energy_loss, contact_time, force_max;
};

Figures with_errors(const Figures& reference, const Errors& errors) {
  return {std::sqrt(1 - reference.energy_loss() * (1 + errors.energy_loss)),
          reference.contact_time * (1 + errors.contact_time),
          reference.force_max * (1 + errors.force_max)};
}

json figures_json(const Figures& f) {
  return {{"restitution", f.restitution},
          {"energy_loss", f.energy_loss()},
          {"contact_time", f.contact_time},
          {"force_max", f.force_max}};
}

// What the simulator measured, the exported model and the FEM at one velocity.
struct KnownRun {
  double velocity;
  Figures tool, reduced_model, fem;
};

// A result file as tests/consumers/simulator_run.cpp writes it (the error blocks are derived
// and not read by the report, so they are left out).
json result_json(const std::string& tool, const std::string& version, const std::string& model,
                 const std::string& file, const json& reference_velocity,
                 const std::vector<KnownRun>& runs) {
  json list = json::array();
  for (const auto& run : runs)
    list.push_back({{"impact_velocity", run.velocity},
                    {"tool", figures_json(run.tool)},
                    {"reduced_model", figures_json(run.reduced_model)},
                    {"fem", figures_json(run.fem)}});
  return {{"format", "impact-simulator-run"},
          {"format_version", 1},
          {"tool", tool},
          {"tool_version", version},
          {"model", model},
          {"export", "/exports/study/export.json"},
          {"file", file},
          {"reference_velocity", reference_velocity},
          {"runs", list}};
}

void write_json(const fs::path& file, const json& content) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << content.dump(2);
}

// The largest |tool / exported model - 1| over e, 1 - e^2, t_c and F_max.
double largest_deviation(const KnownRun& run) {
  double largest = 0;
  for (double deviation : {run.tool.restitution / run.reduced_model.restitution - 1,
                           run.tool.energy_loss() / run.reduced_model.energy_loss() - 1,
                           run.tool.contact_time / run.reduced_model.contact_time - 1,
                           run.tool.force_max / run.reduced_model.force_max - 1})
    largest = std::max(largest, std::abs(deviation));
  return largest;
}

// The tolerances of the printed numbers: six significant digits for values, three for errors.
void expect_value(const std::string& shown, double expected, const std::string& what) {
  expect_same(cell_number(shown), expected, what);
}
void expect_percent(const std::string& shown, double expected, const std::string& what) {
  ASSERT_GE(shown.size(), 2u) << what;
  ASSERT_EQ(shown.substr(shown.size() - 2), " %") << what << ": " << shown;
  EXPECT_NEAR(cell_number(shown) / 100, expected, 5e-3 * std::abs(expected) + 1e-15)
      << what << ": " << shown;
}

// The campaign, its calibration and the known simulator results, made once.
class ReportSimulators : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    directory = new fs::path(scratch_directory("report_simulators"));
    for (double v : velocities) {
      HuntCrossleyTruth truth;
      write_fem_run(synthetic_run(truth, v), campaign() / ("v" + std::to_string(v)));
    }
    const CliRun calibrate = run_tool(IMPACT_CALIBRATE_CLI,
                                      {"--campaign", campaign().string(), "--output",
                                       calibration().string(), "--laws", "none", "--quiet"},
                                      *directory);
    ASSERT_EQ(calibrate.exit_code, 0) << calibrate.err;
    fem = new std::vector<Figures>;
    const json calibrated = json::parse(read_text(calibration()));
    for (const auto& run : calibrated["runs"]) {
      const json& measured = run["measured"];
      fem->push_back({measured["restitution"].get<double>(), measured["contact_time"].get<double>(),
                      measured["force_max"].get<double>()});
    }
  }
  static void TearDownTestSuite() {
    fs::remove_all(*directory);
    delete directory;
    delete fem;
  }
  static fs::path campaign() { return *directory / "campaign"; }
  static fs::path calibration() { return *directory / "calibration.json"; }

  // Simbody: within 2 % at 0.5 m/s (errors of 1 %, 1 %, 1.5 %; the FEM's uncertainty of t_c is
  // one time step, 1/300 of it), outside 2 % but within 5 % at 2 m/s (3 %, 2 %, 4 %).
  static std::vector<KnownRun> simbody_runs() {
    return known_runs({{0.01, -0.01, 0.015}, {-0.03, 0.02, -0.04}}, 1e-4);
  }
  // MuJoCo, matched at 2 m/s: off by 10 % or more at 0.5 m/s, by 0.1 % at 2 m/s except F_max.
  static std::vector<KnownRun> mujoco_runs() {
    return known_runs({{0.3, -0.2, 0.1}, {0.001, -0.001, -0.19}}, 3e-5);
  }
  // The tool's values: the FEM's with these errors; the exported model's: the tool's divided
  // by 1 + deviation (in e, t_c, F_max).
  static std::vector<KnownRun> known_runs(const std::vector<Errors>& errors, double deviation) {
    std::vector<KnownRun> runs;
    for (std::size_t i = 0; i < velocities.size(); ++i) {
      const Figures tool = with_errors((*fem)[i], errors[i]);
      runs.push_back({velocities[i],
                      tool,
                      {tool.restitution / (1 + deviation), tool.contact_time / (1 + deviation),
                       tool.force_max / (1 + deviation)},
                      (*fem)[i]});
    }
    return runs;
  }

  CliRun report(const fs::path& output, const std::vector<std::string>& extra,
                const std::string& environment = "") {
    std::vector<std::string> arguments = {"--campaign",    campaign().string(),
                                          "--calibration", calibration().string(),
                                          "--output",      output.string(),
                                          "--quiet"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return run_tool(IMPACT_REPORT_CLI, arguments, *directory, environment);
  }

  // Checks the table of one result file against the known numbers.
  static void expect_table(const MarkdownTable& table, const std::string& tool,
                           const std::vector<KnownRun>& runs, double reference_velocity) {
    ASSERT_EQ(table.size(), runs.size() + 1);
    const std::vector<std::string> header = {
        "V [m/s]",
        "e " + tool,
        "e FEM",
        "error e",
        "1 - e^2 " + tool,
        "1 - e^2 FEM",
        "error 1 - e^2",
        "t_c " + tool + " [µs]",
        "t_c FEM [µs]",
        "error t_c",
        "F_max " + tool + " [kN]",
        "F_max FEM [kN]",
        "error F_max",
        "largest |error| vs exported model (e, 1 - e^2, t_c, F_max)"};
    EXPECT_EQ(table.front(), header);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const auto& row = table[i + 1];
      const KnownRun& run = runs[i];
      const std::string at = tool + " at V = " + std::to_string(run.velocity) + ": ";
      ASSERT_EQ(row.size(), header.size()) << at;
      const std::string velocity = run.velocity == 0.5 ? "0.5" : "2";
      EXPECT_EQ(row[0], velocity + (run.velocity == reference_velocity ? " (reference)" : ""))
          << at;
      const auto triple = [&](std::size_t first, double tool_value, double fem_value, double scale,
                              const std::string& what) {
        expect_value(row[first], tool_value * scale, at + what + " tool");
        expect_value(row[first + 1], fem_value * scale, at + what + " FEM");
        expect_percent(row[first + 2], (tool_value - fem_value) / fem_value, at + what + " error");
      };
      triple(1, run.tool.restitution, run.fem.restitution, 1, "e");
      triple(4, run.tool.energy_loss(), run.fem.energy_loss(), 1, "1 - e^2");
      triple(7, run.tool.contact_time, run.fem.contact_time, 1e6, "t_c");
      triple(10, run.tool.force_max, run.fem.force_max, 1e-3, "F_max");
      expect_percent(row[13], largest_deviation(run), at + "vs model");
    }
  }

  static fs::path* directory;
  static std::vector<Figures>* fem;
};

fs::path* ReportSimulators::directory = nullptr;
std::vector<Figures>* ReportSimulators::fem = nullptr;

TEST_F(ReportSimulators, TablesHoldTheToolsNumbersAndTheirErrors) {
  const fs::path results = *directory / "in_simulator";
  const auto simbody = simbody_runs();
  const auto mujoco = mujoco_runs();
  write_json(results / "simbody.json", result_json("simbody", "3.7", "hunt-crossley",
                                                   "simbody/impact_contact.hpp", nullptr, simbody));
  write_json(results / "mujoco.json", result_json("mujoco", "2.2.2", "linear-spring-damper",
                                                  "mujoco/impact_contact.xml", 2.0, mujoco));
  const fs::path output = *directory / "report";
  const CliRun run = report(output, {"--simulators", results.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string markdown = read_text(output / "report.md");
  const std::string html = read_text(output / "report.html");
  EXPECT_TRUE(contains(markdown, "Complete:")) << markdown;
  EXPECT_TRUE(contains(markdown, "## In your simulator"));
  EXPECT_TRUE(contains(html, "<h2>In your simulator</h2>"));
  EXPECT_TRUE(contains(html, "<h3>MuJoCo 2.2.2: mujoco/impact_contact.xml</h3>"));

  // One table per file, Simbody first, with the known numbers.
  const auto tables = markdown_tables(markdown);
  std::vector<const MarkdownTable*> found;
  for (const auto& table : tables)
    if (table.front().size() > 1 && table.front()[0] == "V [m/s]" && table.front()[2] == "e FEM")
      found.push_back(&table);
  ASSERT_EQ(found.size(), 2u) << markdown;
  expect_table(*found[0], "Simbody", simbody, NAN);
  expect_table(*found[1], "MuJoCo", mujoco, 2.0);

  // The summary: the ranges that the known errors imply, by the verdict's rule.
  const MarkdownTable* summary = find_table(tables, {"tool", "version", "model", "file"});
  ASSERT_NE(summary, nullptr);
  ASSERT_EQ(summary->size(), 3u);
  const auto& simbody_row = (*summary)[1];
  EXPECT_EQ(simbody_row[0], "Simbody");
  EXPECT_EQ(simbody_row[1], "3.7");
  EXPECT_EQ(simbody_row[2], "hunt-crossley");
  EXPECT_EQ(simbody_row[3], "simbody/impact_contact.hpp");
  EXPECT_EQ(simbody_row[column(*summary, "within 2 %")], "0.5 m/s only");
  EXPECT_EQ(simbody_row[column(*summary, "within 5 %")], "0.5 to 2 m/s");
  EXPECT_EQ((*summary)[2][column(*summary, "within 5 %")], "none");
  // RMS over the two velocities and three quantities; the largest deviation from the model.
  const double rms =
      std::sqrt((0.01 * 0.01 * 2 + 0.015 * 0.015 + 0.03 * 0.03 + 0.02 * 0.02 + 0.04 * 0.04) / 6);
  expect_percent(simbody_row[column(*summary, "RMS error vs FEM (1 - e^2, t_c, F_max)")], rms,
                 "Simbody RMS");
  double largest = 0;
  for (const auto& known : simbody) largest = std::max(largest, largest_deviation(known));
  expect_percent(simbody_row[column(*summary, "largest |error| vs exported model")], largest,
                 "Simbody vs model");

  // The sentences: ranges, largest errors, the file to use, MuJoCo's linear law.
  EXPECT_TRUE(contains(markdown,
                       "- Within 2 %: V = 0.5 m/s in Simbody (1 of 2 tested velocities). "
                       "Outside 2 % at V = 2 m/s"))
      << markdown;
  EXPECT_TRUE(contains(markdown,
                       "- Within 5 %: over the whole tested range, V = 0.5 to 2 m/s in "
                       "Simbody (2 of 2 tested velocities)."));
  EXPECT_TRUE(contains(markdown, "- Within 5 %: at no tested velocity in MuJoCo."));
  EXPECT_TRUE(contains(markdown,
                       "Largest errors against the FEM: 1 - e^2 -3 % (V = 2 m/s), "
                       "t_c +2 % (V = 2 m/s), F_max -4 % (V = 2 m/s)"));
  EXPECT_TRUE(contains(markdown, "The file to use: /exports/study/mujoco/impact_contact.xml"));
  EXPECT_TRUE(contains(markdown, "Matched to the FEM at the reference velocity V = 2 m/s."));
  EXPECT_TRUE(contains(markdown, "MuJoCo's contact is a linear spring–damper"));
  EXPECT_TRUE(contains(markdown, "even there its F_max is off by -19 %"));
}

// The restitution table's law run through Simbody's Force::Custom and LAMMPS's fix external
// stands beside the tool's own exports, named by its extension point and described.
TEST_F(ReportSimulators, ExtensionPointRunsStandBesideTheirTools) {
  const fs::path results = *directory / "in_simulator_extension";
  const std::string table = "restitution/hunt-crossley-thornton-material.json";
  write_json(results / "simbody.json",
             result_json("simbody", "3.7", "hunt-crossley", "simbody/impact_contact.hpp", nullptr,
                         simbody_runs()));
  write_json(results / "mujoco.json", result_json("mujoco", "2.2.2", "linear-spring-damper",
                                                  "mujoco/impact_contact.xml", 2.0, mujoco_runs()));
  write_json(results / "lammps-external.json",
             result_json("lammps-external", "20210929", "hunt-crossley-thornton-material", table,
                         nullptr, simbody_runs()));
  write_json(results / "simbody-custom.json",
             result_json("simbody-custom", "3.7", "hunt-crossley-thornton-material", table, nullptr,
                         simbody_runs()));
  const fs::path output = *directory / "report_extension";
  const CliRun run = report(output, {"--simulators", results.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string markdown = read_text(output / "report.md");
  const auto tables = markdown_tables(markdown);
  const MarkdownTable* summary = find_table(tables, {"tool", "version", "model", "file"});
  ASSERT_NE(summary, nullptr);
  ASSERT_EQ(summary->size(), 5u);
  EXPECT_EQ((*summary)[1][0], "Simbody");
  EXPECT_EQ((*summary)[2][0], "Simbody (Force::Custom)");
  EXPECT_EQ((*summary)[2][2], "hunt-crossley-thornton-material");
  EXPECT_EQ((*summary)[3][0], "MuJoCo");
  EXPECT_EQ((*summary)[4][0], "LAMMPS (fix external)");
  EXPECT_TRUE(contains(markdown, "### Simbody (Force::Custom) 3.7: " + table)) << markdown;
  EXPECT_TRUE(contains(markdown,
                       "as a SimTK::Force::Custom on the sphere, with x_max a "
                       "continuous state"));
  EXPECT_TRUE(contains(markdown, "through fix external (pf/callback) of LAMMPS's library"));
  EXPECT_TRUE(contains(markdown,
                       "the restitution table /exports/study/restitution/"
                       "hunt-crossley-thornton-material.csv"))
      << markdown;
}

TEST_F(ReportSimulators, BadResultFilesAreReportedAndLeftOut) {
  const fs::path results = *directory / "bad";
  const json good = result_json("simbody", "3.7", "hunt-crossley", "simbody/impact_contact.hpp",
                                nullptr, simbody_runs());
  write_json(results / "simbody.json", good);
  std::ofstream(results / "broken.json") << "{\"format\": \"impact-simulator-run\", ";
  write_json(results / "manifest.json", {{"format", "impact-export"}, {"format_version", 1}});
  json version = good;
  version["format_version"] = 2;
  write_json(results / "version.json", version);
  json missing = good;
  missing["runs"][1]["tool"].erase("contact_time");
  write_json(results / "missing.json", missing);
  json negative = good;
  negative["runs"][0]["tool"]["force_max"] = -1.0;
  write_json(results / "negative.json", negative);
  json other = good;
  other["runs"][0]["fem"]["restitution"] = (*fem)[0].restitution * 1.01;
  write_json(results / "other.json", other);

  const fs::path output = *directory / "report_bad";
  // Without the figures (a Python that does not exist): the input problems decide the exit code.
  const CliRun run = report(output, {"--simulators", results.string()},
                            "IMPACT_REPORT_PYTHON=/nonexistent/python3 ");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string markdown = read_text(output / "report.md");
  EXPECT_TRUE(contains(markdown, "INCOMPLETE")) << markdown;
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"broken.json", "not a usable simulator result: is not JSON"},
      {"manifest.json",
       "is not a result file of format 'impact-simulator-run' (the key 'format' is "
       "\"impact-export\")"},
      {"version.json", "has format_version 2; impact-report reads version 1"},
      {"missing.json", "runs[1].tool.contact_time is missing"},
      {"negative.json", "runs[0].tool.force_max must be a finite number > 0 (got -1.0)"},
      {"other.json", "made from another campaign or calibration: its FEM e at V = 0.5 m/s is"}};
  for (const auto& [file, message] : expected) {
    const std::string line = "[input] " + (results / file).string() + ": ";
    EXPECT_TRUE(contains(markdown, line)) << file << "\n" << markdown;
    EXPECT_TRUE(contains(markdown, message)) << message;
    EXPECT_TRUE(contains(run.err, (results / file).string() + ": ")) << run.err;
  }
  // The good file is still shown, alone.
  std::size_t tables = 0;
  for (const auto& table : markdown_tables(markdown))
    tables += table.front().size() > 2 && table.front()[2] == "e FEM";
  EXPECT_EQ(tables, 1u);
  EXPECT_TRUE(contains(markdown, "### Simbody 3.7: simbody/impact_contact.hpp"));
}

TEST_F(ReportSimulators, MissingOrEmptyDirectoryIsNamed) {
  const fs::path absent = *directory / "absent";
  const CliRun run = report(*directory / "report_absent", {"--simulators", absent.string()},
                            "IMPACT_REPORT_PYTHON=/nonexistent/python3 ");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, absent.string() + ": the simulators directory (--simulators) "
                                                  "does not exist"))
      << run.err;
  EXPECT_TRUE(contains(read_text(*directory / "report_absent" / "report.md"), "INCOMPLETE"));

  const fs::path empty = *directory / "empty";
  fs::create_directories(empty);
  const CliRun none = report(*directory / "report_empty", {"--simulators", empty.string()},
                             "IMPACT_REPORT_PYTHON=/nonexistent/python3 ");
  EXPECT_EQ(none.exit_code, 2) << none.err;
  EXPECT_TRUE(contains(none.err, empty.string() + ": the simulators directory (--simulators) "
                                                  "holds no result file"))
      << none.err;
  EXPECT_TRUE(contains(read_text(*directory / "report_empty" / "report.md"),
                       "No usable result file in " + empty.string()));
}

} // namespace
