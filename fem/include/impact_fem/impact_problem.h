#ifndef IMPACT_FEM_IMPACT_PROBLEM_H
#define IMPACT_FEM_IMPACT_PROBLEM_H

#include <impact_fem/contact/mortar_contact.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>
#include <impact_fem/output/history.h>
#include <impact_fem/time_integration/newmark.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/parameter_handler.h>
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
#include <utility>
#include <vector>
#include <memory>
#include <string>

namespace impact_fem
{
  using namespace dealii;

  /**
   * A sphere hitting a plate: axisymmetric small-strain elastodynamics of
   * two bodies in frictionless contact (see fem/README.md for the model).
   */
  class ImpactProblem
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// Progress and results go to `log` on the first rank of `comm`.
    ImpactProblem(ParameterHandler &prm,
                  const MPI_Comm    comm,
                  std::ostream     &log = std::cout);

    void
    run();

    /// The signal (SIGINT, SIGTERM) that interrupted the last run, 0 if none.
    static int
    interrupt_received();

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
    void
    update_material_states();
    void
    record_step();
    void
    output_results(const unsigned int snapshot);
    void
    print_progress(const bool last);
    void
    write_results(const bool complete);

    const materials::Interface &
    material_of(const types::material_id body) const;

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    bool               log_is_terminal; // progress updated in place
    // Created by run(): a TimerOutput destroyed while an exception unwinds
    // prints a warning that would bury the error message.
    std::unique_ptr<TimerOutput> computing_timer;
    ParameterHandler  &parameters;

    // Scenario
    Geometry     geometry;
    bool         static_press    = false;   // quasi-static press, no impact
    double       static_force    = 0;       // [N]
    double       impact_velocity = 0;       // [m/s]
    double       gravity         = 0;       // [m/s^2]
    bool         absorbing_boundaries = true;
    std::unique_ptr<materials::Interface> sphere_material, plate_material;
    double       sphere_mass = 0;           // [kg]
    bool         has_material_damping = false; // any viscous material
    bool         has_internal_variables = false; // any Maxwell body
    double       yield_strength[2] = {0, 0}; // sphere, plate [Pa]; 0: none
    double       hertz_contact_time = 0;    // [s]
    double       initial_energy = 0;        // [J]
    double       contact_velocity = 0;      // speed at first contact [m/s]

    SpherePlateMesh mesh;
    Newmark         time_integrator;
    MortarContact   contact;

    // Output
    std::string output_directory;
    double      snapshot_interval = 0; // [s], 0 = none
    double      progress_interval = 1; // [s] of wall time

    parallel::distributed::Triangulation<2> triangulation;
    std::unique_ptr<FESystem<2>>            fe;
    std::unique_ptr<MappingQ<2>>            mapping;
    DoFHandler<2>                           dof_handler;
    IndexSet                                locally_owned_dofs;
    IndexSet                                locally_relevant_dofs;
    AffineConstraints<double>               constraints;

    TrilinosWrappers::SparseMatrix mass_matrix;
    TrilinosWrappers::SparseMatrix stiffness_matrix;
    TrilinosWrappers::SparseMatrix boundary_damping_matrix; // dashpots
    TrilinosWrappers::SparseMatrix material_damping_matrix; // viscosity
    TrilinosWrappers::SparseMatrix internal_stiffness_matrix; // Maxwell arms
    TrilinosWrappers::SparseMatrix effective_stiffness;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct_solver;
    SolverControl                                   solver_control;
    std::string                                     direct_solver_name;

    // State (condensed: constrained entries are zero)
    TrilinosWrappers::MPI::Vector displacement, velocity, acceleration;
    TrilinosWrappers::MPI::Vector body_force;
    TrilinosWrappers::MPI::Vector sphere_momentum_weights; // M e_z on the sphere
    TrilinosWrappers::MPI::Vector plate_bottom_weights;    // mean u_z of bottom
    TrilinosWrappers::MPI::Vector sphere_mask;             // 1 on sphere dofs
    // Right-hand side part of the Maxwell arms' forces at the next step:
    // int B^T internal_stress_predictor dV.
    TrilinosWrappers::MPI::Vector internal_force_predictor;

    /// Strain and internal variables at one quadrature point, at the end of
    /// the last completed step (bodies with internal variables only, on the
    /// locally owned cells).
    struct QuadraturePointState
    {
      SymmetricTensor<2, 3>              strain;
      std::vector<SymmetricTensor<2, 3>> internal;
    };
    CellDataStorage<typename Triangulation<2>::cell_iterator,
                    QuadraturePointState>
      material_states;
    double internal_energy[2] = {0, 0}; // stored in the arms: sphere, plate [J]

    double         time = 0;
    unsigned int   step = 0;
    Vector<double> contact_pressures, weighted_gaps;
    double         contact_work = 0, radiated_energy = 0, dissipated_energy = 0;
    double         gravity_work = 0;

    History history;
    std::vector<std::pair<double, std::string>> snapshot_records; // (time, .pvtu)
    std::chrono::steady_clock::time_point wall_start, last_progress;
    double       end_time = 0;
    double       separation_time = -1;
    double       largest_force   = -1;
    bool         contact_started = false;

    /// Largest von Mises stress of a body over the run, and where the yield
    /// strength was first exceeded.
    struct StressPeak
    {
      double   value = 0, time = 0;
      Point<2> location;
      double   first_yield_time = -1;
      Point<2> first_yield_location;
    };
    StressPeak stress_peak[2]; // sphere, plate
  };
} // namespace impact_fem

#endif
