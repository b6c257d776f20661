// The number formats of postprocess/ (number_format.hpp).

#include "impact_postprocess/number_format.hpp"

#include <cmath>
#include <cstdio>

namespace impact::postprocess {

std::string cell(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string percent_cell(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%+.3g %%", fraction * 100);
  return text;
}

std::string unsigned_percent(double fraction) {
  if (!std::isfinite(fraction)) return "not known";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", fraction * 100);
  return text;
}

std::string short_number(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
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
