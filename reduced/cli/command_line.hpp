#pragma once
// Parsing and validation of `--name value` options: the command-line framework of the
// project's tools (impact-reduced, impact-calibrate, impact-report, impact-export).

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::cli {

/// Bad command-line input: the tool prints the message and exits with code 2.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The allowed values of a real option.
struct Range {
  double lower;
  double upper;
  bool lower_included;
  bool upper_included;

  static Range positive();      // (0, inf)
  static Range non_negative();  // [0, inf)
  static Range finite();        // (-inf, inf)
  static Range open(double lower, double upper);
  static Range closed(double lower, double upper);

  bool contains(double value) const;
  std::string describe() const;
};

/// The options of one subcommand. Every accessor validates the value and throws
/// UsageError naming the option and its allowed range; `finish()` rejects options
/// that no accessor asked for, so that a misspelt option is never silently ignored.
class CommandLine {
public:
  /// Options only: `--name value` or `--name=value`.
  CommandLine(std::string command, const std::vector<std::string>& arguments);
  /// Options, the `flags` (options without a value, such as --quiet), and operands (words
  /// that are not options, such as input files), in any order.
  struct Syntax {
    std::vector<std::string> flags;
    bool operands = false;
  };
  CommandLine(std::string command, const std::vector<std::string>& arguments,
              const Syntax& syntax);

  const std::string& command() const { return command_; }
  bool has(const std::string& name) const;

  double real(const std::string& name, const Range& range);
  double real(const std::string& name, const Range& range, double fallback);
  long integer(const std::string& name, long lower, long upper);
  long integer(const std::string& name, long lower, long upper, long fallback);
  std::string choice(const std::string& name, const std::vector<std::string>& allowed,
                     const std::string& fallback);
  std::string choice(const std::string& name, const std::vector<std::string>& allowed);
  /// Comma-separated list of reals, each within `range`.
  std::vector<double> reals(const std::string& name, const Range& range);
  /// A text (a path, a list of names), checked by the caller; none when not given.
  std::optional<std::string> text(const std::string& name);
  /// Whether the flag (Syntax::flags) is given.
  bool flag(const std::string& name);
  /// The operands, in order (Syntax::operands).
  const std::vector<std::string>& operands() const { return operands_; }

  void finish() const;

private:
  std::optional<std::string> take(const std::string& name);
  [[noreturn]] void fail(const std::string& name, const std::string& problem) const;

  void add(const std::string& name, std::optional<std::string> value);

  std::string command_;
  std::map<std::string, std::optional<std::string>> values_; ///< none: given without a value
  std::vector<std::string> operands_;
  std::map<std::string, bool> used_;
};

} // namespace impact::cli
