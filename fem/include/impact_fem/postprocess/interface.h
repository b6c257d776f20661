#ifndef IMPACT_FEM_POSTPROCESS_INTERFACE_H
#define IMPACT_FEM_POSTPROCESS_INTERFACE_H

#include <impact_fem/output/checkpoint.h>
#include <impact_fem/output/history.h>
#include <impact_fem/registry.h>

#include <deal.II/base/parameter_handler.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace impact_fem
{
  class ImpactProblem;

  /**
   * What looks at the solution, outside the simulator class (ASPECT's
   * postprocessors): energies, stresses and the yield check, contact
   * quantities, snapshots, progress. Each kind is one file with a
   * registration; the problem runs all of them after every step, in the
   * order of their names, and asks each for its part of the summary at the
   * end.
   */
  namespace postprocess
  {
    using namespace dealii;

    class Interface
    {
    public:
      virtual ~Interface() = default;

      /// Read the entries declared by declare_parameters (at top level).
      virtual void
      parse_parameters(ParameterHandler &)
      {}

      /// Before the first step: declare the history columns.
      virtual void
      initialize(const ImpactProblem &, History &)
      {}

      /// After each step (and once for the initial state): this step's
      /// values into the history (appended on every rank alike).
      virtual void
      execute(const ImpactProblem &problem, History &history) = 0;

      /// What the postprocessor carries from one step to the next (its
      /// accumulators, extremes, the last step's values), for a checkpoint
      /// of the run; every kind says what, if only that it carries nothing.
      virtual void
      save(checkpoint::Writer &writer) const = 0;

      /// Reads what save() wrote, after initialize(), so that the steps
      /// after the checkpoint are postprocessed as if the run had not
      /// stopped.
      virtual void
      load(checkpoint::Reader &reader, const ImpactProblem &problem) = 0;

      /// At the end (and at checkpoints): summary keys, lines of the report.
      virtual void
      finalize(const ImpactProblem &,
               const History &,
               nlohmann::json &,
               std::ostream &)
      {}
    };


    /// Every kind's entries.
    void
    declare_parameters(ParameterHandler &prm);

    /// One of each registered kind, named, in name order, parameters parsed.
    std::vector<std::pair<std::string, std::unique_ptr<Interface>>>
    create_postprocessors(ParameterHandler &prm);
  } // namespace postprocess
} // namespace impact_fem

/// Register a postprocessor class (default constructible, with a static
/// declare_parameters(ParameterHandler &)).
#define IMPACT_FEM_REGISTER_POSTPROCESSOR(classname, name, description) \
  IMPACT_FEM_REGISTER(impact_fem::postprocess::Interface,               \
                      classname,                                        \
                      name,                                             \
                      description)

#endif
