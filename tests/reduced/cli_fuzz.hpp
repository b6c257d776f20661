#pragma once
// Bounded fuzzing of the project's command-line tools: a program is run on an argument list
// (no shell) with a time limit, and its outcome judged by the tools' contract: exit 0 with
// output whose every number is finite, or exit 2 with a message on stderr that names what is
// wrong (and nothing on stdout); never exit 1 (internal error), a signal or a hang.
// Random choices come from std::mt19937_64 (its sequence is fixed by the standard) through
// `pick`, so that a seed gives the same cases on every platform.

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace impact::testing::fuzz {

/// The outcome of one run.
struct Outcome {
  int exit_code = -1; ///< when the program exited
  int signal = 0;     ///< when a signal ended it (SIGKILL also after the time limit)
  bool timed_out = false;
  std::string out, err;
  double seconds = 0;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Runs `program arguments...` with stdout and stderr to files in `scratch`, killed after
/// `time_limit` seconds.
inline Outcome run_bounded(const std::string& program, const std::vector<std::string>& arguments,
                           const std::filesystem::path& scratch, double time_limit) {
  const std::string out_path = (scratch / "fuzz.out").string();
  const std::string err_path = (scratch / "fuzz.err").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  std::vector<std::string> words = {program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  Outcome outcome;
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    outcome.err = "could not start " + program;
    return outcome;
  }
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > time_limit && !outcome.timed_out) {
      outcome.timed_out = true;
      kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  outcome.out = read_text(out_path);
  outcome.err = read_text(err_path);
  return outcome;
}

/// What is wrong with a successful run's output: empty if it is JSON or a CSV table in which
/// every number is finite (an empty CSV field is a value the tool declares absent).
inline std::string output_problem(const std::string& text) {
  const auto first = text.find_first_not_of(" \n\t");
  if (first == std::string::npos) return "no output";
  if (text[first] == '{' || text[first] == '[') {
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
      return std::string("output is not valid JSON: ") + error.what();
    }
    std::vector<const nlohmann::json*> stack = {&json};
    while (!stack.empty()) {
      const nlohmann::json* node = stack.back();
      stack.pop_back();
      if (node->is_number_float() && !std::isfinite(node->get<double>()))
        return "JSON holds a non-finite number";
      if (node->is_structured())
        for (const auto& child : *node) stack.push_back(&child);
    }
    return "";
  }
  std::stringstream lines(text);
  std::string line;
  std::getline(lines, line); // the header
  if (line.empty() || line.find_first_of("0123456789") == 0) return "CSV without a header";
  while (std::getline(lines, line)) {
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) {
      if (field.empty()) continue;
      char* end = nullptr;
      const double value = std::strtod(field.c_str(), &end);
      if (end != field.c_str() + field.size() || !std::isfinite(value))
        return "CSV field '" + field + "' is not a finite number";
    }
  }
  return "";
}

/// Uniform choice in [0, n) from the generator (not std::uniform_int_distribution, whose
/// results differ between standard libraries).
inline std::size_t pick(std::mt19937_64& random, std::size_t n) {
  return static_cast<std::size_t>(random() % n);
}

template <class T>
const T& pick_from(std::mt19937_64& random, const std::vector<T>& values) {
  return values.at(pick(random, values.size()));
}

/// A number as text with every digit.
inline std::string number_text(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

/// An unsigned environment setting, or `fallback`.
inline unsigned long setting(const char* name, unsigned long fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::strtoul(value, nullptr, 10) : fallback;
}

/// A command line as one text, for messages.
inline std::string shown(const std::string& program, const std::vector<std::string>& arguments) {
  std::string text = std::filesystem::path(program).filename().string();
  for (const auto& argument : arguments)
    text += " " + (argument.empty() || argument.find_first_of(" ,'\"") != std::string::npos
                       ? "'" + argument + "'"
                       : argument);
  return text;
}

} // namespace impact::testing::fuzz
