#ifndef IMPACT_FEM_CAMPAIGN_SWEEP_H
#define IMPACT_FEM_CAMPAIGN_SWEEP_H

#include <impact_fem/parameter_path.h>

#include <deal.II/base/parameter_handler.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * One axis of a campaign's sweep: a declared entry and the values it
   * takes, as given (trimmed). The velocities are the campaign's last axis
   * (Campaign/Impact velocities), not a SweepAxis.
   */
  struct SweepAxis
  {
    ParameterPath            parameter;
    std::vector<std::string> values;

    /// The run directory's name component of value @p i,
    /// "<entry slug>-<value>" (fem/README.md, "Campaigns"), e.g.
    /// "plate-thickness-0.005".
    std::string
    name_component(const unsigned int i) const;
  };

  /**
   * The axes of the items "Section/Entry=v1,v2,..." (from --sweep or
   * Campaign/Sweep, named by @p option in messages), in the order given.
   * Throws, naming the option and the allowed form, for an item without
   * '=', an entry that is not declared, a value that does not match the
   * entry's pattern, a value given twice, an entry given twice, and for the
   * entries a campaign owns (Output/Directory, Campaign/..., Verification/
   * Verify, Scenario/Analysis, and Scenario/Impact velocity: --velocities).
   * @p prm is left as it was.
   */
  std::vector<SweepAxis>
  parse_sweep(ParameterHandler               &prm,
              const std::vector<std::string> &items,
              const std::string              &option);

  /// The run directory's name component of a velocity, "v<V>" (6 digits).
  std::string
  velocity_name_component(const double velocity);

  /// A value of an axis for index.json: a JSON number if the whole text is
  /// a finite number, else the text.
  nlohmann::ordered_json
  json_value(const std::string &text);
} // namespace impact_fem

#endif
