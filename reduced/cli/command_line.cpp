#include "command_line.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace impact::cli {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();

std::string format_number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// Strict conversion: the whole text must be one finite number.
std::optional<double> parse_real(const std::string& text) {
  if (text.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value))
    return std::nullopt;
  return value;
}

std::string integer_allowed(long lower, long upper) {
  return "a whole number in [" + std::to_string(lower) + ", " + std::to_string(upper) + "]";
}

std::string choice_listing(const std::vector<std::string>& choices) {
  std::string listing;
  for (const auto& choice : choices) listing += (listing.empty() ? "" : "|") + choice;
  return listing;
}

Option make(Option::Kind kind, std::string name, std::string value_name, std::string help) {
  Option option;
  option.kind = kind;
  option.name = std::move(name);
  option.value_name = std::move(value_name);
  option.help = std::move(help);
  return option;
}

const char* kind_name(Option::Kind kind) {
  switch (kind) {
    case Option::Kind::real:
      return "real";
    case Option::Kind::reals:
      return "list of reals";
    case Option::Kind::integer:
      return "integer";
    case Option::Kind::choice:
      return "choice";
    case Option::Kind::text:
      return "text";
    case Option::Kind::flag:
      return "flag";
    case Option::Kind::heading:
      return "heading";
  }
  return "?";
}
} // namespace

std::string wrapped_text(const std::string& text, std::size_t indent, std::size_t width) {
  std::istringstream words(text);
  std::string word, line, result;
  while (words >> word) {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
      result += std::string(indent, ' ') + line + '\n';
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) result += std::string(indent, ' ') + line + '\n';
  return result;
}

Range Range::positive() {
  return {0.0, infinity, false, false};
}
Range Range::non_negative() {
  return {0.0, infinity, true, false};
}
Range Range::finite() {
  return {-infinity, infinity, false, false};
}
Range Range::open(double lower, double upper) {
  return {lower, upper, false, false};
}
Range Range::closed(double lower, double upper) {
  return {lower, upper, true, true};
}
Range Range::left_open(double lower, double upper) {
  return {lower, upper, false, true};
}
Range Range::right_open(double lower, double upper) {
  return {lower, upper, true, false};
}

bool Range::contains(double value) const {
  const bool above = lower_included ? value >= lower : value > lower;
  const bool below = upper_included ? value <= upper : value < upper;
  return above && below;
}

std::string Range::describe() const {
  if (upper == infinity && lower == -infinity) return "a finite number";
  if (upper == infinity)
    return std::string("a finite number ") + (lower_included ? ">= " : "> ") + format_number(lower);
  if (lower == -infinity)
    return std::string("a number ") + (upper_included ? "<= " : "< ") + format_number(upper);
  return std::string("a number in ") + (lower_included ? "[" : "(") + format_number(lower) + ", " +
         format_number(upper) + (upper_included ? "]" : ")");
}

Option Option::with_default(std::string value) const {
  Option option = *this;
  option.fallback = std::move(value);
  return option;
}

Option Option::with_default_note(std::string note) const {
  Option option = *this;
  option.default_note = std::move(note);
  return option;
}

std::string Option::allowed() const {
  switch (kind) {
    case Kind::real:
      return range.describe();
    case Kind::reals:
      return "a comma-separated list, each " + range.describe();
    case Kind::integer:
      return integer_allowed(lower, upper);
    case Kind::choice:
      return "one of " + choice_listing(choices);
    case Kind::text:
    case Kind::flag:
    case Kind::heading:
      return "";
  }
  return "";
}

Option real_option(std::string name, std::string value_name, Range range, std::string help) {
  Option option = make(Option::Kind::real, std::move(name), std::move(value_name), std::move(help));
  option.range = range;
  return option;
}

Option reals_option(std::string name, std::string value_name, Range range, std::string help) {
  Option option =
      make(Option::Kind::reals, std::move(name), std::move(value_name), std::move(help));
  option.range = range;
  return option;
}

