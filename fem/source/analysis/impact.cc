// Scenario/Analysis = impact: the sphere hits the plate (ImpactProblem), one
// run, a campaign of runs or a run with its grid-convergence study.

#include <impact_fem/analysis/impact.h>
#include <impact_fem/analysis/interface.h>
#include <impact_fem/verification/verification.h>

#include <iostream>

namespace impact_fem
{
  void
  ImpactAnalysis::declare_parameters(ParameterHandler &)
  {
    // The entries of the impact are those every analysis of the bodies
    // shares (ImpactProblem::declare_parameters, declared by main()).
  }


  void
  ImpactAnalysis::parse_parameters(ParameterHandler           &prm,
                                   const analysis::Invocation &invocation,
                                   const MPI_Comm              comm)
  {
    parameters   = &prm;
    communicator = comm;
    if (Campaign::requested(prm,
                            invocation.velocity_list,
                            invocation.sweep_items))
      campaign = std::make_unique<Campaign>(prm,
                                            invocation.velocity_list,
                                            invocation.sweep_items,
                                            invocation.shard);
    else if (!verification::enabled(prm))
      problem = std::make_unique<ImpactProblem>(prm, comm);
  }


  int
  ImpactAnalysis::run()
  {
    if (campaign)
      return campaign->run(communicator) > 0 ? 1 : 0;
    if (!problem)
      {
        verification::verify(*parameters, communicator, std::cout);
        return 0;
      }
    run_impact(*parameters, communicator, std::cout, std::move(problem));
    return 0;
  }


  IMPACT_FEM_REGISTER_ANALYSIS(
    ImpactAnalysis,
    "impact",
    0,
    "the sphere hits the plate at the impact velocity.")
} // namespace impact_fem
