#include <impact_fem/as_written.h>
#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/quadrature.h>
#include <impact_fem/result_files.h>
#include <impact_fem/sphere_plate_setup.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace impact_fem
{
  namespace
  {
    // Set by SIGINT / SIGTERM during the time loop.
    volatile std::sig_atomic_t interrupt_signal = 0;

    extern "C" void
    record_interrupt(int signal)
    {
      interrupt_signal = signal;
    }


    // Parameters flattened to "Section/Entry" -> value, from the JSON print.
    void
    flatten(const nlohmann::json               &node,
            const std::string                  &path,
            std::map<std::string, std::string> &entries)
    {
      for (auto it = node.begin(); it != node.end(); ++it)
        {
          const std::string key =
            path.empty() ? it.key() : path + "/" + it.key();
          if (it->is_object() && it->contains("value"))
            entries[key] = (*it)["value"].get<std::string>();
          else if (it->is_object())
            flatten(*it, key, entries);
          else if (it->is_string())
            entries[key] = it->get<std::string>();
        }
    }

    /// A progress line updated in place needs a terminal that we own: under
    /// Open MPI's launcher stdout is a pty even when mpirun writes to a file.
    bool
    is_interactive(const std::ostream &log)
    {
      return &log == &std::cout && isatty(STDOUT_FILENO) &&
             std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr &&
             std::getenv("PMI_RANK") == nullptr;
    }


    // The cell's share of M, K, C_boundary, C_material, K_internal, of the
    // sphere's or plate's momentum and of the plate bottom's mean, with the
    // scratch of its assembly.
    struct CellTerms
    {
      explicit CellTerms(const unsigned int dofs_per_cell)
        : matrix(5, FullMatrix<double>(dofs_per_cell, dofs_per_cell))
        , momentum(dofs_per_cell)
        , bottom(dofs_per_cell)
        , strain(dofs_per_cell)
        , phi(dofs_per_cell)
      {}

      std::vector<FullMatrix<double>>    matrix;
      Vector<double>                     momentum, bottom;
      std::vector<SymmetricTensor<2, 3>> strain;
      std::vector<Tensor<1, 2>>          phi;
    };


    // The volume terms of a cell: mass, stiffness, material damping, the
    // internal tangent for the step dt, the momentum.
    void
    add_volume_terms(const DoFHandler<2>::active_cell_iterator &cell,
                     const materials::Interface                &material,
                     const double                               dt,
                     FEValues<2>                               &fe_values,
                     CellTerms                                 &terms)
    {
      const FEValuesExtractors::Vector u(0);
      const unsigned int               dofs_per_cell = fe_values.dofs_per_cell;
      const SymmetricTensor<4, 3> tangent[3] = {material.stiffness_tangent(),
                                                material.damping_tangent(),
                                                material.internal_tangent(dt)};
      const double                rho        = material.density();
      fe_values.reinit(cell);
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          const double r = fe_values.quadrature_point(q)[0];
          // The r-weighted measure of the axisymmetric body (2 pi r).
          const double dV = 2 * M_PI * r * fe_values.JxW(q);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              terms.phi[i]    = fe_values[u].value(i, q);
              terms.strain[i] = axisymmetric_strain(terms.phi[i],
                                                    fe_values[u].gradient(i, q),
                                                    r);
            }
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              // Stiffness, material damping, Maxwell tangent: eps_i : T : eps_j.
              const SymmetricTensor<2, 3> stress_i[3] = {
                tangent[0] * terms.strain[i],
                tangent[1] * terms.strain[i],
                tangent[2] * terms.strain[i]};
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                {
                  terms.matrix[0](i, j) +=
                    rho * (terms.phi[i] * terms.phi[j]) * dV;
                  terms.matrix[1](i, j) += (stress_i[0] * terms.strain[j]) * dV;
                  terms.matrix[3](i, j) += (stress_i[1] * terms.strain[j]) * dV;
                  terms.matrix[4](i, j) += (stress_i[2] * terms.strain[j]) * dV;
                }
              terms.momentum(i) += rho * terms.phi[i][1] * dV;
            }
        }
    }


    // The face terms of a cell on the plate's side and bottom: the
    // absorbing dashpots into C_boundary, the support's springs into K, the
    // bottom's mean.
    void
    add_face_terms(const DoFHandler<2>::active_cell_iterator &cell,
                   const materials::Interface                &material,
                   const PlateFaces                          &plate_faces,
                   const double                               bottom_area,
                   FEFaceValues<2>                           &fe_face_values,
                   CellTerms                                 &terms)
    {
      const FEValuesExtractors::Vector u(0);
      const unsigned int dofs_per_cell = fe_face_values.dofs_per_cell;
      const double       rho           = material.density();
      for (const auto face : cell->face_indices())
        if (cell->face(face)->at_boundary() &&
            (cell->face(face)->boundary_id() == boundary_ids::plate_side ||
             cell->face(face)->boundary_id() == boundary_ids::plate_bottom))
          {
            fe_face_values.reinit(cell, face);
            const bool bottom =
              cell->face(face)->boundary_id() == boundary_ids::plate_bottom;
            const FaceCondition condition =
              plate_faces.of(cell->face(face)->boundary_id());
            // Normal and tangential coefficients of the face term:
            // dashpots rho c_p, rho c_s into C_boundary (absorbing), a
            // normal spring k into K (support).
            const bool   absorbing = condition == FaceCondition::absorbing;
            const bool   support   = condition == FaceCondition::support;
            const double normal_coefficient =
              absorbing ? rho * material.p_wave_speed() :
              support   ? plate_faces.support_stiffness :
                          0;
            const double tangential_coefficient =
              absorbing ? rho * material.s_wave_speed() : 0;
            FullMatrix<double> &face_matrix =
              support ? terms.matrix[1] : terms.matrix[2];
            for (unsigned int q = 0; q < fe_face_values.n_quadrature_points;
                 ++q)
              {
                const double       r  = fe_face_values.quadrature_point(q)[0];
                const double       dA = 2 * M_PI * r * fe_face_values.JxW(q);
                const Tensor<1, 2> n  = fe_face_values.normal_vector(q);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const Tensor<1, 2> phi_i = fe_face_values[u].value(i, q);
                    if (bottom)
                      terms.bottom(i) += phi_i[1] * dA / bottom_area;
                    if (!absorbing && !support)
                      continue;
                    // Lysmer-Kuhlemeyer t = -rho c_p v_n n - rho c_s v_t;
                    // Winkler t = -k u_n n.
                    for (unsigned int j = 0; j < dofs_per_cell; ++j)
                      {
                        const Tensor<1, 2> phi_j =
                          fe_face_values[u].value(j, q);
                        const double normal_i = phi_i * n, normal_j = phi_j * n;
                        face_matrix(i, j) +=
                          (normal_coefficient * normal_i * normal_j +
                           tangential_coefficient *
                             (phi_i * phi_j - normal_i * normal_j)) *
                          dA;
                      }
                  }
              }
          }
    }
  } // namespace


  int
  SpherePlateSetup::interrupt_received()
  {
    return interrupt_signal;
  }


  SpherePlateSetup::InterruptHandler::InterruptHandler()
  {
    previous_interrupt = std::signal(SIGINT, record_interrupt);
    previous_terminate = std::signal(SIGTERM, record_interrupt);
  }


  SpherePlateSetup::InterruptHandler::~InterruptHandler()
  {
    std::signal(SIGINT, previous_interrupt);
    std::signal(SIGTERM, previous_terminate);
  }


  void
  SpherePlateSetup::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
    SpherePlateMesh::declare_parameters(prm);
    MortarContact::declare_parameters(prm);
    time_integration::NonlinearStep::declare_parameters(prm);
  }


  SpherePlateSetup::SpherePlateSetup(ParameterHandler &prm,
                                     const MPI_Comm    comm,
                                     std::ostream     &log,
                                     const Loading    &loading)
    : mpi_communicator(comm)
    , pcout(log, Utilities::MPI::this_mpi_process(comm) == 0)
    , log_is_terminal(is_interactive(log))
    , prm(prm)
    , parameters(prm, loading.expected_contact)
    , triangulation(comm, Triangulation<2>::limit_level_difference_at_vertices)
    , dof_handler(triangulation)
    , solver_control(1, 0)
  {
    if (loading.check)
      loading.check(parameters);
    // The contact the sizes left "auto" are made for.
    const discretisation::ExpectedContact &expected =
      parameters.expected_contact;
    Geometry meshed   = parameters.geometry;
    meshed.hemisphere = loading.hemisphere;
    mesh.parse_parameters(prm, meshed, [&]() {
      return discretisation::AutomaticDiscretisation(
        expected,
        parameters.geometry.sphere_radius,
        parameters.hertz.contact_time());
    });
    discretisation_choice.expected = expected;
    using Rule                     = discretisation::AutomaticDiscretisation;
    discretisation_choice.entries  = {
       {"Mesh/Contact element size",
        "m",
        mesh.contact_element_size,
        mesh.automatic_size[0],
        Rule::contact_element_size_rule()},
       {"Mesh/Uniform zone radius",
        "m",
        mesh.uniform_zone_radius,
        mesh.automatic_size[1],
        Rule::uniform_zone_rule()},
       {"Mesh/Contact surface radius",
        "m",
        mesh.contact_surface_radius,
        mesh.automatic_size[2],
        Rule::contact_surface_rule()},
       {"Mesh/Contact surface refinements",
        "1",
        double(mesh.contact_surface_refinements),
        mesh.automatic_surface_refinements,
        Rule::contact_surface_refinements_rule()}};
    contact.parse_parameters(prm);
    nonlinear_step.parse_parameters(prm);
  }


  void
  SpherePlateSetup::declare_iteration_history(const std::string &other_load)
  {
    history.declare(
      {{result_files::newton_iterations_dataset,
        "1",
        "iterations of the step's nonlinear solve (Nonlinear solver)"},
       {result_files::newton_residual_dataset,
        "1",
        "out-of-balance force of the accepted iterate / (||B^T lambda|| + " +
          other_load + ")"}});
  }


  void
  SpherePlateSetup::require_plate_held(const Parameters &parameters)
  {
    const PlateFaces &faces = parameters.plate_faces;
    AssertThrow(parameters.rigid_plate ||
                  faces.side == FaceCondition::clamped ||
                  faces.bottom == FaceCondition::clamped ||
                  faces.bottom == FaceCondition::support,
                ExcMessage("The 'static press' and 'indentation' analyses "
                           "need a rigid plate or a plate held "
                           "against the load: Scenario/Plate bottom = clamped "
                           "or support, or Plate side = clamped (dashpots and "
                           "free faces carry no static load)."));
  }


  void
  SpherePlateSetup::describe_bodies() const
  {
    // What the bodies are made of, and where each constant came from.
    pcout << "impact-fem: materials\n"
          << parameters.material_used[sphere].describe()
          << parameters.material_used[plate].describe()
          << "impact-fem: discretisation\n"
          << discretisation_choice.describe() << std::flush;
  }


  void
  SpherePlateSetup::check_contact_surface(const double expected_radius) const
  {
    AssertThrow(expected_radius < mesh.contact_surface_radius,
                ExcMessage("Mesh/Contact surface radius (" +
                           as_written(mesh.contact_surface_radius) +
                           " m) is smaller than the expected contact radius "
                           "(Hertz: " +
                           as_written(expected_radius) + " m); increase it."));
  }


  void
  SpherePlateSetup::start_run()
  {
    wall_start      = std::chrono::steady_clock::now();
    computing_timer = std::make_unique<TimerOutput>(mpi_communicator,
                                                    pcout,
                                                    TimerOutput::never,
                                                    TimerOutput::wall_times);
    const std::string &directory = parameters.output_directory;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::filesystem::create_directories(directory);
        // Results of an earlier run in the same place would be mistaken for
        // this run's.
        for (const auto *name : {result_files::history_file,
                                 result_files::incomplete_history_file,
                                 result_files::summary_file})
          std::filesystem::remove(directory + "/" + name);
      }
    MPI_Barrier(mpi_communicator);
  }


  const materials::Interface &
  SpherePlateSetup::material_of(const types::material_id body) const
  {
    return *parameters.material[body == body_ids::sphere ? sphere : plate];
  }


  void
  SpherePlateSetup::make_mesh()
  {
    TimerOutput::Scope t(*computing_timer, "make mesh");
    mesh.create(triangulation, parameters.output_directory);
    fe      = std::make_unique<FESystem<2>>(FE_Q<2>(mesh.polynomial_degree), 2);
    mapping = std::make_unique<MappingQ<2>>(mesh.polynomial_degree);
    quadrature = std::make_unique<QGauss<2>>(impact_fem::cell_quadrature(*fe));
  }


  void
  SpherePlateSetup::setup_system()
  {
    TimerOutput::Scope t(*computing_timer, "setup system");
    dof_handler.distribute_dofs(*fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    // u_r = 0 on the axis; a clamped face of the plate is fixed.
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    const FEValuesExtractors::Scalar radial(0);
    VectorTools::interpolate_boundary_values(*mapping,
                                             dof_handler,
                                             boundary_ids::axis,
                                             Functions::ZeroFunction<2>(2),
                                             constraints,
                                             fe->component_mask(radial));
    for (const auto id : {boundary_ids::plate_side, boundary_ids::plate_bottom})
      if (parameters.plate_faces.of(id) == FaceCondition::clamped)
        VectorTools::interpolate_boundary_values(*mapping,
                                                 dof_handler,
                                                 id,
                                                 Functions::ZeroFunction<2>(2),
                                                 constraints);
    constraints.close();

    TrilinosWrappers::SparsityPattern sparsity(locally_owned_dofs,
                                               locally_owned_dofs,
                                               locally_relevant_dofs,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
    for (auto *matrix : {&system.mass,
                         &system.stiffness,
                         &system.boundary_damping,
                         &system.material_damping,
                         &system.internal_stiffness,
                         &effective_stiffness})
      matrix->reinit(sparsity);
    for (auto *vector : {&weights.sphere_momentum,
                         &weights.plate_momentum,
                         &weights.plate_bottom_mean,
                         &weights.sphere_mask,
                         &weights.body_force})
      vector->reinit(locally_owned_dofs, mpi_communicator);
    for (auto *vector : {&ghosted_u, &ghosted_trial})
      vector->reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);

    pcout << "  mesh: " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " degrees of freedom (Q"
          << mesh.polynomial_degree << ")" << std::endl;
  }


  void
  SpherePlateSetup::assemble_system(const double dt)
  {
    TimerOutput::Scope t(*computing_timer, "assemble system");

    const QGauss<1>                       face_rule = face_quadrature(*fe);
    FEValues<2>                           fe_values(*mapping,
                          *fe,
                          *quadrature,
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    FEFaceValues<2>                       fe_face_values(*mapping,
                                   *fe,
                                   face_rule,
                                   update_values | update_quadrature_points |
                                     update_normal_vectors | update_JxW_values);
    const unsigned int                    dofs_per_cell = fe->n_dofs_per_cell();
    CellTerms                             terms(dofs_per_cell);
    TrilinosWrappers::SparseMatrix *const global_matrix[5] = {
      &system.mass,
      &system.stiffness,
      &system.boundary_damping,
      &system.material_damping,
      &system.internal_stiffness};
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    const double bottom_area = M_PI * parameters.geometry.plate_radius *
                               parameters.geometry.plate_radius;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &material  = material_of(cell->material_id());
          const bool  on_sphere = cell->material_id() == body_ids::sphere;
          for (auto &m : terms.matrix)
            m = 0;
          terms.momentum = 0;
          terms.bottom   = 0;
          add_volume_terms(cell, material, dt, fe_values, terms);
          add_face_terms(cell,
                         material,
                         parameters.plate_faces,
                         bottom_area,
                         fe_face_values,
                         terms);

          cell->get_dof_indices(local_dofs);
          for (unsigned int m = 0; m < 5; ++m)
            constraints.distribute_local_to_global(terms.matrix[m],
                                                   local_dofs,
                                                   *global_matrix[m]);
          constraints.distribute_local_to_global(terms.momentum,
                                                 local_dofs,
                                                 on_sphere ?
                                                   weights.sphere_momentum :
                                                   weights.plate_momentum);
          constraints.distribute_local_to_global(terms.bottom,
                                                 local_dofs,
                                                 weights.plate_bottom_mean);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            if (on_sphere && locally_owned_dofs.is_element(local_dofs[i]))
              weights.sphere_mask[local_dofs[i]] = 1;
        }

    for (auto *matrix : global_matrix)
      matrix->compress(VectorOperation::add);
    weights.sphere_momentum.compress(VectorOperation::add);
    weights.plate_momentum.compress(VectorOperation::add);
    weights.plate_bottom_mean.compress(VectorOperation::add);
    weights.sphere_mask.compress(VectorOperation::insert);
  }


  void
  SpherePlateSetup::factorize()
  {
    direct_solver = direct_solver_of(effective_stiffness, true);
  }


  std::unique_ptr<TrilinosWrappers::SolverDirect>
  SpherePlateSetup::direct_solver_of(
    const TrilinosWrappers::SparseMatrix &matrix,
    const bool                            say_which)
  {
    // "auto": the faster solver measured for the run's kind
    // (doc/results/fem-model.md, "Parallel"): KLU's back-substitution on one
    // rank when the steps iterate on the factorisation (an elastic-plastic
    // body), MUMPS otherwise.
    std::string solver = parameters.direct_solver;
    if (solver == "auto")
      {
        const bool plastic = !material_of(body_ids::sphere).is_linear() ||
                             (!parameters.rigid_plate &&
                              !material_of(body_ids::plate).is_linear());
        const bool one_rank =
          Utilities::MPI::n_mpi_processes(mpi_communicator) == 1;
        solver = plastic && one_rank ? "Amesos_Klu" : "Amesos_Mumps";
        if (say_which)
          pcout << "  Solver/Direct solver = " << solver << "  (auto: "
                << (plastic ? "an elastic-plastic body" : "elastic bodies")
                << ", " << (one_rank ? "one rank" : "several ranks") << ")"
                << std::endl;
      }
    auto factorisation = std::make_unique<TrilinosWrappers::SolverDirect>(
      solver_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, solver));
    factorisation->initialize(matrix);
    return factorisation;
  }


  void
  SpherePlateSetup::initialize_internal_variables()
  {
    arms.initialize(
      dof_handler,
      *mapping,
      *quadrature,
      [this](const types::material_id id) -> const materials::Interface & {
        return material_of(id);
      },
      ghosted_u);
  }


  void
  SpherePlateSetup::setup_contact()
  {
    TimerOutput::Scope t(*computing_timer, "setup contact");
    contact.setup(dof_handler, *mapping, constraints, parameters.rigid_plate);
    contact.compute_influence(
      [this](VectorType &x, const VectorType &b) {
        direct_solver->solve(x, b);
      },
      locally_owned_dofs,
      mpi_communicator);
    pressures.reinit(contact.n_contact_nodes());
    pcout << "  contact: " << contact.n_contact_nodes()
          << (parameters.rigid_plate ?
                " nodes on the sphere's contact surface (rigid flat)" :
                " nodes on the plate's contact surface")
          << std::endl;
  }


  void
  SpherePlateSetup::solve_linear_step(const VectorType &rhs,
                                      VectorType       &displacement)
  {
    {
      TimerOutput::Scope t(*computing_timer, "solve free step");
      direct_solver->solve(displacement, rhs);
    }
    TimerOutput::Scope t(*computing_timer, "solve contact");
    pressures =
      contact.solve_complementarity(contact.weighted_gaps(displacement));
    contact.add_contact_response(pressures, displacement);
  }


  std::map<std::string, std::string>
  SpherePlateSetup::parameter_attributes() const
  {
    std::stringstream prm_json;
    prm.print_parameters(prm_json, ParameterHandler::ShortJSON);
    std::map<std::string, std::string> entries;
    flatten(nlohmann::json::parse(prm_json.str()), "", entries);
    // The constants a run used, wherever they came from (the scenario or
    // the material table), under their entries' names.
    for (const auto &body : parameters.material_used)
      for (const auto &constant : body.constants)
        entries[constant.parameter] = as_written(constant.value);
    // The sizes and the step a run used, "auto" resolved.
    for (const auto &entry : discretisation_choice.entries)
      entries[entry.path] = as_written(entry.value);
    return entries;
  }
} // namespace impact_fem
