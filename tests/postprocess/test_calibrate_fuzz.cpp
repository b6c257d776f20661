// impact-calibrate on damaged JSON: a valid campaign (three runs written like impact-fem's,
// with their summary.json, and the campaign's index.json), one of its JSON files damaged per
// case: truncated, a bit flipped, a key deleted, a value replaced by one of another type or an
// extreme number, a key added, emptied, removed. impact-calibrate --campaign must end with
// exit 0 and a calibration JSON whose numbers are finite, exit 3 (a fit did not converge, the
// JSON written and saying so), or exit 2 with a message naming the damaged file or run; never
// exit 1, a signal or a hang.
//
// Bounded and deterministic: IMPACT_CALIBRATE_FUZZ_CASES cases (default 40) from seed
// IMPACT_CALIBRATE_FUZZ_SEED (default 30); IMPACT_CALIBRATE_FUZZ_VERBOSE=1 prints each case.

#include "../reduced/cli_fuzz.hpp"
#include "synthetic_runs.hpp"

#include "impact_postprocess/run/fem_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace impact::testing::fuzz;
using json = nlohmann::json;

const std::vector<std::pair<std::string, double>> runs = {{"v0.5", 0.5}, {"v1", 1.0}, {"v2", 2.0}};

// The valid campaign: the runs of the report tests (steel materials and radius recorded) and
// an index listing them.
void write_campaign(const fs::path& directory) {
  json index = {{"runs", json::array()}};
  for (const auto& [name, velocity] : runs) {
    impact::postprocess::write_fem_run(impact::testing::campaign_run(velocity), directory / name);
    index["runs"].push_back({{"velocity", velocity}, {"path", name}});
  }
  std::ofstream(directory / "index.json") << index.dump(2) << '\n';
}

// Pointers to every value of a JSON document, objects and arrays included.
void collect(json& node, std::vector<json*>& values) {
  values.push_back(&node);
  if (node.is_structured())
    for (auto& child : node) collect(child, values);
}

const std::vector<std::string> replacements = {"\"text\"",
                                               "null",
                                               "true",
                                               "[]",
                                               "{}",
                                               "-1",
                                               "0",
                                               "1e308",
                                               "-1e308",
                                               "5e-324",
                                               "1e999",
                                               "\"NaN\"",
                                               "99999999999999999999",
                                               "-0.0",
                                               "[1, 2]",
                                               "{\"path\": 3}",
                                               "\"../v1\"",
                                               "\"\""};
const std::vector<std::string> added_keys = {"axes",        "point",       "runs",
                                             "complete",    "sphere_mass", "contact_velocity",
                                             "restitution", "extra"};

// The damaged text of `text` (a JSON document) and what was done, in words.
std::pair<std::string, std::string> damaged(std::mt19937_64& random, const std::string& text) {
  switch (pick(random, 7)) {
    case 0: { // truncated
      const std::size_t length = pick(random, text.size());
      return {text.substr(0, length), "truncated to " + std::to_string(length) + " bytes"};
    }
    case 1: { // a bit flipped
      std::string flipped = text;
      const std::size_t at = pick(random, text.size());
      const int bit = static_cast<int>(pick(random, 8));
      flipped[at] = static_cast<char>(flipped[at] ^ (1 << bit));
      return {flipped,
              "bit " + std::to_string(bit) + " of byte " + std::to_string(at) + " flipped"};
    }
    case 2: // emptied, or not an object
      return pick(random, 2) ? std::make_pair(std::string(), std::string("emptied"))
                             : std::make_pair(std::string("[]"), std::string("replaced by []"));
    default:
      break;
  }
  json document = json::parse(text);
  std::vector<json*> values;
  collect(document, values);
  // A replaced or added value is written as raw text in place of a marker, so that 1e999 and
  // the like reach the reader as written.
  const std::string marker = "@@fuzz@@";
  const std::string replacement = pick_from(random, replacements);
  std::string what;
  const std::size_t kind = pick(random, 3);
  if (kind == 0) { // a key deleted
    std::vector<std::pair<json*, std::string>> keys;
    for (json* value : values)
      if (value->is_object())
        for (auto item = value->begin(); item != value->end(); ++item)
          keys.emplace_back(value, item.key());
    const auto& [object, key] = pick_from(random, keys);
    object->erase(key);
    return {document.dump(2), "key '" + key + "' deleted"};
  }
  if (kind == 1) { // a value replaced
    json* value = values.at(1 + pick(random, values.size() - 1));
    what = "value " + value->dump().substr(0, 40) + " replaced by " + replacement;
    *value = marker;
  } else { // a key added to an object (or its value replaced)
    std::vector<json*> objects;
    for (json* value : values)
      if (value->is_object()) objects.push_back(value);
    const std::string key = pick_from(random, added_keys);
    (*pick_from(random, objects))[key] = marker;
    what = "key '" + key + "' set to " + replacement;
  }
  std::string text_out = document.dump(2);
  const std::size_t at = text_out.find("\"" + marker + "\"");
  text_out.replace(at, marker.size() + 2, replacement);
  return {text_out, what};
}

