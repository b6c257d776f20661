#ifndef IMPACT_FEM_ANALYSIS_INTERFACE_H
#define IMPACT_FEM_ANALYSIS_INTERFACE_H

#include <impact_fem/campaign/shard.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace impact_fem
{
  /**
   * The analyses of `Scenario/Analysis` (impact, static press, indentation,
   * material point, specimen): each a class of its own in analysis/,
   * registered under its name by IMPACT_FEM_REGISTER_ANALYSIS in its file.
   * main() declares the entries of all of them, creates the one the
   * parameters name, lets it read its input and runs it.
   */
  namespace analysis
  {
    using namespace dealii;

    /// What the command line adds to the parameters.
    struct Invocation
    {
      /// --velocities and --sweep (campaigns of impacts).
      std::string              velocity_list;
      std::vector<std::string> sweep_items;
      /// --shard K/N, and whether it was given.
      CampaignShard shard;
      bool          sharded = false;
    };

    class Interface
    {
    public:
      virtual ~Interface() = default;

      /**
       * Read and check the input (the parameters as set, the command
       * line): an error thrown here is one of the input (exit code 2).
       * Nothing is written yet.
       */
      virtual void
      parse_parameters(ParameterHandler &prm,
                       const Invocation &invocation,
                       const MPI_Comm    comm) = 0;

      /// Run; returns the exit code (0 success, 1 a failed run).
      virtual int
      run() = 0;

      /// Whether a campaign of this analysis is possible (and so --shard).
      virtual bool
      runs_campaigns() const
      {
        return false;
      }
    };

    /// One kind of analysis, as registered.
    struct Entry
    {
      std::string name;
      /// The text of the name in the help of Scenario/Analysis.
      std::string description;
      /// Place in the selection's list (and in the help), ascending.
      int                                         position;
      std::function<void(ParameterHandler &)>     declare_parameters;
      std::function<std::unique_ptr<Interface>()> create;
    };

    /// Add a kind; returns true (for use in a static initialiser).
    bool
    add(const Entry &entry);

    /// All kinds, in the order of their positions.
    std::vector<Entry>
    all();

    /// The analysis called @p name (an error that lists the known ones).
    std::unique_ptr<Interface>
    create(const std::string &name);

    /// "impact|static press|...": the pattern of Scenario/Analysis.
    std::string
    selection();

    /// "'impact': ... 'static press': ...": the help of Scenario/Analysis.
    std::string
    descriptions();

    /// Declare Scenario/Analysis (the registered names) and the entries
    /// every analysis reads beyond the shared ones.
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Refuse a campaign (--velocities, --sweep, Campaign/...) and --verify
     * for the analysis @p name, which runs alone: both are built on impact
     * results. @p advice (empty, or "; ..." ) ends the message.
     */
    void
    require_single_run(ParameterHandler  &prm,
                       const Invocation  &invocation,
                       const std::string &name,
                       const std::string &advice);
  } // namespace analysis
} // namespace impact_fem

/**
 * Register @p classname (default constructible, derived from
 * analysis::Interface, with a static declare_parameters(ParameterHandler &)
 * for its own entries) as the analysis @p name, listed at @p position in
 * Scenario/Analysis. Used inside namespace impact_fem, in the class's file.
 */
#define IMPACT_FEM_REGISTER_ANALYSIS(classname, name, position, description) \
  namespace                                                                  \
  {                                                                          \
    const bool impact_fem_registered_analysis_##classname =                  \
      impact_fem::analysis::add(                                             \
        {name,                                                               \
         description,                                                        \
         position,                                                           \
         &classname::declare_parameters,                                     \
         []() -> std::unique_ptr<impact_fem::analysis::Interface> {          \
           return std::make_unique<classname>();                             \
         }});                                                                \
  }

#endif
