#ifndef IMPACT_FEM_IMPACT_PROBLEM_H
#define IMPACT_FEM_IMPACT_PROBLEM_H

#include <impact_fem/output/checkpoint.h>
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

    /// The refinements of the automatic step and contact nodes for the
    /// energy balance.
    using EnergyRefinement =
      discretisation::AutomaticDiscretisation::EnergyRefinement;

    /// Progress and results go to `log` on the first rank of `comm`. An
    /// automatic step count and contact-node spacing are refined as
    /// @p refinement says (the later runs of run_impact()).
    ImpactProblem(ParameterHandler       &prm,
                  const MPI_Comm          comm,
                  std::ostream           &log        = std::cout,
                  const EnergyRefinement &refinement = {});

    /**
     * Thrown by run() at the end of a run whose automatic step or contact
     * nodes lost more energy than the energy balance allows
     * (AutomaticDiscretisation::step_refinement_for_energy(),
     * contact_spacing_halving_for_energy()); the run is left incomplete,
     * for run_impact() to make again with refinement().
     */
    class TooCoarseForEnergy : public std::runtime_error
    {
    public:
      TooCoarseForEnergy(const std::string      &what,
                         const EnergyRefinement &refinement)
        : std::runtime_error(what)
        , next(refinement)
      {}
      /// The refinement to run with (the totals, not increments).
      const EnergyRefinement &
      refinement() const
      {
        return next;
      }

    private:
      EnergyRefinement next;
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
    /// the @p refinement of an automatic step and contact nodes).
    ImpactProblem(ParameterHandler       &prm,
                  const MPI_Comm          comm,
                  std::ostream           &log,
                  const Loading          &loading,
                  const bool              impact,
                  const EnergyRefinement &refinement = {});

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
    /// K + (kappa / dt^2) M + (delta / dt) C + the Maxwell arms' tangent.
    void
    assemble_effective_stiffness(const double                    dt,
                                 TrilinosWrappers::SparseMatrix &matrix) const;
    /// The factorisation and contact influence of the sub-steps at contact
    /// entry (Time integration/Sub-steps at contact entry).
    void
    setup_entry_sub_steps();
    void
    set_initial_conditions();
    /// The equation of the next step (of the stepper's current length)
    /// solved, with contact; nothing accepted yet.
    void
    solve_step_equation(VectorType &displacement);
    /// The state advanced to @p displacement, the internal variables
    /// committed.
    void
    accept_step(const VectorType &displacement);
    /// One step, or its sub-steps if a contact node entered in it; each
    /// postprocessed.
    void
    take_time_step();
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
    /// Wall time of the run so far [s]: this attempt's and the earlier
    /// ones' that its checkpoint carried.
    double
    run_wall_time() const;
    /// What a checkpoint of this run is stamped with, at the current step.
    checkpoint::Stamp
    checkpoint_stamp() const;
    /// Everything that carries from one step to the next, in this order:
    /// the time stepper, the internal variables, the contact's warm starts
    /// and pressures, the problem's own scalars, the history and each
    /// postprocessor.
    void
    save_state(checkpoint::Writer &writer) const;
    void
    load_state(checkpoint::Reader &reader);
    /// The run goes on from its checkpoint if it has one of the same run
    /// (true; the log says from where), else from the first contact.
    bool
    resume_from_checkpoint();
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

    /// Whether the energy balance may refine this run's automatic step (an
    /// impact whose step count is automatic) and its contact nodes (also
    /// placed by the rule), and the refinement this run makes (its step
    /// factor 1 where the step is not sized for the energy balance).
    bool step_sized_for_energy    = false;
    bool spacing_sized_for_energy = false;
    /// ... and its sub-steps at contact entry (left "auto").
    bool             sub_steps_sized_for_energy = false;
    EnergyRefinement energy_refinement;

    /// The refinement the energy balance asks for the next run, the same
    /// as this run's when it asks for none; @p reason says why.
    EnergyRefinement
    next_energy_refinement(std::string &reason) const;

    /// Sub-steps at contact entry: their number (1: none), effective
    /// matrix, factorisation and contact influence, and the steps divided.
    unsigned int                                    entry_sub_steps = 1;
    std::unique_ptr<TrilinosWrappers::SparseMatrix> entry_stiffness;
    std::unique_ptr<TrilinosWrappers::SolverDirect> entry_solver;
    MortarContact                                   entry_contact;
    unsigned int                                    entry_steps_divided = 0;
    /// The last sub-steps changed the active set: divide the next step too.
    bool divide_next_step = false;

    double end_time         = 0;
    double separation_time  = -1;
    double first_force_time = -1;

    /// An impact keeps checkpoints (analyses on this time loop do not):
    /// its run identity (run_identity::of() of its entries) and the wall
    /// time of the attempts before the one that resumed it [s].
    bool        resumable = false;
    std::string identity;
    double      earlier_wall_time = 0;
  };

  /**
   * Runs the impact of @p prm (an ImpactProblem, progress to @p log): once,
   * or, when its automatic step or contact nodes lost too much energy
   * (ImpactProblem::TooCoarseForEnergy), again with the finer step or
   * the denser contact nodes it asks for (each once, so at most three
   * runs). @p first, if given, is the
   * problem of the first run (made from @p prm).
   */
  void
  run_impact(ParameterHandler              &prm,
             const MPI_Comm                 comm,
             std::ostream                  &log,
             std::unique_ptr<ImpactProblem> first = nullptr);
} // namespace impact_fem

#endif
