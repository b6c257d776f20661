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
} // namespace

Range Range::positive() { return {0.0, infinity, false, false}; }
Range Range::non_negative() { return {0.0, infinity, true, false}; }
Range Range::finite() { return {-infinity, infinity, false, false}; }
Range Range::open(double lower, double upper) { return {lower, upper, false, false}; }
Range Range::closed(double lower, double upper) { return {lower, upper, true, true}; }

bool Range::contains(double value) const {
  const bool above = lower_included ? value >= lower : value > lower;
  const bool below = upper_included ? value <= upper : value < upper;
  return above && below;
}

std::string Range::describe() const {
  if (upper == infinity && lower == -infinity) return "a finite number";
  if (upper == infinity)
    return std::string("a finite number ") + (lower_included ? ">= " : "> ") + format_number(lower);
  return std::string("a number in ") + (lower_included ? "[" : "(") + format_number(lower) + ", " +
         format_number(upper) + (upper_included ? "]" : ")");
}

CommandLine::CommandLine(std::string command, const std::vector<std::string>& arguments)
  : CommandLine(std::move(command), arguments, Syntax{}) {}

CommandLine::CommandLine(std::string command, const std::vector<std::string>& arguments,
                         const Syntax& syntax)
  : command_(std::move(command)) {
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& word = arguments[i];
    if (word.rfind("--", 0) != 0 || word.size() == 2) {
      if (!syntax.operands)
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
    } else if (std::find(syntax.flags.begin(), syntax.flags.end(), name) != syntax.flags.end()) {
      value = "";
    } else if (i + 1 < arguments.size() && arguments[i + 1].rfind("--", 0) != 0) {
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

bool CommandLine::has(const std::string& name) const { return values_.count(name) > 0; }

// An option given without a value is reported when it is asked for (it needs one) or by
// finish() (it is not known), whichever comes first.
std::optional<std::string> CommandLine::take(const std::string& name) {
  const auto found = values_.find(name);
  if (found == values_.end()) return std::nullopt;
  used_[name] = true;
  if (!found->second) fail(name, "needs a value");
  return found->second;
}

std::optional<std::string> CommandLine::text(const std::string& name) { return take(name); }

bool CommandLine::flag(const std::string& name) {
  const bool given = has(name);
  if (given) used_[name] = true;
  return given;
}

void CommandLine::fail(const std::string& name, const std::string& problem) const {
  throw UsageError("--" + name + " " + problem);
}

double CommandLine::real(const std::string& name, const Range& range) {
  const auto text = take(name);
  if (!text) fail(name, "is required: " + range.describe());
  const auto value = parse_real(*text);
  if (!value || !range.contains(*value))
    fail(name, "must be " + range.describe() + " (got '" + *text + "')");
  return *value;
}

double CommandLine::real(const std::string& name, const Range& range, double fallback) {
  return has(name) ? real(name, range) : fallback;
}

long CommandLine::integer(const std::string& name, long lower, long upper) {
  const auto text = take(name);
  const std::string allowed =
      "a whole number in [" + std::to_string(lower) + ", " + std::to_string(upper) + "]";
  if (!text) fail(name, "is required: " + allowed);
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text->c_str(), &end, 10);
  if (text->empty() || end != text->c_str() + text->size() || errno == ERANGE || value < lower ||
      value > upper)
    fail(name, "must be " + allowed + " (got '" + *text + "')");
  return value;
}

long CommandLine::integer(const std::string& name, long lower, long upper, long fallback) {
  return has(name) ? integer(name, lower, upper) : fallback;
}

std::string CommandLine::choice(const std::string& name, const std::vector<std::string>& allowed) {
  std::string listing;
  for (const auto& option : allowed) listing += (listing.empty() ? "" : "|") + option;
  const auto text = take(name);
  if (!text) fail(name, "is required: one of " + listing);
  for (const auto& option : allowed)
    if (*text == option) return option;
  fail(name, "must be one of " + listing + " (got '" + *text + "')");
}

std::string CommandLine::choice(const std::string& name, const std::vector<std::string>& allowed,
                                const std::string& fallback) {
  return has(name) ? choice(name, allowed) : fallback;
}

std::vector<double> CommandLine::reals(const std::string& name, const Range& range) {
  const auto text = take(name);
  if (!text) fail(name, "is required: a comma-separated list, each " + range.describe());
  std::vector<double> values;
  std::stringstream items(*text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto value = parse_real(item);
    if (!value || !range.contains(*value))
      fail(name, "entries must each be " + range.describe() + " (got '" + item + "')");
    values.push_back(*value);
  }
  if (values.empty()) fail(name, "must list at least one value");
  return values;
}

void CommandLine::finish() const {
  for (const auto& [name, was_used] : used_)
    if (!was_used) throw UsageError("unknown option '--" + name + "' for '" + command_ + "'");
}

} // namespace impact::cli