TEST(CalibrateCliFuzz, DamagedJsonGetsAnAnswerOrExitTwoNamingTheFile) {
  const fs::path scratch =
      fs::temp_directory_path() / ("impact_calibrate_fuzz_" + std::to_string(::getpid()));
  fs::remove_all(scratch);
  const fs::path valid = scratch / "valid";
  fs::create_directories(valid);
  write_campaign(valid);
  // The JSON files that may be damaged.
  std::vector<fs::path> files = {"index.json"};
  for (const auto& [name, velocity] : runs) files.push_back(fs::path(name) / "summary.json");

  // The valid campaign calibrates.
  const std::vector<std::string> options = {"--laws", "none", "--quiet", "--max-iterations", "50"};
  std::vector<std::string> arguments = {"--campaign", valid.string(), "--output",
                                        (scratch / "valid.json").string()};
  arguments.insert(arguments.end(), options.begin(), options.end());
  const Outcome reference = run_bounded(IMPACT_CALIBRATE_CLI, arguments, scratch, 120);
  ASSERT_EQ(reference.exit_code, 0) << reference.err;

  const unsigned long cases = setting("IMPACT_CALIBRATE_FUZZ_CASES", 40);
  const bool verbose = setting("IMPACT_CALIBRATE_FUZZ_VERBOSE", 0) != 0;
  std::mt19937_64 random(setting("IMPACT_CALIBRATE_FUZZ_SEED", 30));
  int answered = 0, refused = 0, not_converged = 0;
  std::vector<std::string> failures;
  double slowest = 0;
  for (unsigned long i = 0; i < cases; ++i) {
    const fs::path campaign = scratch / "campaign";
    fs::remove_all(campaign);
    fs::copy(valid, campaign, fs::copy_options::recursive);
    const fs::path file = pick_from(random, files);
    std::string what;
    if (pick(random, 12) == 0) {
      fs::remove(campaign / file);
      what = "removed";
    } else {
      auto [text, damage] = damaged(random, read_text(campaign / file));
      std::ofstream(campaign / file, std::ios::trunc) << text;
      what = damage;
    }
    const fs::path output = scratch / "calibration.json";
    fs::remove(output);
    arguments = {"--campaign", campaign.string(), "--output", output.string()};
    arguments.insert(arguments.end(), options.begin(), options.end());
    const Outcome outcome = run_bounded(IMPACT_CALIBRATE_CLI, arguments, scratch, 120);
    slowest = std::max(slowest, outcome.seconds);
    const std::string label = file.string() + " " + what;
    if (verbose)
      std::printf("%d %.2f s  %s\n    %s\n", outcome.exit_code, outcome.seconds, label.c_str(),
                  outcome.err.substr(0, 300).c_str());
    std::string problem;
    if (outcome.timed_out)
      problem = "no answer within the time limit";
    else if (outcome.signal)
      problem = "ended by signal " + std::to_string(outcome.signal);
    else if (outcome.exit_code == 0 || outcome.exit_code == 3) {
      problem = fs::exists(output) ? output_problem(read_text(output)) : "no calibration written";
      (outcome.exit_code == 0 ? answered : not_converged) += problem.empty();
    } else if (outcome.exit_code == 2) {
      const std::string run = file.parent_path().string();
      const bool named = outcome.err.find(file.filename().string()) != std::string::npos ||
                         (!run.empty() && outcome.err.find(run) != std::string::npos) ||
                         outcome.err.find(campaign.string()) != std::string::npos;
      if (!named) problem = "exit 2 without naming the file: " + outcome.err;
      refused += named;
    } else {
      problem = "exit " + std::to_string(outcome.exit_code) + ": " + outcome.err;
    }
    if (!problem.empty()) failures.push_back(label + "\n    " + problem);
  }
  fs::remove_all(scratch);
  std::printf(
      "%lu cases: %d answered, %d not converged (exit 3), %d refused, %zu failures; "
      "slowest %.2f s\n",
      cases, answered, not_converged, refused, failures.size(), slowest);
  for (const auto& failure : failures) ADD_FAILURE() << failure;
}

} // namespace