Option integer_option(std::string name, std::string value_name, long lower, long upper,
                      std::string help) {
  Option option =
      make(Option::Kind::integer, std::move(name), std::move(value_name), std::move(help));
  option.lower = lower;
  option.upper = upper;
  return option;
}

Option choice_option(std::string name, std::vector<std::string> choices, std::string help) {
  Option option =
      make(Option::Kind::choice, std::move(name), choice_listing(choices), std::move(help));
  option.choices = std::move(choices);
  return option;
}

Option text_option(std::string name, std::string value_name, std::string help) {
  return make(Option::Kind::text, std::move(name), std::move(value_name), std::move(help));
}

Option flag_option(std::string name, std::string help) {
  return make(Option::Kind::flag, std::move(name), "", std::move(help));
}

Option heading(std::string text) {
  return make(Option::Kind::heading, "", "", std::move(text));
}

std::string usage_of_options(const std::vector<Option>& options) {
  constexpr std::size_t column = 24, width = 92;
  std::string usage;
  for (const auto& option : options) {
    if (option.kind == Option::Kind::heading) {
      usage += (usage.empty() ? "" : "\n") + wrapped_text(option.help, 0, width);
      continue;
    }
    std::string left = "  --" + option.name;
    if (!option.value_name.empty()) left += " " + option.value_name;
    // A choice lists its values in place of the value's name.
    std::string details = option.kind == Option::Kind::choice ? "" : option.allowed();
    if (option.fallback)
      details += (details.empty() ? "" : "; ") + std::string("default ") + *option.fallback;
    else if (!option.default_note.empty())
      details += (details.empty() ? "" : "; ") + std::string("default: ") + option.default_note;
    std::string right = wrapped_text(option.help, column, width);
    if (!details.empty()) right += wrapped_text("(" + details + ")", column, width);
    if (left.size() + 2 <= column)
      usage += left + right.substr(left.size());
    else
      usage += left + '\n' + right;
  }
  return usage;
}

bool asks_for_help(const std::vector<std::string>& arguments) {
  return std::any_of(arguments.begin(), arguments.end(),
                     [](const std::string& word) { return word == "--help" || word == "-h"; });
}

CommandLine::CommandLine(std::string command, const std::vector<std::string>& arguments,
                         std::vector<Option> options, bool operands)
    : command_(std::move(command)), options_(std::move(options)) {
  const auto find = [this](const std::string& name) {
    return std::find_if(options_.begin(), options_.end(), [&](const Option& option) {
      return option.kind != Option::Kind::heading && option.name == name;
    });
  };
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& word = arguments[i];
    if (word.rfind("--", 0) != 0 || word.size() == 2) {
      if (!operands)
        throw UsageError("unexpected argument '" + word + "' (options are written --name value)");
      operands_.push_back(word);
      continue;
    }
    std::string name = word.substr(2);
    std::optional<std::string> value;
    const auto equals = name.find('=');
    if (equals != std::string::npos) {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
    }
    const auto option = find(name);
    if (option == options_.end())
      throw UsageError("unknown option '--" + name + "' for '" + command_ + "' (--help lists " +
                       "its options)");
    if (option->kind == Option::Kind::flag) {
      if (value) fail(name, "takes no value (got '" + *value + "')");
      value = "";
    } else if (!value && i + 1 < arguments.size() && arguments[i + 1].rfind("--", 0) != 0) {
      value = arguments[++i];
    }
    add(name, value);
  }
}

void CommandLine::add(const std::string& name, std::optional<std::string> value) {
  if (values_.count(name)) throw UsageError("--" + name + " is given twice");
  values_[name] = std::move(value);
  used_[name] = false;
}

const Option& CommandLine::declared(const std::string& name, Option::Kind kind) const {
  for (const auto& option : options_)
    if (option.kind != Option::Kind::heading && option.name == name) {
      if (option.kind != kind)
        throw std::logic_error("option --" + name + " of '" + command_ + "' is declared as a " +
                               kind_name(option.kind) + ", read as a " + kind_name(kind));
      return option;
    }
  throw std::logic_error("option --" + name + " of '" + command_ + "' is read but not declared");
}

