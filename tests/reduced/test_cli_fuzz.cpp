// impact-reduced fed random argument sets: every subcommand, starting from valid argument
// sets (each way of giving its inputs) and changing one to four options: a value drawn from
// the ends of the option's interval as --help states it and just beyond them, NaN, +-inf,
// 1e+-300, 5e-324, 0, -1, text, typical values scaled by powers of ten, valid and invalid
// choices; an option removed; an option of the subcommand's --help added. Half the cases
// draw instead the valid set's options anywhere within their intervals. Each run
// must end with exit 0 and only finite numbers in its output, or exit 2 with a message naming
// one of the subcommand's options and nothing on stdout; never exit 1, a signal or a hang.
//
// Bounded and deterministic: IMPACT_CLI_FUZZ_CASES cases (default 360) from seed
// IMPACT_CLI_FUZZ_SEED (default 30). The failures are listed with their command lines;
// IMPACT_CLI_FUZZ_VERBOSE=1 prints every case and its outcome.

#include "cli_fuzz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace impact::testing::fuzz;
using Arguments = std::vector<std::pair<std::string, std::string>>;

// Valid argument sets of each subcommand, one per way of giving its inputs.
const std::vector<std::pair<std::string, Arguments>> valid_sets = {
    {"hc",
     {{"mass", "0.1"},
      {"stiffness", "1.7135e10"},
      {"exponent", "1.5"},
      {"damping", "0.1"},
      {"velocity", "1"}}},
    {"hc",
     {{"sphere-modulus", "2e11"},
      {"sphere-poisson", "0.25"},
      {"radius", "0.01452"},
      {"flat-modulus", "2e11"},
      {"flat-poisson", "0.25"},
      {"sphere-density", "7800"},
      {"damping", "0.1"},
      {"velocity", "1"}}},
    {"hc",
     {{"sphere-modulus", "2e11"},
      {"sphere-poisson", "0.25"},
      {"radius", "0.01452"},
      {"flat", "rigid"},
      {"mass", "0.1"},
      {"damping", "0.5"},
      {"velocity", "2"},
      {"history", "20"}}},
    {"damping", {{"restitution", "0.9"}, {"velocity", "1"}}},
    {"law",
     {{"model", "lankarani-nikravesh"},
      {"restitution", "0.5"},
      {"velocity", "1"},
      {"mass", "0.1"},
      {"stiffness", "1e9"}}},
    {"law",
     {{"model", "kuwabara-kono"},
      {"restitution", "0.8"},
      {"velocity", "1"},
      {"sphere-modulus", "2e11"},
      {"sphere-poisson", "0.3"},
      {"radius", "0.01"},
      {"flat", "rigid"},
      {"sphere-density", "7800"}}},
    {"oscillator",
     {{"mass", "2"},
      {"viscous", "8"},
      {"c1", "800"},
      {"c2", "4000"},
      {"power", "1"},
      {"a0", "0.05"},
      {"count", "10"},
      {"method", "numeric"}}},
    {"oscillator",
     {{"mass", "2"},
      {"viscous", "8"},
      {"c1", "800"},
      {"c2", "-4000"},
      {"power", "2"},
      {"a0", "0.05"},
      {"count", "10"},
      {"method", "lambert"}}},
    {"thin-plate",
     {{"plate-modulus", "2e11"},
      {"plate-poisson", "0.25"},
      {"plate-density", "7800"},
      {"thickness", "0.005"},
      {"stiffness", "1.7135e10"},
      {"exponent", "1.5"},
      {"mass", "0.1"},
      {"damping", "0.1"},
      {"velocity", "0.5,1,5"}}},
    {"thin-plate",
     {{"plate-modulus", "2e11"},
      {"plate-poisson", "0.25"},
      {"plate-density", "7800"},
      {"thickness", "0.005"},
      {"sphere-modulus", "2e11"},
      {"sphere-poisson", "0.25"},
      {"radius", "0.01452"},
      {"sphere-density", "7800"},
      {"velocity", "1"}}},
    {"plastic",
     {{"model", "thornton"},
      {"radius", "0.01"},
      {"density", "7800"},
      {"modulus", "2.1e11"},
      {"poisson", "0.3"},
      {"yield-strength", "1e9"},
      {"velocity", "0.1,1,5"}}},
    {"plastic",
     {{"model", "jackson-green"},
      {"radius", "0.01"},
      {"mass", "0.05"},
      {"modulus", "2.1e11"},
      {"poisson", "0.3"},
      {"flat", "rigid"},
      {"yield-strength", "1e9"},
      {"velocity", "2"},
      {"unloading", "brake"}}},
    {"plastic",
     {{"model", "thornton"},
      {"radius", "0.01"},
      {"density", "7800"},
      {"modulus", "2.1e11"},
      {"poisson", "0.3"},
      {"flat-modulus", "7e10"},
      {"flat-poisson", "0.33"},
      {"yield-strength", "1e9"},
      {"velocity", "1"},
      {"loop", "20"}}},
};

