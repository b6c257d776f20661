// Scenario/Analysis = static press: the sphere, at rest, pressed into the
// plate by a body force.

#include <impact_fem/analysis/impact.h>
#include <impact_fem/analysis/interface.h>

namespace impact_fem
{
  /**
   * `Scenario/Analysis = static press`: the problem of the impact with the
   * sphere at rest under the body force of resultant Scenario/Static force,
   * one step of soft springs to the ground (Parameters::time_step()).
   */
  class StaticPressAnalysis : public ImpactAnalysis
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}
  };

  IMPACT_FEM_REGISTER_ANALYSIS(
    StaticPressAnalysis,
    "static press",
    1,
    "the sphere, at rest, is pressed into the plate by a uniform body force of "
    "resultant 'Static force' (use with a clamped far boundary); one "
    "quasi-static solve, the Hertz check.")
} // namespace impact_fem
