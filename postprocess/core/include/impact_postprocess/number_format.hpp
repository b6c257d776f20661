#pragma once
/// @file
/// The number formats of postprocess/, in one place: the cells and sentences of the report,
/// the problems' messages and the exports' headers write their numbers through these.

#include <string>
#include <vector>

namespace impact::postprocess {

/// `digits` significant digits, as printf's "%.*g" writes them (non-finite values as it
/// writes them too): the one rounding of the numbers postprocess/ writes for a reader; the
/// formats below are made of it.
std::string significant(double value, int digits);

/// Six significant digits: enough to compare with the calibration JSON to 1e-5.
std::string cell(double value);
/// "+1.23 %" (three significant digits), "n/a" when not finite.
std::string percent_cell(double fraction);
/// "1.23 %" (three significant digits, no sign), "not known" when not finite.
std::string unsigned_percent(double fraction);
/// Four significant digits (or `digits`), "n/a" when not finite.
std::string short_number(double value, int digits = 4);
/// A tolerance band by its width: "2 %" of 0.02 (short_number of the percentage).
std::string band_name(double tolerance);
/// "V = 1 m/s".
std::string velocity_label(double velocity);
/// "0.5, 1 and 2 m/s".
std::string velocity_list(const std::vector<double>& velocities);

} // namespace impact::postprocess