const std::vector<std::string> special_values = {"nan",    "-nan",
                                                 "NaN",    "inf",
                                                 "-inf",   "1e300",
                                                 "-1e300", "1e-300",
                                                 "5e-324", "-5e-324",
                                                 "1e308",  "1.7976931348623157e308",
                                                 "0",      "-0",
                                                 "-1",     "1e400",
                                                 "abc",    "",
                                                 " 1",     "0x10",
                                                 "1,2",    "2.2250738585072014e-308"};
const std::vector<std::string> word_values = {"rigid",
                                              "json",
                                              "csv",
                                              "thornton",
                                              "jackson-green",
                                              "brake",
                                              "johnson",
                                              "numeric",
                                              "implicit",
                                              "lambert",
                                              "lambert-approx",
                                              "tsuji",
                                              "kelvin-voigt",
                                              "kuwabara-kono-no-tension",
                                              "hertz",
                                              "1",
                                              "2",
                                              "3",
                                              "10",
                                              "10000",
                                              "100000",
                                              "-5",
                                              "1e3"};

// An option as the usage of its subcommand describes it: its name and, for a number in an
// interval, the interval's ends.
struct DeclaredOption {
  std::string name;
  std::optional<std::pair<double, double>> interval;
};

// The options of a subcommand, read from its usage.
std::vector<DeclaredOption> options_in_usage(const std::string& command, const fs::path& scratch) {
  const Outcome usage = run_bounded(IMPACT_REDUCED_CLI, {command, "--help"}, scratch, 30);
  EXPECT_EQ(usage.exit_code, 0) << command << " --help: " << usage.err;
  std::vector<DeclaredOption> options;
  std::stringstream lines(usage.out);
  std::string line;
  const std::regex option_line(R"(^  --([a-z0-9-]+).*)");
  const std::regex interval(R"(a number in [\[(]([-+0-9.e]+), ([-+0-9.e]+)[\])])");
  std::smatch match;
  while (std::getline(lines, line)) {
    if (std::regex_match(line, match, option_line))
      options.push_back({match[1], std::nullopt});
    else if (!options.empty() && std::regex_search(line, match, interval))
      options.back().interval = std::make_pair(std::stod(match[1]), std::stod(match[2]));
  }
  return options;
}

