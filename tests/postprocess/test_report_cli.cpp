// impact-report as a user runs it. A small synthetic campaign (four velocities, FEM format,
// made by the reduced library with a damping that grows with V so that the calibrated
// Hunt–Crossley model holds only in part of the range) is calibrated by impact-calibrate and
// reported: the HTML and Markdown exist, every figure is a valid PNG, the tables hold the
// calibration JSON's numbers, and the page renders in headless Chromium (not blank; at
// 1280 px nothing scrolls sideways and the first figure and the recommended model are on
// the first screen). Each
// bad input gives its exit code, a message, and a report that says what is missing.

#include "report_cli_testing.hpp"
#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace {

using namespace impact::postprocess;
using namespace impact::testing;
using json = nlohmann::json;
namespace fs = std::filesystem;

using impact::testing::campaign_run;

// Adds FEM-only results to a run's summary.json (energy balance, stresses).
void add_to_summary(const fs::path& run_directory, const json& extra) {
  const fs::path file = run_directory / fem_format::summary_file;
  json summary = json::parse(read_text(file));
  summary.update(extra);
  std::ofstream(file) << summary.dump(2);
}

// ---- PNG reader ---------------------------------------------------------------------------

struct PngSize {
  bool valid;
  unsigned width, height;
};

PngSize png_size(const std::string& bytes) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.size() < 24 || bytes.compare(0, 8, signature) != 0 || bytes.compare(12, 4, "IHDR") != 0)
    return {false, 0, 0};
  const auto word = [&](std::size_t at) {
    return unsigned((unsigned char)bytes[at]) << 24 | unsigned((unsigned char)bytes[at + 1]) << 16 |
           unsigned((unsigned char)bytes[at + 2]) << 8 | unsigned((unsigned char)bytes[at + 3]);
  };
  return {true, word(16), word(20)};
}

// ---- The good campaign, made once ---------------------------------------------------------

const std::vector<double> velocities = {0.5, 1.0, 2.0, 4.0};

// The campaign is calibrated and reported once; ctest runs every test case in its own process,
// so the checks are one test case (each check names itself in a failure).
struct ReportOfCampaign {
  static void make() {
    directory = new fs::path(impact::testing::scratch_directory("report_campaign"));
    const fs::path campaign = *directory / "campaign";
    for (double v : velocities)
      write_fem_run(campaign_run(v), campaign / ("v" + std::to_string(v)));
    add_to_summary(campaign / ("v" + std::to_string(1.0)), {{"energy_error", 0.0012},
                                                            {"max_von_mises", 1.2e9},
                                                            {"yield_strength", 1.5e9},
                                                            {"dissipated_energy_fraction", 0.05},
                                                            {"radiated_energy_fraction", 0.01}});
    // V = 4 m/s yields: the report must flag it.
    add_to_summary(campaign / ("v" + std::to_string(4.0)),
                   {{"max_von_mises", 1.8e9}, {"yield_strength", 1.5e9}});
    calibrate = new CliRun(run_tool(IMPACT_CALIBRATE_CLI,
                                    {"--campaign", campaign.string(), "--output",
                                     (*directory / "calibration.json").string(), "--laws",
                                     "lankarani-nikravesh,kuwabara-kono", "--quiet"},
                                    *directory));
    report = new CliRun(run_tool(IMPACT_REPORT_CLI,
                                 {"--campaign", campaign.string(), "--calibration",
                                  (*directory / "calibration.json").string(), "--output",
                                  (*directory / "report").string(), "--quiet"},
                                 *directory));
  }
  // IMPACT_REPORT_TEST_KEEP=DIR keeps the campaign, calibration and report there.
  static void remove() {
    if (const char* keep = std::getenv("IMPACT_REPORT_TEST_KEEP"); keep && *keep) {
      fs::remove_all(keep);
      fs::copy(*directory, keep, fs::copy_options::recursive);
    }
    fs::remove_all(*directory);
    delete directory;
    delete calibrate;
    delete report;
  }
  static fs::path output() { return *directory / "report"; }
  static json calibration() { return json::parse(read_text(*directory / "calibration.json")); }

  static fs::path* directory;
  static CliRun* calibrate;
  static CliRun* report;
};

fs::path* ReportOfCampaign::directory = nullptr;
CliRun* ReportOfCampaign::calibrate = nullptr;
CliRun* ReportOfCampaign::report = nullptr;

const std::vector<std::string> figure_files = {"loops.png",      "histories.png",   "residuals.png",
                                               "quantities.png", "energy_loss.png", "damping.png",
                                               "errors.png"};

