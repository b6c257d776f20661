#ifndef IMPACT_FEM_IMPACT_PROBLEM_H
#define IMPACT_FEM_IMPACT_PROBLEM_H

#include <impact_fem/discretisation/automatic_discretisation.h>
#include <impact_fem/analysis/indentation.h>
#include <impact_fem/contact/mortar_contact.h>
#include <impact_fem/materials/internal_variables.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>
#include <impact_fem/output/history.h>
#include <impact_fem/parameters.h>
#include <impact_fem/postprocess/interface.h>
#include <impact_fem/time_integration/interface.h>
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
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * A sphere hitting a plate: axisymmetric small-strain elastodynamics of
   * two bodies in frictionless contact (fem/README.md). The life cycle is
   * that of a deal.II tutorial, read in run(): mesh, system, matrices,
   * factorisation, contact influence, initial state, then per step the
   * solve (time stepper + contact) and the postprocessors.
   *
   * What only looks at the solution (energies, stresses, contact
   * quantities, snapshots, progress) lives in postprocess/ and reads the
   * state through the const accessors below.
   */
  class ImpactProblem
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Progress and results go to `log` on the first rank of `comm`.
    ImpactProblem(ParameterHandler &prm,
                  const MPI_Comm    comm,
                  std::ostream     &log = std::cout);

    void
    run();

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
    /// the sphere).
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

    const time_integration::Interface &
    stepper() const
    {
      return *time_stepper;
    }
    /// Displacement and velocity with constraints distributed and ghost
    /// entries, for cell-wise evaluation (refreshed after every step).
    const VectorType &
    ghosted_displacement() const
    {
      return ghosted_u;
    }
    const VectorType &
    ghosted_velocity() const
    {
      return ghosted_v;
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
    /// Speed of the sphere at first contact [m/s].
    double
    contact_velocity() const
    {
      return first_contact_speed;
    }
    /// Expected end of the run [s]: from Hertz until the bodies separate.
    double
    expected_end_time() const;
    std::chrono::steady_clock::time_point
    start_of_run() const
    {
      return wall_start;
    }

  private:
    void
    make_mesh();
    void
    setup_system();
    void
    assemble_system();
    void
    factorize_effective_stiffness();
    void
    setup_contact();
    void
    set_initial_conditions();
    void
    solve_time_step();
    /// u = K_eff^{-1} rhs with the contact response (one solve, one LCP).
    void
    solve_linear_step(const VectorType &rhs, VectorType &displacement);
    /// The step of plastic bodies: iterations of solve_linear_step.
    void
    solve_nonlinear_step(const VectorType &rhs, VectorType &displacement);
    void
    refresh_ghosted_state();
    void
    postprocess_step();
    void
    write_results(const bool complete);
    /// The parameters flattened to "Section/Entry" -> value.
    std::map<std::string, std::string>
    parameter_attributes() const;

    // The quasi-static indentation (analysis/indentation.cc): the base's
    // rows eliminated from K and factorised, the response to a unit
    // approach; one displacement-controlled step; the load program.
    void
    setup_indentation();
    void
    solve_indentation_step(const double approach, VectorType &displacement);
    /// The step with elastic-plastic bodies: iterations of the elastic step
    /// on the plastic force from the committed state (nothing committed).
    time_integration::NonlinearStep::Result
    solve_plastic_indentation_step(const double      approach,
                                   const VectorType &committed_displacement,
                                   VectorType       &displacement);
    void
    run_indentation();

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    bool               log_is_terminal;
    // Created by run(): a TimerOutput destroyed while an exception unwinds
    // prints a warning that would bury the error message.
    std::unique_ptr<TimerOutput> computing_timer;
    ParameterHandler            &prm;

    Parameters         parameters;
    IndentationControl indentation_control;
    SpherePlateMesh    mesh;
    /// The sizes and the step the run uses, and whether "auto" chose them.
    discretisation::DiscretisationChoice         discretisation_choice;
    MortarContact                                contact;
    std::unique_ptr<time_integration::Interface> time_stepper;
    std::vector<std::pair<std::string, std::unique_ptr<postprocess::Interface>>>
      postprocessors;

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
    // Right-hand side part of the Maxwell arms' forces at the next step.
    VectorType internal_force_predictor;
    // Indentation: displacement for a unit approach of the base, the load
    // that prescribes it and the rows it holds (owned).
    VectorType unit_approach_response, unit_approach_load;
    std::vector<types::global_dof_index> indentation_held_rows;
    VectorType                           ghosted_u, ghosted_v, ghosted_trial;
    Vector<double>                       pressures;
    double                               first_contact_speed = 0;

    History                               history;
    std::chrono::steady_clock::time_point wall_start;
    double                                end_time         = 0;
    double                                separation_time  = -1;
    double                                first_force_time = -1;
  };
} // namespace impact_fem

#endif
