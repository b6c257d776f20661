// The number formats of postprocess/ (number_format.hpp).

#include "impact_postprocess/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace impact::postprocess {

std::string significant(double value, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string cell(double value) {
  return std::isfinite(value) ? significant(value, 6) : "n/a";
}

std::string percent_cell(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  return (std::signbit(fraction) ? "" : "+") + significant(fraction * 100, 3) + " %";
}

std::string unsigned_percent(double fraction) {
  return std::isfinite(fraction) ? significant(fraction * 100, 3) + " %" : "not known";
}

std::string short_number(double value, int digits) {
  return std::isfinite(value) ? significant(value, digits) : "n/a";
}

std::string band_name(double tolerance) {
  return short_number(tolerance * 100) + " %";
}

std::string velocity_label(double velocity) {
  return "V = " + short_number(velocity) + " m/s";
}

std::string velocity_list(const std::vector<double>& velocities) {
  std::string text;
  for (std::size_t i = 0; i < velocities.size(); ++i)
    text += (i == 0                       ? ""
             : i + 1 == velocities.size() ? " and "
                                          : ", ") +
            short_number(velocities[i]);
  return text + " m/s";
}

} // namespace impact::postprocess
