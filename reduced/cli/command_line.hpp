#pragma once
// Parsing and validation of `--name value` options: the command-line framework of the
// project's tools (impact-reduced, impact-calibrate, impact-report, impact-export).
//
// A command declares its options once (Option: name, what it takes, its range, its
// default, one line of help). The same declarations check what is given and write the
// usage (usage_of_options), so that --help cannot say something else than what is parsed.

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

  static Range positive();     // (0, inf)
  static Range non_negative(); // [0, inf)
  static Range finite();       // (-inf, inf)
  static Range open(double lower, double upper);
  static Range closed(double lower, double upper);
  /// (lower, upper]
  static Range left_open(double lower, double upper);
  /// [lower, upper)
  static Range right_open(double lower, double upper);

  bool contains(double value) const;
  std::string describe() const;
};

/// One option of a command, as declared. Made by the functions below (real_option, ...),
/// completed by with_default / with_default_note.
struct Option {
  enum class Kind { real, reals, integer, choice, text, flag, heading };
  Kind kind = Kind::heading;
  std::string name;                 ///< without the leading "--"; for a heading, empty
  std::string value_name;           ///< in the usage: --mass M
  std::string help;                 ///< what it is, with its unit; for a heading, the heading
  Range range = Range::finite();    ///< real, reals
  long lower = 0, upper = 0;        ///< integer
  std::vector<std::string> choices; ///< choice
  /// The value used when the option is not given, as it would be written on the command
  /// line ("1.5", "json"); shown in the usage. None: required, or a default that the command
  /// computes (then `default_note` says which).
  std::optional<std::string> fallback;
  std::string default_note;

  /// A constant default, parsed like a given value.
  Option with_default(std::string value) const;
  /// A default the command computes from other options, in words ("the sphere's").
  Option with_default_note(std::string note) const;
  /// "values: ..." of the usage: the range, the choices or the integer bounds.
  std::string allowed() const;
};

Option real_option(std::string name, std::string value_name, Range range, std::string help);
/// A comma-separated list of reals, each within `range`.
Option reals_option(std::string name, std::string value_name, Range range, std::string help);
Option integer_option(std::string name, std::string value_name, long lower, long upper,
                      std::string help);
Option choice_option(std::string name, std::vector<std::string> choices, std::string help);
/// A text (a path, a list of names), checked by the command.
Option text_option(std::string name, std::string value_name, std::string help);
/// An option without a value (--quiet).
Option flag_option(std::string name, std::string help);
/// A line that groups the options after it in the usage.
Option heading(std::string text);

/// The options part of a usage: one entry per option, "--name VALUE  help", then its
/// allowed values and default on the next line; headings as they are.
std::string usage_of_options(const std::vector<Option>& options);

/// `text` broken into lines of at most `width` characters (`indent` spaces included), for the
/// paragraphs of a usage.
std::string wrapped_text(const std::string& text, std::size_t indent = 0, std::size_t width = 92);

/// Whether `arguments` ask for the usage: --help or -h among them.
bool asks_for_help(const std::vector<std::string>& arguments);

/// The options of one subcommand, checked against its declarations: an option that is not
/// declared is refused at once, with the command's name; every accessor validates the value
/// and throws UsageError naming the option and its allowed values; `finish()` rejects
/// declared options that the command did not use with the others given, so that no option
/// is ever silently ignored. Asking for an option that is not declared (or as another kind)
/// is a programming error: std::logic_error.
class CommandLine {
public:
  /// `--name value`, `--name=value`, the declared flags, and, with `operands`, words that
  /// are not options (such as input files), in any order.
  CommandLine(std::string command, const std::vector<std::string>& arguments,
              std::vector<Option> options, bool operands = false);

  const std::string& command() const { return command_; }
  const std::vector<Option>& options() const { return options_; }
  bool has(const std::string& name) const;
  /// The text given for an option of any kind, as given (for messages); empty if none.
  std::string given_text(const std::string& name) const;

  /// The value, or the declared default; UsageError if neither.
  double real(const std::string& name);
  /// The value, or `fallback` when not given (a default computed by the command).
  double real(const std::string& name, double fallback);
  long integer(const std::string& name);
  long integer(const std::string& name, long fallback);
  std::string choice(const std::string& name);
  std::string choice(const std::string& name, const std::string& fallback);
  std::vector<double> reals(const std::string& name);
  /// The text; none when not given.
  std::optional<std::string> text(const std::string& name);
  /// Whether the flag is given.
  bool flag(const std::string& name);
  /// The operands, in order.
  const std::vector<std::string>& operands() const { return operands_; }

  /// UsageError "--name `reason`" if the option is given (it does not go with the others).
  void require_absent(const std::string& name, const std::string& reason);
  /// A quantity that the command computes from other options, where the option `name` could
  /// have given it directly: UsageError unless `value` is within that option's range, the
  /// message "`source` <value>, outside the range of --name: ..." (`source` says which
  /// options it comes from: "the solid sphere of --radius and --sphere-density has a mass").
  void require_within(const std::string& name, double value, const std::string& source) const;

  void finish() const;

private:
  const Option& declared(const std::string& name, Option::Kind kind) const;
  std::optional<std::string> take(const std::string& name, Option::Kind kind);
  [[noreturn]] void fail(const std::string& name, const std::string& problem) const;

  void add(const std::string& name, std::optional<std::string> value);

  std::string command_;
  std::vector<Option> options_;
  std::map<std::string, std::optional<std::string>> values_; ///< none: given without a value
  std::vector<std::string> operands_;
  std::map<std::string, bool> used_;
};

} // namespace impact::cli
