#ifndef IMPACT_FEM_PARAMETER_PATH_H
#define IMPACT_FEM_PARAMETER_PATH_H

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * A declared entry named as on the command line, "Section/Subsection/Entry"
   * (--set, --sweep). ParameterHandler checks entry names only in debug
   * mode, so the entry is looked up among the declared ones.
   */
  struct ParameterPath
  {
    std::vector<std::string> sections; ///< the subsections, outermost first
    std::string              entry;
    std::string              pattern_description; ///< the allowed values

    /// "Section/Subsection/Entry"
    std::string
    name() const;
    std::string
    get(ParameterHandler &prm) const;
    /// Sets the entry; false (entry unchanged) if @p value does not match
    /// the entry's pattern.
    bool
    set(ParameterHandler &prm, const std::string &value) const;
  };

  /// The declared entry at @p path ("Section/Entry", parts trimmed), or
  /// none if there is no such entry.
  std::optional<ParameterPath>
  find_parameter(ParameterHandler &prm, const std::string &path);
} // namespace impact_fem

#endif
