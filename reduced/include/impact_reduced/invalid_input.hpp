#pragma once
/// @file
/// The one error type of the reduced library: a parameter outside its valid range.

#include <stdexcept>
#include <string>

namespace impact::reduced {

/// Thrown by every public function that receives a parameter outside its valid range
/// or a non-finite value. `parameter()` names the offending parameter as the caller
/// knows it (e.g. "mass"), `what()` is a full sentence with the allowed range and the
/// received value. The library never returns NaN for invalid input; it throws this.
class InvalidInput : public std::invalid_argument {
public:
  InvalidInput(std::string parameter, const std::string& message);
  const std::string& parameter() const noexcept { return parameter_; }

private:
  std::string parameter_;
};

/// Throws InvalidInput unless `value` is finite and > 0.
void require_positive(const char* parameter, double value);
/// Throws InvalidInput unless `value` is finite and >= 0.
void require_non_negative(const char* parameter, double value);
/// Throws InvalidInput unless `value` is finite and lower < value < upper.
void require_open_interval(const char* parameter, double value, double lower, double upper);
/// Throws InvalidInput unless `value` is finite.
void require_finite(const char* parameter, double value);

} // namespace impact::reduced