// A value for an option whose valid value was `valid`: often at or just beyond the ends of
// its interval, else a special value, a word, or the valid value scaled by a power of ten.
std::string random_value(std::mt19937_64& random, const std::string& valid,
                         const std::optional<std::pair<double, double>>& interval) {
  const std::size_t kind = pick(random, 12);
  if (kind < 6 && interval) {
    const auto [lower, upper] = *interval;
    switch (pick(random, 8)) {
      case 0:
        return number_text(lower);
      case 1:
        return number_text(upper);
      case 2:
        return number_text(std::nextafter(lower, -HUGE_VAL));
      case 3:
        return number_text(std::nextafter(upper, HUGE_VAL));
      default: {
        const double fraction = static_cast<double>(pick(random, 1001)) / 1000;
        return number_text(lower > 0 ? lower * std::pow(upper / lower, fraction)
                                     : lower + (upper - lower) * fraction);
      }
    }
  }
  if (kind < 8) return pick_from(random, special_values);
  if (kind < 9) return pick_from(random, word_values);
  char* end = nullptr;
  const double number = std::strtod(valid.c_str(), &end);
  const bool numeric = !valid.empty() && end == valid.c_str() + valid.size() && number != 0;
  const double base = numeric ? number : 1.0;
  // The valid value scaled by 10^k: near it (|k| <= 30) or far (|k| up to 320).
  const int span = kind < 11 ? 30 : 320;
  const int power = static_cast<int>(pick(random, 2 * span + 1)) - span;
  const double sign = pick(random, 8) == 0 ? -1.0 : 1.0;
  std::string value = number_text(sign * base * std::pow(10.0, power));
  if (pick(random, 6) == 0) value += "," + number_text(base); // a list
  return value;
}

const DeclaredOption& find_option(const std::vector<DeclaredOption>& options,
                                  const std::string& name) {
  static const DeclaredOption unknown{"", std::nullopt};
  for (const auto& option : options)
    if (option.name == name) return option;
  return unknown;
}

struct Case {
  std::string command;
  std::vector<std::string> arguments;
};

Case random_case(std::mt19937_64& random,
                 const std::map<std::string, std::vector<DeclaredOption>>& declared) {
  const auto& [command, valid] = pick_from(random, valid_sets);
  Arguments arguments = valid;
  // Half the cases: every option with an interval, with probability 1/2, at an end of it or
  // anywhere inside (log-uniform for positive ones), to find the combinations of valid values
  // that the computation does not survive.
  const bool within = pick(random, 2) == 0;
  for (auto& [name, value] : arguments) {
    const auto& interval = find_option(declared.at(command), name).interval;
    if (!within || !interval || pick(random, 2) == 0) continue;
    const auto [lower, upper] = *interval;
    const std::size_t where = pick(random, 6);
    const double fraction = static_cast<double>(pick(random, 1001)) / 1000;
    value = number_text(where == 0   ? lower
                        : where == 1 ? upper
                        : lower > 0  ? lower * std::pow(upper / lower, fraction)
                                     : lower + (upper - lower) * fraction);
  }
  const std::size_t changes = within ? pick(random, 2) : 1 + pick(random, 4);
  for (std::size_t k = 0; k < changes; ++k) {
    const std::size_t what = pick(random, 20);
    if (what < 12 && !arguments.empty()) { // a new value
      auto& [name, value] = arguments[pick(random, arguments.size())];
      value = random_value(random, value, find_option(declared.at(command), name).interval);
    } else if (what < 15 && !arguments.empty()) { // an option removed
      arguments.erase(arguments.begin() + static_cast<long>(pick(random, arguments.size())));
    } else { // an option of the usage added (or given again)
      const DeclaredOption& option = pick_from(random, declared.at(command));
      const std::string& name = option.name;
      const auto same = std::find_if(arguments.begin(), arguments.end(),
                                     [&](const auto& entry) { return entry.first == name; });
      const std::string value =
          random_value(random, same == arguments.end() ? "1" : same->second, option.interval);
      if (same != arguments.end() && pick(random, 4) != 0)
        same->second = value;
      else
        arguments.emplace_back(name, value);
    }
  }
  Case result{command, {command}};
  for (const auto& [name, value] : arguments) {
    // Both spellings of an option: --name value and --name=value.
    if (pick(random, 5) == 0) {
      result.arguments.push_back("--" + name + "=" + value);
    } else {
      result.arguments.push_back("--" + name);
      result.arguments.push_back(value);
    }
  }
  return result;
}