void check_HtmlAndMarkdownExist() {
  EXPECT_TRUE(
      contains(ReportOfCampaign::report->out,
               "report written to " + (ReportOfCampaign::output() / "report.html").string()))
      << ReportOfCampaign::report->out;
  const std::string html = read_text(ReportOfCampaign::output() / "report.html");
  const std::string markdown = read_text(ReportOfCampaign::output() / "report.md");
  EXPECT_TRUE(contains(html, "<!DOCTYPE html>"));
  EXPECT_TRUE(contains(html, "</html>"));
  EXPECT_TRUE(contains(markdown, "# Impact model-validity report"));
  for (const char* section :
       {"Validity verdict", "Calibrated parameters", "Runs", "Force–approach loops",
        "Approach and force against time", "Per-run damping b against V",
        "Errors of the reduced models", "Energy balance and yield check", "In your simulator"}) {
    EXPECT_TRUE(contains(markdown, std::string("## ") + section)) << section;
    EXPECT_TRUE(contains(html, std::string("<h2>") + section)) << section;
  }
  EXPECT_TRUE(contains(markdown, "Complete:"));
  // Without --simulators the section gives the commands that produce it, with this campaign.
  const fs::path campaign = *ReportOfCampaign::directory / "campaign";
  const fs::path calibration = *ReportOfCampaign::directory / "calibration.json";
  EXPECT_TRUE(contains(markdown, "build/bin/impact-export --campaign " + campaign.string() +
                                     " --calibration " + calibration.string() +
                                     " --output EXPORT_DIR\n"
                                     "tests/consumers/run_in_simulators.sh EXPORT_DIR RESULTS_DIR\n"
                                     "build/bin/impact-report --campaign " +
                                     campaign.string()))
      << markdown;
  EXPECT_TRUE(contains(markdown, "--simulators RESULTS_DIR"));
}

void check_EveryFigureIsAValidImage() {
  const std::string markdown = read_text(ReportOfCampaign::output() / "report.md");
  const std::string html = read_text(ReportOfCampaign::output() / "report.html");
  std::size_t embedded = 0;
  for (std::size_t at = html.find("data:image/png;base64,"); at != std::string::npos;
       at = html.find("data:image/png;base64,", at + 1))
    ++embedded;
  EXPECT_EQ(embedded, figure_files.size()); // the HTML stands alone
  for (const auto& file : figure_files) {
    const fs::path path = ReportOfCampaign::output() / "figures" / file;
    ASSERT_TRUE(fs::exists(path)) << path;
    const std::string bytes = read_text(path);
    EXPECT_GT(bytes.size(), 5000u) << path;
    const PngSize size = png_size(bytes);
    EXPECT_TRUE(size.valid) << path << " is not a PNG";
    EXPECT_GT(size.width, 200u) << path;
    EXPECT_GT(size.height, 200u) << path;
    EXPECT_TRUE(contains(markdown, "](figures/" + file + ")")) << file;
  }
}

