#pragma once

#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <string>

namespace impact_fem
{
  /**
   * A number as a reader would write it: "1.5", "2.5575534e-05", "-1e+08":
   * the fewest significant digits that read back as the same double.
   * std::to_string prints six fixed decimals, so a length of 5e-8 m or a
   * tolerance of 1e-8 would read "0.000000": a message that refuses an entry
   * must show what was given. The postprocess exports use it too: a contact
   * constant written for another simulator must reproduce the double.
   */
  inline std::string
  as_written(const double x)
  {
    std::string text;
    for (int digits = 1; digits <= 17; ++digits)
      {
        std::ostringstream s;
        s << std::setprecision(digits) << x;
        text = s.str();
        if (std::strtod(text.c_str(), nullptr) == x)
          break;
      }
    return text;
  }
} // namespace impact_fem
