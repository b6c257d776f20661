#pragma once
// A law of the calibration in words (glance_section.cpp): the block to copy, where it holds,
// what keeps it out, its largest error. The first screen and the block for a multibody code
// use them.

#include "impact_postprocess/report/report.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

/// A law of the calibration in a form to copy (glance_section.cpp): its name and origin, its
/// force law, and each parameter's symbol, value and unit.
struct LawBlock {
  struct Parameter {
    std::string name;
    double value;
    std::string unit;
  };
  bool found = false; ///< the calibration holds the law
  std::string name;
  std::string law;
  std::vector<Parameter> parameters;
};
LawBlock law_block(const Report& report, const std::string& key);
/// heading + name, then the law and one parameter per line, "  c = 1.2e+10 N/m^1.5".
std::string law_block_text(const std::string& heading, const LawBlock& block);
/// "its largest error is -12.3 % (peak approach x_max at V = 5 m/s)".
std::string largest_error(const Report& report, const JudgedLaw& law);
/// What keeps a law out of the band, by quantity and cause: "1 - e^2 at V = 2 m/s (held out:
/// -4.63 % in the fit to every velocity; the fit without 2 m/s moves Y from 1.796e+09 to
/// 1.841e+09 Pa), F_max at V = 5 m/s (the law's shape: -6.5 % even in the fit to every
/// velocity)".
std::string breaking_text(const Report& report, const JudgedLaw& law);
/// The hardening the runs record that the law's elastic-plastic spring leaves out ("the
/// Plate's Johnson-Cook B = 2.75e+08 Pa, C = 0.022"); "" when the law has no such spring or the
/// runs record none.
std::string hardening_left_out_by(const Report& report, const JudgedLaw& law);
/// Where a law is within the band: "over the whole tested range, V = 0.5 to 5 m/s" or
/// "at V = 0.5 to 1 and 3 to 5 m/s".
std::string where_within(const Report& report, const JudgedLaw& law);
/// "Label (key)".
std::string law_name(const JudgedLaw& law);
/// The velocities of report runs.
std::vector<double> velocities_of(const Report& report, const std::vector<std::size_t>& runs);

} // namespace impact::postprocess::detail