void check_TablesHoldTheNumbersOfTheCalibration() {
  const json calibration_json = ReportOfCampaign::calibration();
  const auto tables = markdown_tables(read_text(ReportOfCampaign::output() / "report.md"));

  const MarkdownTable* parameters = find_table(tables, {"parameter", "value", "standard error"});
  ASSERT_NE(parameters, nullptr);
  const json& hc = calibration_json["campaign"]["hunt_crossley"];
  ASSERT_EQ(parameters->size(), 4u);
  for (std::size_t row = 1; row < parameters->size(); ++row) {
    const auto& cells = (*parameters)[row];
    const json& p = hc["parameters"][cells[0]];
    expect_same(cell_number(cells[1]), p["value"].get<double>(), cells[0] + " value");
    expect_same(cell_number(cells[2]), p["standard_error"].get<double>(), cells[0] + " error");
    expect_same(cell_number(cells[3]), p["interval"][0].get<double>(), cells[0] + " lower");
    expect_same(cell_number(cells[4]), p["interval"][1].get<double>(), cells[0] + " upper");
  }

  const MarkdownTable* runs = find_table(tables, {"V [m/s]", "mass [kg]"});
  ASSERT_NE(runs, nullptr);
  ASSERT_EQ(runs->size(), velocities.size() + 1);
  const json& calibrated_runs = calibration_json["runs"];
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const auto& cells = (*runs)[i + 1];
    const json& run = calibrated_runs[i];
    const json& measured = run["measured"];
    expect_same(cell_number(cells[0]), run["impact_velocity"].get<double>(), "V");
    expect_same(cell_number(cells[column(*runs, "e [1]")]), measured["restitution"].get<double>(),
                "e");
    expect_same(cell_number(cells[column(*runs, "t_c [µs]")]) * 1e-6,
                measured["contact_time"].get<double>(), "t_c");
    expect_same(cell_number(cells[column(*runs, "F_max [kN]")]) * 1e3,
                measured["force_max"].get<double>(), "F_max");
    expect_same(cell_number(cells[column(*runs, "x_max [µm]")]) * 1e-6,
                measured["approach_max"].get<double>(), "x_max");
    expect_same(cell_number(cells[column(*runs, "b from e [s/m]")]),
                run["restitution_fit"]["b"]["value"].get<double>(), "b from e");
    expect_same(cell_number(cells[column(*runs, "b history fit [s/m]")]),
                run["history_fit"]["parameters"]["b"]["value"].get<double>(), "b history");
    expect_same(cell_number(cells[column(*runs, "n history fit")]),
                run["history_fit"]["parameters"]["n"]["value"].get<double>(), "n history");
  }

  // Predictions of the calibrated and best-law models: the calibration's own numbers.
  const MarkdownTable* restitution = find_table(tables, {"V [m/s]", "FEM restitution e [1]"});
  ASSERT_NE(restitution, nullptr);
  const json& ranking = calibration_json["campaign"]["ranking"];
  // The best law: the comparison law ranked first (the ranking also holds the Hunt–Crossley
  // variants and the reference models).
  std::string best;
  const json* best_fit = nullptr;
  for (const auto& entry : ranking) {
    for (const auto& law : calibration_json["campaign"]["comparison_laws"])
      if (law["key"] == entry["model"]) best_fit = &law;
    if (best_fit) {
      best = entry["model"].get<std::string>();
      break;
    }
  }
  ASSERT_NE(best_fit, nullptr);
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const auto& cells = (*restitution)[i + 1];
    expect_same(cell_number(cells[column(*restitution, "Hunt–Crossley (calibrated)")]),
                hc["runs"][i]["prediction"]["restitution"].get<double>(), "HC e");
    expect_same(cell_number(cells[column(*restitution, best + " (best law)")]),
                (*best_fit)["runs"][i]["prediction"]["restitution"].get<double>(), "best-law e");
  }

  const MarkdownTable* ranked = find_table(tables, {"rank", "model"});
  ASSERT_NE(ranked, nullptr);
  ASSERT_EQ(ranked->size(), ranking.size() + 1);
  for (std::size_t i = 0; i < ranking.size(); ++i) {
    EXPECT_EQ((*ranked)[i + 1][1], ranking[i]["model"].get<std::string>());
    expect_same(cell_number((*ranked)[i + 1][column(*ranked, "RMS residual [%]")]) / 100,
                ranking[i]["rms_residual"].get<double>(), "RMS");
    expect_same(cell_number((*ranked)[i + 1][column(*ranked, "value")]),
                ranking[i]["parameter"]["value"].get<double>(), "ranking parameter");
  }
}

