// draw_figures_with_python (pipeline.hpp): the figure data written as JSON, drawn by
// report_figures.py. C++ computes every number; the script only draws.

#include "impact_postprocess/report/pipeline.hpp"

#include <cstdlib>
#include <fstream>
#include <string>

#include <sys/wait.h>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The figure script: installed beside the executable's share directory, else in the source
// tree the library was built from.
fs::path figure_script() {
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed =
        executable.parent_path().parent_path() / "share" / "impact" / "report_figures.py";
    if (fs::exists(installed)) return installed;
  }
  return IMPACT_REPORT_FIGURE_SCRIPT;
}

std::string python_interpreter() {
  const char* chosen = std::getenv("IMPACT_REPORT_PYTHON");
  return chosen && *chosen ? chosen : IMPACT_REPORT_PYTHON;
}

// The last non-empty line of the log: it says what failed.
std::string last_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, message;
  while (std::getline(in, line))
    if (!line.empty()) message = line;
  return message;
}

} // namespace

std::vector<Problem> draw_figures_with_python(const Report& report, const fs::path& output,
                                              const fs::path& figures) {
  const auto expected = report_figures(report);
  if (expected.empty()) return {};
  fs::create_directories(figures);
  for (const auto& figure : expected) fs::remove(figures / figure.file); // no stale image
  const fs::path data = output / "report_data.json";
  {
    std::ofstream out(data);
    out << figure_specification(report).dump() << '\n';
    if (!out) return {{data.string(), ProblemKind::figures, "cannot write the figure data file"}};
  }
  const fs::path log = output / "figures.log";
  const std::string python = python_interpreter();
  const fs::path script = figure_script();
  const std::string command = shell_quote(python) + " " + shell_quote(script.string()) + " " +
                              shell_quote(data.string()) + " " + shell_quote(figures.string()) +
                              " >" + shell_quote(log.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::vector<Problem> problems;
  if (code != 0) {
    const std::string message = last_line(log);
    problems.push_back({script.string(), ProblemKind::figures,
                        "the figures could not be drawn (" + python + " " + script.string() +
                            " exited with " + std::to_string(code) + ": " +
                            (message.empty() ? "no message" : message) +
                            "); install python3-matplotlib or set IMPACT_REPORT_PYTHON"});
  }
  for (const auto& figure : expected)
    if (!fs::exists(figures / figure.file) || fs::file_size(figures / figure.file) == 0)
      problems.push_back(
          {(figures / figure.file).string(), ProblemKind::figures, "the figure was not drawn"});
  return problems;
}

} // namespace impact::postprocess
