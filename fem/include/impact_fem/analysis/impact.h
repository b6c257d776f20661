#ifndef IMPACT_FEM_ANALYSIS_IMPACT_H
#define IMPACT_FEM_ANALYSIS_IMPACT_H

#include <impact_fem/analysis/interface.h>
#include <impact_fem/campaign.h>
#include <impact_fem/impact_problem.h>

#include <memory>

namespace impact_fem
{
  /**
   * `Scenario/Analysis = impact`: one ImpactProblem, or a campaign of them
   * (--velocities, --sweep, Campaign/...), or one with its grid-convergence
   * study (--verify, Verification/Verify).
   */
  class ImpactAnalysis : public analysis::Interface
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler           &prm,
                     const analysis::Invocation &invocation,
                     const MPI_Comm              comm) override;

    int
    run() override;

    bool
    runs_campaigns() const override
    {
      return true;
    }

  private:
    ParameterHandler              *parameters   = nullptr;
    MPI_Comm                       communicator = MPI_COMM_WORLD;
    std::unique_ptr<Campaign>      campaign;
    std::unique_ptr<ImpactProblem> problem;
  };
} // namespace impact_fem

#endif