void check_StatesTheVerdictTheModelsAndTheChecks() {
  const std::string markdown = read_text(ReportOfCampaign::output() / "report.md");
  EXPECT_TRUE(contains(markdown, "- Within 2 %:")) << markdown;
  EXPECT_TRUE(contains(markdown, "- Within 5 %:"));
  EXPECT_TRUE(contains(markdown, "Cause: "));
  // b was made to grow with V: the report must see the trend.
  EXPECT_TRUE(contains(markdown, "b rises with V")) << markdown;
  // The Hertz stiffness of the recorded materials (published steel example).
  EXPECT_TRUE(contains(markdown, "Hertz value of the scenario's materials"));
  EXPECT_TRUE(contains(markdown, "c_Hertz = 1.713")); // 1.7135e10 N/m^1.5, published steel
  EXPECT_TRUE(contains(markdown, "Hunt–Crossley (b = 0.1 s/m)"));
  EXPECT_TRUE(contains(markdown, "Hertz (b = 0)"));
  EXPECT_TRUE(contains(markdown, "n - 3/2 = "));
  // Energy and yield: recorded for one run, "not recorded" for the others.
  const auto tables = markdown_tables(markdown);
  // The summary records the largest stress over both bodies only: judged against the smallest
  // strength, in a column of its own.
  const MarkdownTable* energy = find_table(tables, {"V [m/s]", "largest energy error [%]"});
  ASSERT_NE(energy, nullptr);
  ASSERT_EQ(energy->size(), velocities.size() + 1);
  EXPECT_EQ((*energy)[1][1], "not recorded");
  expect_same(cell_number((*energy)[2][1]), 0.12, "energy error");
  const std::size_t stress = column(*energy, "both bodies: max von Mises of yield strength");
  EXPECT_EQ((*energy)[2][stress], "1200 of 1500 (80 %)");
  EXPECT_EQ((*energy)[2].back(), "elastic");
  EXPECT_TRUE(contains((*energy)[1].back(), "not recorded"));
  // The table of errors: every model (seven: Hunt–Crossley calibrated, with the energy loss,
  // with b(V), the best law, the published b, Hertz — the synthetic runs record no
  // retardation times, so no Kuwabara–Kono from the material), every quantity (seven: 1 - e^2,
  // 1 - e, e, t_c, F_max, t(F_max), x_max), every velocity.
  const MarkdownTable* errors = find_table(tables, {"model", "quantity"});
  ASSERT_NE(errors, nullptr);
  EXPECT_EQ(errors->size(), 1 + 6 * 7u);
  EXPECT_EQ(errors->front().size(), 2 + velocities.size());
  for (const char* label : {"Hunt–Crossley (calibrated)", "Hunt–Crossley (force + energy)",
                            "Hunt–Crossley b(V)", "Hunt–Crossley (b = 0.1 s/m)", "Hertz (b = 0)"}) {
    std::size_t rows = 0;
    for (const auto& row : *errors) rows += row.front() == label;
    EXPECT_EQ(rows, 7u) << label;
  }
  // The verdict judges the energy loss out of sample, names it and the FEM's uncertainty.
  EXPECT_TRUE(contains(markdown, "The errors are out of sample")) << markdown;
  EXPECT_TRUE(contains(markdown, "(out of sample)"));
  EXPECT_TRUE(contains(markdown, "Velocity trend of the FEM's energy loss: 1 - e ∝ V^p with p = "));
  EXPECT_TRUE(contains(markdown, "## Ranking of the models"));
  EXPECT_TRUE(contains(markdown, "## FEM quality per run"));
  EXPECT_TRUE(contains(markdown, "## The laws as their users apply them"));
  EXPECT_TRUE(contains(markdown, "CONDITIONAL ON THE MODEL"));
  EXPECT_TRUE(find_table(tables, {"parameter", "value", "jackknife standard error"}) != nullptr);
  // The run above the recorded yield strength is flagged in every table.
  EXPECT_TRUE(contains(markdown,
                       "The FEM exceeds the yield strength (1.5 GPa, yield_strength) "
                       "from V = 4 m/s on"))
      << markdown;
  EXPECT_EQ((*energy)[4].back(),
            "YIELDS: the largest stress of both bodies at 120 % of the smallest yield strength "
            "(yield_strength)");
  for (const auto& table : tables)
    for (const auto& row : table)
      if (row.front().rfind("4", 0) == 0 && row.front().size() > 1 && row.front()[1] != '.') {
        EXPECT_EQ(row.front(), "4 (yields)");
      }
}

