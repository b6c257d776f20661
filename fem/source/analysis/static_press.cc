// Scenario/Analysis = static press: the sphere, at rest, pressed into the
// plate by a body force.

#include <impact_fem/analysis/interface.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/result_files.h>

#include <iostream>
#include <memory>

namespace impact_fem
{
  namespace
  {
    /**
     * The time loop of the impact with the sphere at rest on the plate
     * under a uniform body force of resultant Scenario/Static force: one
     * step of length Parameters::time_step(), which ties every degree of
     * freedom to the ground by soft springs, is the static problem.
     */
    class StaticPress : public ImpactProblem
    {
    public:
      StaticPress(ParameterHandler &prm, const MPI_Comm comm)
        : ImpactProblem(prm, comm, std::cout, false)
      {}

    protected:
      /// At rest, touching the plate.
      InitialMotion
      initial_motion() const override
      {
        return InitialMotion();
      }

      double
      body_acceleration() const override
      {
        return parameters.static_force / parameters.sphere_mass;
      }

      /// No first contact: the bodies touch from the start.
      double
      contact_start_time() const override
      {
        return summary::nan;
      }

      void
      print_result(const summary::ImpactSummary &) const override
      {
        const std::size_t n = history.n_steps();
        pcout << "  contact force     "
              << history[result_files::contact_force_dataset][n - 1] << " N\n"
              << "  contact radius    "
              << history["contact_radius"][n - 1] * 1e3 << " mm\n"
              << "  max pressure      " << history["max_pressure"][n - 1] / 1e9
              << " GPa\n"
              << "  approach          "
              << history[result_files::approach_dataset][n - 1] * 1e6
              << " um\n";
      }

      /// The bodies are not meant to separate.
      void
      warn_if_not_separated() const override
      {}
    };


    /// `Scenario/Analysis = static press`: one StaticPress.
    class StaticPressAnalysis : public analysis::Interface
    {
    public:
      /// Its entry, Scenario/Static force, is one of Parameters.
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      parse_parameters(ParameterHandler           &prm,
                       const analysis::Invocation &invocation,
                       const MPI_Comm              comm) override
      {
        analysis::require_single_run(prm, invocation, "static press", "");
        problem = std::make_unique<StaticPress>(prm, comm);
      }

      int
      run() override
      {
        problem->run();
        return 0;
      }

    private:
      std::unique_ptr<StaticPress> problem;
    };
  } // namespace

  IMPACT_FEM_REGISTER_ANALYSIS(
    StaticPressAnalysis,
    "static press",
    1,
    "the sphere, at rest, is pressed into the plate by a uniform body force "
    "of resultant 'Static force' (use with a clamped far boundary); one "
    "quasi-static solve, the Hertz check.")
} // namespace impact_fem
