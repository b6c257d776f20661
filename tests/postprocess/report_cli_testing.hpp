#pragma once
// What the tests of impact-report share: running a tool as a user does (exit code, stdout,
// stderr) and reading the tables of the Markdown page back.

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace impact::testing {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code;
  std::string out;
  std::string err;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

inline std::string quote(const std::string& text) {
  return "'" + text + "'";
}

inline CliRun run_command(const std::string& command, const fs::path& scratch) {
  const std::string full = command + " >" + quote((scratch / "out.txt").string()) + " 2>" +
                           quote((scratch / "err.txt").string());
  const int status = std::system(full.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(scratch / "out.txt"),
          read_text(scratch / "err.txt")};
}

inline CliRun run_tool(const char* tool, const std::vector<std::string>& arguments,
                       const fs::path& scratch, const std::string& environment = "") {
  std::string command = environment + quote(tool);
  for (const auto& argument : arguments) command += " " + quote(argument);
  return run_command(command, scratch);
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

using MarkdownTable = std::vector<std::vector<std::string>>; // header row first

inline std::vector<std::string> split_row(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (line[i] == '|') {
      const auto begin = cell.find_first_not_of(' ');
      const auto end = cell.find_last_not_of(' ');
      cells.push_back(begin == std::string::npos ? "" : cell.substr(begin, end - begin + 1));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

inline std::vector<MarkdownTable> markdown_tables(const std::string& markdown) {
  std::vector<MarkdownTable> tables;
  std::stringstream stream(markdown);
  std::string line;
  MarkdownTable current;
  while (std::getline(stream, line)) {
    if (line.rfind("|", 0) == 0) {
      if (line.rfind("|---", 0) == 0) continue;
      current.push_back(split_row(line));
    } else if (!current.empty()) {
      tables.push_back(current);
      current.clear();
    }
  }
  if (!current.empty()) tables.push_back(current);
  return tables;
}

// The table whose header starts with these cells.
inline const MarkdownTable* find_table(const std::vector<MarkdownTable>& tables,
                                       const std::vector<std::string>& header_start) {
  for (const auto& table : tables)
    if (table.front().size() >= header_start.size() &&
        std::equal(header_start.begin(), header_start.end(), table.front().begin()))
      return &table;
  return nullptr;
}

inline std::size_t column(const MarkdownTable& table, const std::string& name) {
  for (std::size_t i = 0; i < table.front().size(); ++i)
    if (table.front()[i] == name) return i;
  ADD_FAILURE() << "no column '" << name << "'";
  return 0;
}

inline double cell_number(const std::string& cell) {
  return std::stod(cell);
}

// Six significant digits are printed.
inline void expect_same(double shown, double expected, const std::string& what) {
  EXPECT_NEAR(shown, expected, 1e-5 * std::abs(expected)) << what;
}

} // namespace impact::testing