// The offsets from Hertz: n - 3/2 from the free campaign fit, c / c_Hertz - 1 from the fit
// with n fixed at 3/2, and the free fit's c offset for information, all from the JSON.
void check_StatesTheOffsetsFromHertz() {
  const json campaign = ReportOfCampaign::calibration()["campaign"];
  const json& free_fit = campaign["hunt_crossley"];
  const json& fixed_fit = campaign["hunt_crossley_hertz_exponent"];
  ASSERT_TRUE(fixed_fit.is_object()) << "the calibration has no fit with n fixed at 3/2";
  EXPECT_TRUE(fixed_fit["parameters"]["n"]["fixed"].get<bool>());
  EXPECT_EQ(fixed_fit["parameters"]["n"]["value"].get<double>(), 1.5);
  const double n = free_fit["parameters"]["n"]["value"].get<double>();
  const double c_free = free_fit["parameters"]["c"]["value"].get<double>();
  const double c_fixed = fixed_fit["parameters"]["c"]["value"].get<double>();

  const std::string markdown = read_text(ReportOfCampaign::output() / "report.md");
  std::smatch match;
  const std::string number = "([-+]?[0-9.]+(?:e[-+]?[0-9]+)?)";
  const std::regex bullet(
      "Offsets of the calibrated elastic part from Hertz \\(c_Hertz = " + number +
      " N/m\\^1\\.5\\): n - 3/2 = " + number + " \\(free fit of c, n, b: n = " + number +
      "\\); c / c_Hertz - 1 = " + number + " % \\(fit with n fixed at 3/2, c and b free: c = " +
      number + " N/m\\^1\\.5\\); for information, the free fit's c / c_Hertz - 1 = " + number +
      " % \\(c = " + number + " N/m\\^n");
  ASSERT_TRUE(std::regex_search(markdown, match, bullet)) << markdown;
  const double hertz = std::stod(match[1]);
  EXPECT_NEAR(hertz, 1.7135e10, 1e-3 * 1.7135e10); // the recorded steel materials
  // Offsets: three significant digits; values: six.
  const auto expect_offset = [](double shown, double expected, const std::string& what) {
    EXPECT_NEAR(shown, expected, 5e-3 * std::abs(expected) + 1e-12) << what;
  };
  expect_offset(std::stod(match[2]), n - 1.5, "n - 3/2");
  expect_same(std::stod(match[3]), n, "free-fit n");
  expect_offset(std::stod(match[4]) / 100, c_fixed / hertz - 1, "fixed-n c / c_Hertz - 1");
  expect_same(std::stod(match[5]), c_fixed, "fixed-n c");
  expect_offset(std::stod(match[6]) / 100, c_free / hertz - 1, "free-fit c / c_Hertz - 1");
  expect_same(std::stod(match[7]), c_free, "free-fit c");
  // The HTML states the same.
  const std::string html = read_text(ReportOfCampaign::output() / "report.html");
  EXPECT_TRUE(contains(html, "n - 3/2 = " + std::string(match[2])));
  EXPECT_TRUE(
      contains(html, "fit with n fixed at 3/2, c and b free: c = " + std::string(match[5])));
}

void check_PageRendersInHeadlessChromium() {
  ASSERT_EQ(std::system("command -v chromium >/dev/null 2>&1"), 0)
      << "chromium is not installed: the rendering of the report cannot be checked. Install "
         "it (Debian package 'chromium'; CI installs it).";
  const fs::path screenshot = ReportOfCampaign::output() / "screenshot.png";
  const fs::path profile = ReportOfCampaign::output() / "chromium-profile";
  fs::create_directories(profile);
  const CliRun render = run_command(
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
          quote(profile.string()) + " --screenshot=" + quote(screenshot.string()) +
          " --window-size=1200,3000 " +
          quote("file://" + (ReportOfCampaign::output() / "report.html").string()),
      *ReportOfCampaign::directory);
  ASSERT_TRUE(fs::exists(screenshot))
      << "no screenshot (exit " << render.exit_code << "): " << render.err;
  const PngSize size = png_size(read_text(screenshot));
  ASSERT_TRUE(size.valid);
  EXPECT_EQ(size.width, 1200u);
  EXPECT_EQ(size.height, 3000u);
  // Not blank: many distinct colours and a good share of non-white pixels.
  const CliRun analysis =
      run_command(quote(IMPACT_REPORT_PYTHON) + " -c " +
                      quote(
                          "import sys, numpy, matplotlib.image as image\n"
                          "a = numpy.round(image.imread(sys.argv[1])[..., :3] * 255).astype(int)\n"
                          "p = a.reshape(-1, 3)\n"
                          "print(len(numpy.unique(p[:, 0] * 65536 + p[:, 1] * 256 + p[:, 2])),"
                          " float((p.min(axis=1) < 240).mean()))") +
                      " " + quote(screenshot.string()),
                  *ReportOfCampaign::directory);
  ASSERT_EQ(analysis.exit_code, 0) << analysis.err;
  std::stringstream numbers(analysis.out);
  int colours = 0;
  double ink = 0;
  numbers >> colours >> ink;
  EXPECT_GT(colours, 100) << "the screenshot looks blank";
  EXPECT_GT(ink, 0.02) << "the screenshot looks blank";
}

