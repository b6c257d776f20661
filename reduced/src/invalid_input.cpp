#include "impact_reduced/invalid_input.hpp"

#include <cmath>
#include <sstream>

namespace impact::reduced {

InvalidInput::InvalidInput(std::string parameter, const std::string& message)
    : std::invalid_argument(message), parameter_(std::move(parameter)) {}

namespace {
[[noreturn]] void reject(const char* parameter, double value, const char* allowed) {
  std::ostringstream message;
  message.precision(17);
  message << parameter << " must be " << allowed << " (got " << value << ")";
  throw InvalidInput(parameter, message.str());
}
} // namespace

void require_finite(const char* parameter, double value) {
  if (!std::isfinite(value)) reject(parameter, value, "a finite number");
}

void require_positive(const char* parameter, double value) {
  if (!std::isfinite(value) || !(value > 0)) reject(parameter, value, "a finite number > 0");
}

void require_non_negative(const char* parameter, double value) {
  if (!std::isfinite(value) || !(value >= 0)) reject(parameter, value, "a finite number >= 0");
}

void require_open_interval(const char* parameter, double value, double lower, double upper) {
  if (!std::isfinite(value) || !(value > lower && value < upper)) {
    std::ostringstream allowed;
    allowed.precision(17);
    allowed << "a finite number in (" << lower << ", " << upper << ")";
    reject(parameter, value, allowed.str().c_str());
  }
}

} // namespace impact::reduced