// Empty if the outcome keeps the contract, else what is wrong.
std::string contract_problem(const Outcome& outcome, const std::vector<DeclaredOption>& options) {
  if (outcome.timed_out) return "no answer within the time limit";
  if (outcome.signal) return "ended by signal " + std::to_string(outcome.signal);
  if (outcome.exit_code == 0) return output_problem(outcome.out);
  if (outcome.exit_code == 2) {
    if (!outcome.out.empty()) return "exit 2 with output on stdout";
    for (const auto& option : options)
      if (outcome.err.find("--" + option.name) != std::string::npos) return "";
    if (outcome.err.find("unexpected argument") != std::string::npos) return "";
    return "exit 2 without naming an option: " + outcome.err;
  }
  return "exit " + std::to_string(outcome.exit_code) + ": " + outcome.err;
}

TEST(ReducedCliFuzz, EveryInputGetsAFiniteAnswerOrExitTwoNamingTheOption) {
  const fs::path scratch =
      fs::temp_directory_path() / ("impact_reduced_cli_fuzz_" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  std::map<std::string, std::vector<DeclaredOption>> declared;
  for (const auto& [command, valid] : valid_sets) {
    if (declared.count(command)) continue;
    declared[command] = options_in_usage(command, scratch);
    // The usage lists every option of the valid sets.
    for (const auto& [name, value] : valid)
      EXPECT_EQ(find_option(declared[command], name).name, name)
          << command << " --help does not list --" << name;
  }
  // The valid sets themselves are answered.
  for (const auto& [command, valid] : valid_sets) {
    std::vector<std::string> arguments = {command};
    for (const auto& [name, value] : valid) {
      arguments.push_back("--" + name);
      arguments.push_back(value);
    }
    const Outcome outcome = run_bounded(IMPACT_REDUCED_CLI, arguments, scratch, 60);
    EXPECT_EQ(outcome.exit_code, 0) << shown(IMPACT_REDUCED_CLI, arguments) << ": " << outcome.err;
  }

  const unsigned long cases = setting("IMPACT_CLI_FUZZ_CASES", 360);
  const bool verbose = setting("IMPACT_CLI_FUZZ_VERBOSE", 0) != 0; // every case and outcome
  std::mt19937_64 random(setting("IMPACT_CLI_FUZZ_SEED", 30));
  std::map<std::string, int> answered, refused;
  std::vector<std::string> failures;
  double slowest = 0;
  std::string slowest_case;
  for (unsigned long i = 0; i < cases; ++i) {
    const Case fuzz_case = random_case(random, declared);
    const Outcome outcome = run_bounded(IMPACT_REDUCED_CLI, fuzz_case.arguments, scratch, 60);
    const std::string problem = contract_problem(outcome, declared.at(fuzz_case.command));
    const std::string text = shown(IMPACT_REDUCED_CLI, fuzz_case.arguments);
    if (verbose)
      std::printf("%d %s\n    %s", outcome.exit_code, text.c_str(),
                  outcome.exit_code == 0 ? "answered\n" : outcome.err.c_str());
    if (outcome.seconds > slowest) {
      slowest = outcome.seconds;
      slowest_case = text;
    }
    if (!problem.empty())
      failures.push_back(text + "\n    " + problem);
    else if (outcome.exit_code == 0)
      ++answered[fuzz_case.command];
    else
      ++refused[fuzz_case.command];
  }
  fs::remove_all(scratch);
  std::string counts;
  for (const auto& [command, options] : declared)
    counts += " " + command + " " + std::to_string(answered[command]) + "/" +
              std::to_string(refused[command]);
  std::printf("%lu cases (answered/refused by command:%s), %zu failures; slowest %.2f s: %s\n",
              cases, counts.c_str(), failures.size(), slowest, slowest_case.c_str());
  for (const auto& failure : failures) ADD_FAILURE() << failure;
}

} // namespace