// The first screen at 1280 x 900: the page measured by Chromium itself (a copy of the page
// with a script that writes the measurements into it, read back with --dump-dom): the page is
// no wider than the window, no table, code block or figure is wider than its box (with every
// section opened), and the first figure and the recommended model's parameters end above the
// window's lower edge with every section folded. A screenshot of that screen is kept beside
// the report (IMPACT_REPORT_TEST_KEEP) to look at.
void check_FirstScreenAt1280Pixels() {
  const fs::path page = ReportOfCampaign::output() / "report.html";
  const fs::path probe = ReportOfCampaign::output() / "report_measured.html";
  const std::string script =
      "<script>(function () {\n"
      "  function bottom(e) { return e ? e.getBoundingClientRect().bottom + window.scrollY : -1; "
      "}\n"
      "  var m = {figure: bottom(document.querySelector('img')),\n"
      "           parameters: bottom(document.querySelector('pre')),\n"
      "           folded: document.querySelectorAll('details:not([open])').length,\n"
      "           height: window.innerHeight, viewport: document.documentElement.clientWidth};\n"
      "  document.querySelectorAll('details').forEach(function (d) { d.open = true; });\n"
      "  m.width = document.documentElement.scrollWidth;\n"
      "  m.boxes = 0; m.sideways = 0;\n"
      "  document.querySelectorAll('table, pre, img').forEach(function (e) {\n"
      "    m.boxes++;\n"
      "    if (e.scrollWidth > e.clientWidth + 1 ||\n"
      "        e.getBoundingClientRect().right > m.viewport) m.sideways++;\n"
      "  });\n"
      "  var out = document.createElement('div'); out.id = 'measured';\n"
      // The markers split, so that the script's own text does not hold them.
      "  out.textContent = 'MEAS' + 'URED' + JSON.stringify(m) + 'E' + 'ND';\n"
      "  document.body.appendChild(out);\n"
      "})();</script>\n";
  std::string html = read_text(page);
  const std::size_t end = html.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  html.insert(end, script);
  std::ofstream(probe) << html;
  const fs::path profile = ReportOfCampaign::output() / "chromium-profile";
  fs::create_directories(profile);
  const std::string chromium =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
      quote(profile.string()) + " --window-size=1280,900 ";
  const CliRun dump = run_command(chromium + "--dump-dom " + quote("file://" + probe.string()),
                                  *ReportOfCampaign::directory);
  const std::size_t from = dump.out.find("MEASURED"), to = dump.out.find("END", from);
  ASSERT_TRUE(from != std::string::npos && to != std::string::npos)
      << "no measurements (exit " << dump.exit_code << "): " << dump.err;
  const json m = json::parse(dump.out.substr(from + 8, to - from - 8));
  SCOPED_TRACE(m.dump());
  EXPECT_GT(m["folded"].get<int>(), 10) << "the sections are not folded";
  EXPECT_LE(m["width"].get<double>(), m["viewport"].get<double>()) << "the page scrolls sideways";
  EXPECT_GT(m["boxes"].get<int>(), 20);
  EXPECT_EQ(m["sideways"].get<int>(), 0) << "a table, code block or figure is wider than the page";
  EXPECT_GT(m["figure"].get<double>(), 0);
  EXPECT_LE(m["figure"].get<double>(), m["height"].get<double>())
      << "the first figure is not on the first screen";
  EXPECT_GT(m["parameters"].get<double>(), m["figure"].get<double>());
  EXPECT_LE(m["parameters"].get<double>(), m["height"].get<double>())
      << "the recommended model is not on the first screen";
  const fs::path screenshot = ReportOfCampaign::output() / "first_screen.png";
  run_command(chromium + "--screenshot=" + quote(screenshot.string()) + " " +
                  quote("file://" + page.string()),
              *ReportOfCampaign::directory);
  const PngSize size = png_size(read_text(screenshot));
  EXPECT_TRUE(size.valid && size.width == 1280u && size.height == 900u);
}

TEST(ReportOfCampaign, IsCompleteHoldsTheCalibrationAndRenders) {
  ReportOfCampaign::make();
  ASSERT_EQ(ReportOfCampaign::calibrate->exit_code, 0) << ReportOfCampaign::calibrate->err;
  ASSERT_EQ(ReportOfCampaign::report->exit_code, 0) << ReportOfCampaign::report->err;
  {
    SCOPED_TRACE("HTML and Markdown exist");
    check_HtmlAndMarkdownExist();
  }
  {
    SCOPED_TRACE("every figure is a valid image");
    check_EveryFigureIsAValidImage();
  }
  {
    SCOPED_TRACE("the tables hold the numbers of the calibration JSON");
    check_TablesHoldTheNumbersOfTheCalibration();
  }
  {
    SCOPED_TRACE("verdict, models, energy and yield");
    check_StatesTheVerdictTheModelsAndTheChecks();
  }
  {
    SCOPED_TRACE("the offsets from Hertz");
    check_StatesTheOffsetsFromHertz();
  }
  {
    SCOPED_TRACE("the page renders in headless Chromium");
    check_PageRendersInHeadlessChromium();
  }
  {
    SCOPED_TRACE("the first screen at 1280 px");
    check_FirstScreenAt1280Pixels();
  }
  ReportOfCampaign::remove();
}

// ---- Bad input ---------------------------------------------------------------------------

