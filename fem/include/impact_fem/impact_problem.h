#ifndef IMPACT_FEM_IMPACT_PROBLEM_H
#define IMPACT_FEM_IMPACT_PROBLEM_H

#include <impact_fem/postprocess/interface.h>
#include <impact_fem/sphere_plate_setup.h>
#include <impact_fem/summary/impact_summary.h>
#include <impact_fem/time_integration/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * A sphere hitting a plate: axisymmetric small-strain elastodynamics of
   * two bodies in frictionless contact (fem/README.md), on the bodies,
   * mesh and contact of SpherePlateSetup. The life cycle is that of a
   * deal.II tutorial, read in run(): mesh, system, matrices, factorisation,
   * contact influence, initial state, then per step the solve (time
   * stepper + contact) and the postprocessors.
   *
   * What only looks at the solution (energies, stresses, contact
   * quantities, snapshots, progress) lives in postprocess/ and reads the
   * state through the const accessors.
   */
  class ImpactProblem : public SpherePlateSetup
  {
  public:
    /// Every entry of an impact run.
    static void
    declare_parameters(ParameterHandler &prm);

    /// The contact an impact expects (Parameters::ExpectedContactOf):
    /// Hertz's, or Jackson-Green's if a body can yield.
    static discretisation::ExpectedContact
    expected_contact(const Parameters &parameters);

    /// Progress and results go to `log` on the first rank of `comm`. An
    /// automatic step count is raised @p step_refinement times (the second
    /// run of run_impact()).
    ImpactProblem(ParameterHandler &prm,
                  const MPI_Comm    comm,
                  std::ostream     &log             = std::cout,
                  const double      step_refinement = 1);

    /**
     * Thrown by run() at the end of a run whose automatic step lost more
     * energy to the contact activation than the energy balance allows
     * (AutomaticDiscretisation::step_refinement_for_energy()); the run is
     * left incomplete, for run_impact() to make again with the step
     * refinement() times finer.
     */
    class StepTooCoarseForEnergy : public std::runtime_error
    {
    public:
      StepTooCoarseForEnergy(const std::string &what, const double refinement)
        : std::runtime_error(what)
        , factor(refinement)
      {}
      /// The total refinement of the automatic step count to run with [-].
      double
      refinement() const
      {
        return factor;
      }

    private:
      double factor;
    };

    void
    run();

    // ---- Access for the postprocessors ----
    const time_integration::Interface &
    stepper() const
    {
      return *time_stepper;
    }
    /// Velocity with constraints distributed and ghost entries, for
    /// cell-wise evaluation (refreshed after every step).
    const VectorType &
    ghosted_velocity() const
    {
      return ghosted_v;
    }
    /// Speed of the sphere at first contact [m/s].
    double
    contact_velocity() const
    {
      return first_contact_speed;
    }
    /// Expected end of the run [s]: from Hertz until the bodies separate.
    double
    expected_end_time() const;

  protected:
    /// The rigid motion of the sphere at the start of the run, the plate at
    /// rest: vertical displacement, downward speed, vertical acceleration
    /// [m, m/s, m/s^2] at the start time t0 [s].
    struct InitialMotion
    {
      double displacement = 0, speed = 0, acceleration = 0, t0 = 0;
    };

    /// For the analyses on this time loop, under their @p loading:
    /// @p impact false leaves out what only a sphere flying at the plate
    /// has (the step from the contact time, the expected contact radius,
    /// the @p step_refinement of an automatic step).
    ImpactProblem(ParameterHandler &prm,
                  const MPI_Comm    comm,
                  std::ostream     &log,
                  const Loading    &loading,
                  const bool        impact,
                  const double      step_refinement = 1);

    /// The time step [s] (Parameters::time_step()); time_stepper is made.
    virtual double
    time_step() const;
    /// Hard end of the run [s] for the step @p dt (before the end after
    /// separation; Parameters::end_time()).
    virtual double
    hard_end_time(const double dt) const;

    /// The sphere's motion when the run starts: at the first contact,
    /// having flown across the initial gap.
    virtual InitialMotion
    initial_motion() const;
    /// The body force on the sphere per mass, downward [m/s^2]: gravity.
    virtual double
    body_acceleration() const;
    /// The time of the first contact given to the summary [s] (the start
    /// of the run).
    virtual double
    contact_start_time() const;
    /// The result printed at the end of the run (@p s its summary).
    virtual void
    print_result(const summary::ImpactSummary &s) const;
    /// Said when the run ends before the bodies separated.
    virtual void
    warn_if_not_separated() const;

  private:
    /// The sphere, the Hertz estimates and the step, on the log.
    void
    describe_run() const;
    void
    setup_dynamic_state();
    void
    factorize_effective_stiffness();
    void
    set_initial_conditions();
    void
    solve_time_step();
    /// The step of plastic bodies: iterations of solve_linear_step.
    void
    solve_nonlinear_step(const VectorType &rhs, VectorType &displacement);
    void
    refresh_ghosted_state();
    void
    postprocess_step();
    /// The time loop, checkpoints and interrupts included.
    void
    time_loop();
    void
    write_results(const bool complete);
    /// The summary.json of the run (@p s its summary).
    nlohmann::json
    results(const summary::ImpactSummary &s,
            const bool                    complete,
            const double                  wall_time,
            std::ostringstream           &report);
    /// history.h5 with the parameters, the results and their definitions.
    void
    write_history(const nlohmann::json &result, const bool complete);

    std::unique_ptr<time_integration::Interface> time_stepper;
    std::vector<std::pair<std::string, std::unique_ptr<postprocess::Interface>>>
      postprocessors;

    // Right-hand side part of the Maxwell arms' forces at the next step.
    VectorType internal_force_predictor;
    VectorType ghosted_v;
    double     first_contact_speed = 0;
    /// The report of the postprocessors, printed with the result.
    std::string report;

    /// The refinement of the automatic step count this run makes [-], and
    /// whether its energy balance may raise it (an impact whose step count
    /// is automatic).
    double step_refinement       = 1;
    bool   step_sized_for_energy = false;

    /// The refinement the energy balance asks for (1: none), said on the
    /// log when it is more than this run's.
    double
    energy_step_refinement() const;

    double end_time         = 0;
    double separation_time  = -1;
    double first_force_time = -1;
  };

  /**
   * Runs the impact of @p prm (an ImpactProblem, progress to @p log): once,
   * or, when its automatic step lost too much energy to the contact
   * activation (ImpactProblem::StepTooCoarseForEnergy), again with the
   * finer step it asks for (once). @p first, if given, is the
   * problem of the first run (made from @p prm).
   */
  void
  run_impact(ParameterHandler              &prm,
             const MPI_Comm                 comm,
             std::ostream                  &log,
             std::unique_ptr<ImpactProblem> first = nullptr);
} // namespace impact_fem

#endif