bool CommandLine::has(const std::string& name) const {
  return values_.count(name) > 0;
}

std::string CommandLine::given_text(const std::string& name) const {
  const auto found = values_.find(name);
  return found == values_.end() ? "" : found->second.value_or("");
}

std::optional<std::string> CommandLine::take(const std::string& name, Option::Kind kind) {
  const Option& option = declared(name, kind);
  const auto found = values_.find(name);
  if (found == values_.end()) return option.fallback;
  used_[name] = true;
  if (!found->second) fail(name, "needs a value: " + option.allowed());
  return found->second;
}

void CommandLine::fail(const std::string& name, const std::string& problem) const {
  throw UsageError("--" + name + " " + problem);
}

std::optional<std::string> CommandLine::text(const std::string& name) {
  return take(name, Option::Kind::text);
}

bool CommandLine::flag(const std::string& name) {
  declared(name, Option::Kind::flag);
  const bool given = has(name);
  if (given) used_[name] = true;
  return given;
}

void CommandLine::require_absent(const std::string& name, const std::string& reason) {
  if (has(name)) fail(name, reason);
}

void CommandLine::require_within(const std::string& name, double value,
                                 const std::string& source) const {
  const Option& option = declared(name, Option::Kind::real);
  if (!option.range.contains(value))
    throw UsageError(source + " " + format_number(value) + ", outside the range of --" + name +
                     ": " + option.allowed());
}

double CommandLine::real(const std::string& name) {
  const Option& option = declared(name, Option::Kind::real);
  const auto text = take(name, Option::Kind::real);
  if (!text) fail(name, "is required: " + option.allowed());
  const auto value = parse_real(*text);
  if (!value || !option.range.contains(*value))
    fail(name, "must be " + option.allowed() + " (got '" + *text + "')");
  return *value;
}

double CommandLine::real(const std::string& name, double fallback) {
  declared(name, Option::Kind::real);
  return has(name) ? real(name) : fallback;
}

long CommandLine::integer(const std::string& name) {
  const Option& option = declared(name, Option::Kind::integer);
  const auto text = take(name, Option::Kind::integer);
  if (!text) fail(name, "is required: " + option.allowed());
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text->c_str(), &end, 10);
  if (text->empty() || end != text->c_str() + text->size() || errno == ERANGE ||
      value < option.lower || value > option.upper)
    fail(name, "must be " + option.allowed() + " (got '" + *text + "')");
  return value;
}

long CommandLine::integer(const std::string& name, long fallback) {
  declared(name, Option::Kind::integer);
  return has(name) ? integer(name) : fallback;
}

std::string CommandLine::choice(const std::string& name) {
  const Option& option = declared(name, Option::Kind::choice);
  const auto text = take(name, Option::Kind::choice);
  if (!text) fail(name, "is required: " + option.allowed());
  for (const auto& allowed : option.choices)
    if (*text == allowed) return allowed;
  fail(name, "must be " + option.allowed() + " (got '" + *text + "')");
}

std::string CommandLine::choice(const std::string& name, const std::string& fallback) {
  declared(name, Option::Kind::choice);
  return has(name) ? choice(name) : fallback;
}

std::vector<double> CommandLine::reals(const std::string& name) {
  const Option& option = declared(name, Option::Kind::reals);
  const auto text = take(name, Option::Kind::reals);
  if (!text) fail(name, "is required: " + option.allowed());
  std::vector<double> values;
  std::stringstream items(*text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto value = parse_real(item);
    if (!value || !option.range.contains(*value))
      fail(name, "entries must each be " + option.range.describe() + " (got '" + item + "')");
    values.push_back(*value);
  }
  if (values.empty()) fail(name, "must list at least one value: " + option.allowed());
  return values;
}

void CommandLine::finish() const {
  for (const auto& [name, was_used] : used_)
    if (!was_used)
      throw UsageError("--" + name + " does not apply with the other options given to '" +
                       command_ + "' (--help tells which options go together)");
}

} // namespace impact::cli