class ReportBadInput : public ::testing::Test {
protected:
  void SetUp() override {
    directory = impact::testing::scratch_directory(
        std::string("report_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    campaign = directory / "campaign";
    output = directory / "report";
  }
  void TearDown() override { fs::remove_all(directory); }

  void add_run(double velocity, bool complete = true) {
    write_fem_run(campaign_run(velocity), campaign / ("v" + std::to_string(velocity)), complete);
  }
  CliRun report(std::vector<std::string> extra = {}, const std::string& environment = "") {
    std::vector<std::string> arguments = {"--campaign", campaign.string(), "--output",
                                          output.string(), "--quiet"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return run_tool(IMPACT_REPORT_CLI, arguments, directory, environment);
  }
  // impact-calibrate with --laws lankarani-nikravesh unless `extra` names the laws (an
  // option is given once).
  fs::path calibrate(std::vector<std::string> extra = {}) {
    const fs::path file = directory / "calibration.json";
    std::vector<std::string> arguments = {"--campaign", campaign.string(), "--output",
                                          file.string(), "--quiet"};
    if (std::find(extra.begin(), extra.end(), "--laws") == extra.end())
      arguments.insert(arguments.end(), {"--laws", "lankarani-nikravesh"});
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    run_tool(IMPACT_CALIBRATE_CLI, arguments, directory);
    return file;
  }
  // The report exists in both forms and says it is incomplete, naming `what`.
  void expect_incomplete_report(const std::string& what) {
    const std::string markdown = read_text(output / "report.md");
    const std::string html = read_text(output / "report.html");
    EXPECT_TRUE(contains(markdown, "INCOMPLETE")) << markdown;
    EXPECT_TRUE(contains(markdown, what)) << "'" << what << "' not in:\n" << markdown;
    EXPECT_TRUE(contains(html, "INCOMPLETE"));
  }

  fs::path directory, campaign, output;
};

TEST_F(ReportBadInput, MissingHdf5File) {
  add_run(1.0);
  add_run(2.0);
  add_run(4.0);
  fs::remove(campaign / ("v" + std::to_string(4.0)) / fem_format::history_file);
  // Without an index, a run directory that lost its HDF5 file is found by its summary.json.
  const fs::path calibration = calibrate();
  const CliRun run = report({"--calibration", calibration.string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "but no history.h5")) << run.err;
  expect_incomplete_report("the HDF5 file of the run is missing");
  // The good runs are still reported.
  EXPECT_TRUE(contains(read_text(output / "report.md"), "- Within 2 %:"));
}

TEST_F(ReportBadInput, IncompleteHdf5File) {
  add_run(1.0);
  add_run(2.0);
  add_run(4.0, false);
  const CliRun run = report({"--calibration", calibrate().string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "did not finish")) << run.err;
  expect_incomplete_report("did not finish");
}

TEST_F(ReportBadInput, CampaignWithASingleVelocity) {
  add_run(1.0);
  const CliRun run = report({"--calibration", calibrate().string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "single impact velocity")) << run.err;
  expect_incomplete_report("single impact velocity");
  const std::string markdown = read_text(output / "report.md");
  EXPECT_TRUE(contains(markdown, "Cause: No verdict")) << markdown;
  EXPECT_TRUE(contains(markdown, "Hunt–Crossley (per-run fit)"));
  EXPECT_FALSE(contains(markdown, "- Within 2 %:"));
}

TEST_F(ReportBadInput, RunWithoutContact) {
  add_run(1.0);
  add_run(2.0);
  FemRun no_contact = campaign_run(4.0);
  std::fill(no_contact.contact_force.begin(), no_contact.contact_force.end(), 0.0);
  write_fem_run(no_contact, campaign / "v4");
  const CliRun run = report({"--calibration", calibrate().string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "no contact")) << run.err;
  expect_incomplete_report("no contact");
}

TEST_F(ReportBadInput, FitThatDoesNotConverge) {
  add_run(1.0);
  add_run(2.0);
  impact::testing::HuntCrossleyTruth truth;
  write_fem_run(impact::testing::synthetic_run(truth, 4.0, 0.01), campaign / "v4");
  const fs::path calibration = calibrate({"--max-iterations", "1"});
  const CliRun run = report({"--calibration", calibration.string()});
  EXPECT_EQ(run.exit_code, 3) << run.err;
  EXPECT_TRUE(contains(run.err, "did not converge")) << run.err;
  expect_incomplete_report("did not converge");
  const std::string markdown = read_text(output / "report.md");
  EXPECT_TRUE(contains(markdown, "(not converged)"));
  EXPECT_TRUE(contains(markdown,
                       "Cause: No verdict: the campaign fit of Hunt–Crossley did not "
                       "converge"));
}

TEST_F(ReportBadInput, CalibrationFileMissing) {
  add_run(1.0);
  add_run(2.0);
  const CliRun run = report({"--calibration", (directory / "absent.json").string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "calibration file does not exist")) << run.err;
  expect_incomplete_report("calibration file does not exist");
  EXPECT_TRUE(contains(read_text(output / "report.md"), "Cause: No verdict"));
}

// Nothing written from nothing: without a usable run there is no report, only the message
// why (a missing campaign directory, an empty one).
TEST_F(ReportBadInput, NoUsableRunWritesNothing) {
  const CliRun run = report();
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(contains(run.err, "does not exist")) << run.err;
  EXPECT_TRUE(contains(run.err, "no usable run: nothing was written")) << run.err;
  EXPECT_FALSE(fs::exists(output));
  fs::create_directories(campaign);
  const CliRun empty = report();
  EXPECT_EQ(empty.exit_code, 2) << empty.err;
  EXPECT_TRUE(contains(empty.err, "holds no run")) << empty.err;
  EXPECT_TRUE(contains(empty.err, "no usable run: nothing was written")) << empty.err;
  EXPECT_FALSE(fs::exists(output));
}

TEST_F(ReportBadInput, FiguresThatCannotBeDrawn) {
  add_run(1.0);
  add_run(2.0);
  const CliRun run =
      report({"--calibration", calibrate().string()}, "IMPACT_REPORT_PYTHON=/nonexistent/python3 ");
  EXPECT_EQ(run.exit_code, 4) << run.err;
  EXPECT_TRUE(contains(run.err, "figures could not be drawn")) << run.err;
  expect_incomplete_report("Figure missing");
}

TEST(ReportCli, CalibratesTheCampaignItselfWithoutACalibrationFile) {
  const fs::path directory = impact::testing::scratch_directory("report_self_calibrated");
  for (double v : {0.5, 1.0, 2.0})
    write_fem_run(campaign_run(v), directory / "campaign" / ("v" + std::to_string(v)));
  const CliRun run = run_tool(IMPACT_REPORT_CLI,
                              {"--campaign", (directory / "campaign").string(), "--output",
                               (directory / "report").string(), "--quiet"},
                              directory);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const json calibration = json::parse(read_text(directory / "report" / "calibration.json"));
  EXPECT_EQ(calibration["status"], "complete");
  EXPECT_TRUE(
      contains(read_text(directory / "report" / "report.md"), "calibrated by impact-report"));
  fs::remove_all(directory);
}

// The tolerance bands and the published b are options, not constants of the code.
TEST_F(ReportBadInput, ToleranceBandsAndPublishedDampingAreOptions) {
  add_run(1.0);
  add_run(2.0);
  const fs::path calibration = calibrate({"--laws", "none", "--published-damping", "0.05"});
  const CliRun run = report({"--calibration", calibration.string(), "--tolerances", "1,10"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::string markdown = read_text(output / "report.md");
  EXPECT_TRUE(contains(markdown, "- Within 1 %:")) << markdown;
  EXPECT_TRUE(contains(markdown, "- Within 10 %:"));
  EXPECT_FALSE(contains(markdown, "- Within 2 %:"));
  EXPECT_TRUE(contains(markdown, "Hunt–Crossley (b = 0.05 s/m)"));
  // Two velocities: no out-of-sample errors, and the page says so.
  EXPECT_TRUE(contains(markdown, "The errors are in sample")) << markdown;
  const CliRun bad = report({"--calibration", calibration.string(), "--tolerances", "2,abc"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(contains(bad.err, "--tolerances must be per cents in (0, 100)")) << bad.err;
}

TEST(ReportCli, UsageErrors) {
  const fs::path directory = impact::testing::scratch_directory("report_usage");
  EXPECT_EQ(run_tool(IMPACT_REPORT_CLI, {"--help"}, directory).exit_code, 0);
  const CliRun no_output = run_tool(IMPACT_REPORT_CLI, {"--campaign", "x"}, directory);
  EXPECT_EQ(no_output.exit_code, 2);
  EXPECT_TRUE(contains(no_output.err, "--output DIR is required"));
  const CliRun unknown =
      run_tool(IMPACT_REPORT_CLI, {"--campaign", "x", "--output", "y", "--nope"}, directory);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(contains(unknown.err, "unknown option '--nope'"));
  fs::remove_all(directory);
}

} // namespace
