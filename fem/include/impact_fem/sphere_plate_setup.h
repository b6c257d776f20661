#ifndef IMPACT_FEM_SPHERE_PLATE_SETUP_H
#define IMPACT_FEM_SPHERE_PLATE_SETUP_H

#include <impact_fem/contact/mortar_contact.h>
#include <impact_fem/discretisation/automatic_discretisation.h>
#include <impact_fem/materials/internal_variables.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>
#include <impact_fem/output/history.h>
#include <impact_fem/parameters.h>
#include <impact_fem/time_integration/nonlinear_step.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * What the analyses of the sphere and the plate share (impact, static
   * press, indentation): the bodies and their materials (Parameters), the
   * mesh, the degrees of freedom and constraints, the matrices of the
   * bodies, the contact conditions and their influence, the internal
   * variables of the materials, the history and the output directory.
   * An analysis derives from it and adds its load program: setup in the
   * order make_mesh(), setup_system(), assemble_system(), a factorisation
   * of effective_stiffness (factorize()), setup_contact().
   *
   * The const accessors below are what the postprocessors read.
   */
  class SpherePlateSetup
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /// The entries of the bodies, the mesh, the contact and the nonlinear
    /// solver (Parameters and the components).
    static void
    declare_parameters(ParameterHandler &prm);

    virtual ~SpherePlateSetup() = default;

    /// The signal (SIGINT, SIGTERM) that interrupted a run, 0 if none.
    static int
    interrupt_received();

    // ---- Access for the postprocessors ----
    const Parameters &
    scenario() const
    {
      return parameters;
    }
    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }
    const ConditionalOStream &
    console() const
    {
      return pcout;
    }
    /// The log is a terminal that can show a line updated in place.
    bool
    console_is_terminal() const
    {
      return log_is_terminal;
    }
    const SpherePlateMesh &
    mesh_parameters() const
    {
      return mesh;
    }
    const DoFHandler<2> &
    dofs() const
    {
      return dof_handler;
    }
    const Mapping<2> &
    geometric_mapping() const
    {
      return *mapping;
    }
    const Quadrature<2> &
    cell_quadrature() const
    {
      return *quadrature;
    }
    const IndexSet &
    owned_dofs() const
    {
      return locally_owned_dofs;
    }
    const IndexSet &
    relevant_dofs() const
    {
      return locally_relevant_dofs;
    }
    const AffineConstraints<double> &
    hanging_and_boundary_constraints() const
    {
      return constraints;
    }
    const materials::Interface &
    material_of(const types::material_id body) const;

    /// The matrices of M a + C v + K u = f (C = boundary + material).
    struct SystemMatrices
    {
      TrilinosWrappers::SparseMatrix mass, stiffness, boundary_damping,
        material_damping, internal_stiffness;
    };
    const SystemMatrices &
    matrices() const
    {
      return system;
    }

    /// Functionals of the state: M e_z on the sphere and on the plate
    /// (their momenta from the velocity), the mean vertical displacement of
    /// the plate bottom, 1 on the sphere's dofs, the body force (gravity on
    /// the sphere; set by the analysis).
    struct Functionals
    {
      VectorType sphere_momentum, plate_momentum, plate_bottom_mean,
        sphere_mask, body_force;
    };
    const Functionals &
    functionals() const
    {
      return weights;
    }

    /// Displacement with constraints distributed and ghost entries, for
    /// cell-wise evaluation (refreshed after every step).
    const VectorType &
    ghosted_displacement() const
    {
      return ghosted_u;
    }
    const MortarContact &
    contact_conditions() const
    {
      return contact;
    }
    /// Nodal contact pressures at the end of the last step [Pa].
    const Vector<double> &
    contact_pressures() const
    {
      return pressures;
    }
    const materials::InternalVariables &
    internal_variables() const
    {
      return arms;
    }
    std::chrono::steady_clock::time_point
    start_of_run() const
    {
      return wall_start;
    }

  protected:
    /**
     * What the analysis puts the bodies through, as far as the setup needs
     * it before the mesh is made (Parameters knows no analysis).
     */
    struct Loading
    {
      /// The contact the sizes and the step left "auto" are made for.
      Parameters::ExpectedContactOf expected_contact;
      /// Only the sphere's lower hemisphere is meshed, its base a boundary.
      bool hemisphere = false;
      /// The analysis's own checks of the scenario (an ExcMessage names
      /// the entry), before the mesh is read.
      std::function<void(const Parameters &)> check;
    };

    /// Reads the bodies, the mesh (sized for the contact @p loading
    /// expects), the contact and the nonlinear solver; progress and results
    /// go to `log` on the first rank of `comm`.
    SpherePlateSetup(ParameterHandler &prm,
                     const MPI_Comm    comm,
                     std::ostream     &log,
                     const Loading    &loading);

    /// Refuses a plate that nothing holds against a static load (the
    /// analyses without inertia: static press, indentation).
    static void
    require_plate_held(const Parameters &parameters);

    /// Catches SIGINT and SIGTERM while it lives (interrupt_received()),
    /// restores the old handlers after. A signal once received stays
    /// recorded (it is not reset for the next run of a campaign), so that a
    /// campaign stops instead of losing it.
    class InterruptHandler
    {
    public:
      InterruptHandler();
      ~InterruptHandler();

    private:
      void (*previous_interrupt)(int);
      void (*previous_terminate)(int);
    };

    /// Logs what the bodies are made of (and where each constant came
    /// from) and the discretisation.
    void
    describe_bodies() const;
    /// Refuses a contact surface smaller than @p expected_radius [m].
    void
    check_contact_surface(const double expected_radius) const;
    /// The clock and the timer of the run; the output directory created
    /// and cleared of an earlier run's results (all ranks).
    void
    start_run();
    void
    make_mesh();
    void
    setup_system();
    /// The matrices and functionals (not the body force) with the
    /// internal tangent for the step @p dt.
    void
    assemble_system(const double dt);
    /// The direct solver of effective_stiffness.
    void
    factorize();
    /// A factorisation of @p matrix by "Solver/Direct solver" ("auto" said
    /// on the log if @p say_which); @p matrix must outlive it.
    std::unique_ptr<TrilinosWrappers::SolverDirect>
    direct_solver_of(const TrilinosWrappers::SparseMatrix &matrix,
                     const bool                            say_which);
    void
    setup_contact();
    /// The internal variables, relaxed, on the displacement ghosted_u.
    void
    initialize_internal_variables();
    /// u = K_eff^{-1} rhs with the contact response (one solve, one LCP).
    void
    solve_linear_step(const VectorType &rhs, VectorType &displacement);
    /// The history's columns of the nonlinear steps of plastic bodies: the
    /// iterations and the residual, relative to ||B^T lambda|| +
    /// @p other_load (the load that stays when the contact opens).
    void
    declare_iteration_history(const std::string &other_load);
    /// The parameters flattened to "Section/Entry" -> value, with the
    /// constants and sizes the run used.
    std::map<std::string, std::string>
    parameter_attributes() const;

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    bool               log_is_terminal;
    // Created by start_run(): a TimerOutput destroyed while an exception
    // unwinds prints a warning that would bury the error message.
    std::unique_ptr<TimerOutput> computing_timer;
    ParameterHandler            &prm;

    Parameters      parameters;
    SpherePlateMesh mesh;
    /// The sizes and the step the run uses, and whether "auto" chose them.
    discretisation::DiscretisationChoice discretisation_choice;
    MortarContact                        contact;

    parallel::distributed::Triangulation<2> triangulation;
    std::unique_ptr<FESystem<2>>            fe;
    std::unique_ptr<MappingQ<2>>            mapping;
    std::unique_ptr<Quadrature<2>>          quadrature;
    DoFHandler<2>                           dof_handler;
    IndexSet                                locally_owned_dofs;
    IndexSet                                locally_relevant_dofs;
    AffineConstraints<double>               constraints;

    SystemMatrices                                  system;
    Functionals                                     weights;
    TrilinosWrappers::SparseMatrix                  effective_stiffness;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct_solver;
    SolverControl                                   solver_control;

    materials::InternalVariables    arms;
    time_integration::NonlinearStep nonlinear_step;
    unsigned int                    step_iterations = 0;
    double                          step_residual   = 0;
    VectorType                      ghosted_u, ghosted_trial;
    Vector<double>                  pressures;

    History                               history;
    std::chrono::steady_clock::time_point wall_start;
  };
} // namespace impact_fem

#endif
