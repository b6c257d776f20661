#pragma once
/// @file
/// A problem met while reading runs, calibrating, building or drawing the report: one type for
/// every component, with its kind as an enum. The kinds decide everything that depends on a
/// problem (whether the result is complete, the exit code of the tools, error or warning);
/// the message is only ever shown, never tested.

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impact::postprocess {

enum class ProblemKind {
  input,       ///< a run or file missing or unusable, a campaign that cannot be fitted
  no_rebound,  ///< a complete run in which the sphere did not rebound: a finding, listed
  quality,     ///< the FEM history itself is not clean: a warning, the result is complete
  convergence, ///< a fit did not converge (its numbers are marked so)
  figures      ///< the report's figures could not be drawn
};

/// The kind's name in the calibration JSON and on the page: "input", "no rebound",
/// "quality", "convergence", "figures".
std::string_view kind_name(ProblemKind kind);
/// The kind of a name of kind_name; none for any other text.
std::optional<ProblemKind> kind_from_name(std::string_view name);
/// The kinds after which the result is still complete (no_rebound, quality).
bool is_warning(ProblemKind kind);
std::ostream& operator<<(std::ostream& out, ProblemKind kind);

struct Problem {
  std::string source; ///< the file, run, directory or model concerned ("" if none)
  ProblemKind kind;
  std::string message; ///< a sentence naming the problem
};

/// Whether every problem is a warning (the result is complete).
bool complete(const std::vector<Problem>& problems);

/// The exit code of the tools for these problems: 2 when one is of kind input, else 3 when one
/// is of kind convergence, else 4 when one is of kind figures, else 0.
int exit_code(const std::vector<Problem>& problems);

} // namespace impact::postprocess
