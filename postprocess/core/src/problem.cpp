#include "impact_postprocess/problem.hpp"

#include <algorithm>
#include <array>
#include <ostream>
#include <utility>

namespace impact::postprocess {

namespace {
constexpr std::array<std::pair<ProblemKind, std::string_view>, 5> names = {{
    {ProblemKind::input, "input"},
    {ProblemKind::no_rebound, "no rebound"},
    {ProblemKind::quality, "quality"},
    {ProblemKind::convergence, "convergence"},
    {ProblemKind::figures, "figures"},
}};

bool any_of_kind(const std::vector<Problem>& problems, ProblemKind kind) {
  return std::any_of(problems.begin(), problems.end(),
                     [kind](const Problem& problem) { return problem.kind == kind; });
}
} // namespace

std::string_view kind_name(ProblemKind kind) {
  for (const auto& [known, name] : names)
    if (known == kind) return name;
  return "unknown";
}

std::optional<ProblemKind> kind_from_name(std::string_view name) {
  for (const auto& [kind, known] : names)
    if (known == name) return kind;
  return std::nullopt;
}

bool is_warning(ProblemKind kind) {
  return kind == ProblemKind::no_rebound || kind == ProblemKind::quality;
}

std::ostream& operator<<(std::ostream& out, ProblemKind kind) {
  return out << kind_name(kind);
}

bool complete(const std::vector<Problem>& problems) {
  return std::all_of(problems.begin(), problems.end(),
                     [](const Problem& problem) { return is_warning(problem.kind); });
}

int exit_code(const std::vector<Problem>& problems) {
  if (any_of_kind(problems, ProblemKind::input)) return 2;
  if (any_of_kind(problems, ProblemKind::convergence)) return 3;
  return any_of_kind(problems, ProblemKind::figures) ? 4 : 0;
}

} // namespace impact::postprocess
