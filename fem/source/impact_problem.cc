#include <impact_fem/as_written.h>
#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/quadrature.h>
#include <impact_fem/summary/impact_summary.h>
#include <impact_fem/result_files.h>

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
#include <fstream>
#include <iomanip>
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

    /// Catch SIGINT and SIGTERM while it lives, restore the old handlers after.
    /// A signal once received stays recorded (it is not reset for the next run
    /// of a campaign), so that a campaign stops instead of losing it.
    class ScopedInterruptHandler
    {
    public:
      ScopedInterruptHandler()
      {
        previous_interrupt = std::signal(SIGINT, record_interrupt);
        previous_terminate = std::signal(SIGTERM, record_interrupt);
      }
      ~ScopedInterruptHandler()
      {
        std::signal(SIGINT, previous_interrupt);
        std::signal(SIGTERM, previous_terminate);
      }

    private:
      void (*previous_interrupt)(int);
      void (*previous_terminate)(int);
    };


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

    nlohmann::json
    number(const double x)
    {
      return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
    }
  } // namespace


  int
  ImpactProblem::interrupt_received()
  {
    return interrupt_signal;
  }


  void
  ImpactProblem::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
    time_integration::NonlinearStep::declare_parameters(prm);
  }


  ImpactProblem::ImpactProblem(ParameterHandler &prm,
                               const MPI_Comm    comm,
                               std::ostream     &log)
    : mpi_communicator(comm)
    , pcout(log, Utilities::MPI::this_mpi_process(comm) == 0)
    , log_is_terminal(is_interactive(log))
    , prm(prm)
    , parameters(prm)
    , time_stepper(time_integration::create_time_stepper(prm))
    , postprocessors(postprocess::create_postprocessors(prm))
    , triangulation(comm, Triangulation<2>::limit_level_difference_at_vertices)
    , dof_handler(triangulation)
    , solver_control(1, 0)
  {
    if (parameters.indentation)
      indentation_control.parse_parameters(prm);
    // The contact the sizes left "auto" are made for.
    const discretisation::ExpectedContact expected =
      parameters.indentation ?
        discretisation::ExpectedContact::of_indentation(
          parameters.hertz, indentation_control.maximum_approach) :
        parameters.expected_contact;
    mesh.parse_parameters(prm, parameters.geometry, [&]() {
      return discretisation::AutomaticDiscretisation(
        expected,
        parameters.geometry.sphere_radius,
        parameters.hertz.contact_time());
    });
    discretisation_choice.expected = expected;
    using Rule                     = discretisation::AutomaticDiscretisation;
    discretisation_choice.entries  = {{"Mesh/Contact element size",
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
                                       Rule::contact_surface_rule()}};
    if (!parameters.static_press && !parameters.indentation &&
        parameters.prescribed_time_step == 0)
      discretisation_choice.entries.push_back(
        {"Time integration/Steps per contact time",
         "1",
         parameters.steps_per_contact_time,
         parameters.steps_per_contact_time_automatic,
         discretisation::AutomaticDiscretisation::steps_rule()});
    contact.parse_parameters(prm);
    nonlinear_step.parse_parameters(prm);
    // What the bodies are made of, and where each constant came from.
    pcout << "impact-fem: materials\n"
          << parameters.material_used[sphere].describe()
          << parameters.material_used[plate].describe()
          << "impact-fem: discretisation\n"
          << discretisation_choice.describe() << std::flush;
    const HertzImpact &hertz = parameters.hertz;
    const double       expected_contact_radius =
      parameters.indentation ? std::sqrt(parameters.geometry.sphere_radius *
                                         indentation_control.maximum_approach) :
                                     hertz.contact_radius_max();
    AssertThrow(parameters.static_press ||
                  expected_contact_radius < mesh.contact_surface_radius,
                ExcMessage("Mesh/Contact surface radius (" +
                           as_written(mesh.contact_surface_radius) +
                           " m) is smaller than the expected contact radius "
                           "(Hertz: " +
                           as_written(expected_contact_radius) +
                           " m); increase it."));
    if (parameters.indentation)
      {
        const double omega = indentation_control.maximum_approach;
        pcout << "impact-fem: indentation of a hemisphere R = "
              << parameters.geometry.sphere_radius * 1e3 << " mm to "
              << omega * 1e6 << " um in " << indentation_control.steps
              << " steps" << (parameters.rigid_plate ? " (rigid flat)" : "")
              << "\n  Hertz at the maximum approach: force "
              << hertz.stiffness() * std::pow(omega, 1.5)
              << " N, contact radius " << expected_contact_radius * 1e3 << " mm"
              << std::endl;
        return;
      }
    pcout << "impact-fem: sphere R = "
          << parameters.geometry.sphere_radius * 1e3
          << " mm, m = " << parameters.sphere_mass
          << " kg, V = " << parameters.impact_velocity << " m/s\n"
          << "  Hertz: approach " << hertz.approach_max() * 1e6 << " um, force "
          << hertz.force_max() / 1e3 << " kN, contact radius "
          << hertz.contact_radius_max() * 1e3 << " mm, contact time "
          << hertz.contact_time() * 1e6 << " us\n"
          << "  time step "
          << parameters.time_step(time_stepper->mass_weight()) * 1e9 << " ns ("
          << parameters.scheme << ") on "
          << Utilities::MPI::n_mpi_processes(comm) << " rank(s)" << std::endl;
  }


  const materials::Interface &
  ImpactProblem::material_of(const types::material_id body) const
  {
    return *parameters.material[body == body_ids::sphere ? sphere : plate];
  }


  double
  ImpactProblem::expected_end_time() const
  {
    if (separation_time >= 0)
      return end_time;
    const double flight =
      parameters.geometry.initial_gap / parameters.impact_velocity;
    return std::min(end_time,
                    flight + parameters.hertz.contact_time() *
                               (1 + parameters.time_after_separation));
  }


  void
  ImpactProblem::make_mesh()
  {
    TimerOutput::Scope t(*computing_timer, "make mesh");
    mesh.create(triangulation, parameters.output_directory);
    fe      = std::make_unique<FESystem<2>>(FE_Q<2>(mesh.polynomial_degree), 2);
    mapping = std::make_unique<MappingQ<2>>(mesh.polynomial_degree);
    quadrature = std::make_unique<QGauss<2>>(impact_fem::cell_quadrature(*fe));
  }


  void
  ImpactProblem::setup_system()
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
                         &weights.body_force,
                         &internal_force_predictor})
      vector->reinit(locally_owned_dofs, mpi_communicator);
    for (auto *vector : {&ghosted_u, &ghosted_v, &ghosted_trial})
      vector->reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);

    pcout << "  mesh: " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " degrees of freedom (Q"
          << mesh.polynomial_degree << ")" << std::endl;
  }


  void
  ImpactProblem::assemble_system()
  {
    TimerOutput::Scope t(*computing_timer, "assemble system");

    const QGauss<1>    face_rule = face_quadrature(*fe);
    FEValues<2>        fe_values(*mapping,
                          *fe,
                          *quadrature,
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    FEFaceValues<2>    fe_face_values(*mapping,
                                   *fe,
                                   face_rule,
                                   update_values | update_quadrature_points |
                                     update_normal_vectors | update_JxW_values);
    const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
    // The cell matrices of M, K, C_boundary, C_material, K_internal.
    std::vector<FullMatrix<double>> cell_matrix(
      5, FullMatrix<double>(dofs_per_cell, dofs_per_cell));
    TrilinosWrappers::SparseMatrix *const global_matrix[5] = {
      &system.mass,
      &system.stiffness,
      &system.boundary_damping,
      &system.material_damping,
      &system.internal_stiffness};
    Vector<double> cell_momentum(dofs_per_cell), cell_bottom(dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<SymmetricTensor<2, 3>>   strain(dofs_per_cell);
    std::vector<Tensor<1, 2>>            phi(dofs_per_cell);
    const FEValuesExtractors::Vector     u(0);
    const double bottom_area = M_PI * parameters.geometry.plate_radius *
                               parameters.geometry.plate_radius;
    const double dt = parameters.time_step(time_stepper->mass_weight());

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &material = material_of(cell->material_id());
          const SymmetricTensor<4, 3> tangent[3] = {
            material.stiffness_tangent(),
            material.damping_tangent(),
            material.internal_tangent(dt)};
          const double rho       = material.density();
          const bool   on_sphere = cell->material_id() == body_ids::sphere;
          for (auto &m : cell_matrix)
            m = 0;
          cell_momentum = 0;
          cell_bottom   = 0;

          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature->size(); ++q)
            {
              const double r = fe_values.quadrature_point(q)[0];
              // The r-weighted measure of the axisymmetric body (2 pi r).
              const double dV = 2 * M_PI * r * fe_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  phi[i] = fe_values[u].value(i, q);
                  strain[i] =
                    axisymmetric_strain(phi[i], fe_values[u].gradient(i, q), r);
                }
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  // Stiffness, material damping, Maxwell tangent: eps_i : T : eps_j.
                  const SymmetricTensor<2, 3> stress_i[3] = {
                    tangent[0] * strain[i],
                    tangent[1] * strain[i],
                    tangent[2] * strain[i]};
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    {
                      cell_matrix[0](i, j) += rho * (phi[i] * phi[j]) * dV;
                      cell_matrix[1](i, j) += (stress_i[0] * strain[j]) * dV;
                      cell_matrix[3](i, j) += (stress_i[1] * strain[j]) * dV;
                      cell_matrix[4](i, j) += (stress_i[2] * strain[j]) * dV;
                    }
                  cell_momentum(i) += rho * phi[i][1] * dV;
                }
            }

          for (const auto face : cell->face_indices())
            if (cell->face(face)->at_boundary() &&
                (cell->face(face)->boundary_id() == boundary_ids::plate_side ||
                 cell->face(face)->boundary_id() == boundary_ids::plate_bottom))
              {
                fe_face_values.reinit(cell, face);
                const bool bottom =
                  cell->face(face)->boundary_id() == boundary_ids::plate_bottom;
                const FaceCondition condition =
                  parameters.plate_faces.of(cell->face(face)->boundary_id());
                // Normal and tangential coefficients of the face term:
                // dashpots rho c_p, rho c_s into C_boundary (absorbing), a
                // normal spring k into K (support).
                const bool   absorbing = condition == FaceCondition::absorbing;
                const bool   support   = condition == FaceCondition::support;
                const double normal_coefficient =
                  absorbing ? rho * material.p_wave_speed() :
                  support   ? parameters.plate_faces.support_stiffness :
                              0;
                const double tangential_coefficient =
                  absorbing ? rho * material.s_wave_speed() : 0;
                FullMatrix<double> &face_matrix =
                  support ? cell_matrix[1] : cell_matrix[2];
                for (unsigned int q = 0; q < face_rule.size(); ++q)
                  {
                    const double r  = fe_face_values.quadrature_point(q)[0];
                    const double dA = 2 * M_PI * r * fe_face_values.JxW(q);
                    const Tensor<1, 2> n = fe_face_values.normal_vector(q);
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        const Tensor<1, 2> phi_i =
                          fe_face_values[u].value(i, q);
                        if (bottom)
                          cell_bottom(i) += phi_i[1] * dA / bottom_area;
                        if (!absorbing && !support)
                          continue;
                        // Lysmer-Kuhlemeyer t = -rho c_p v_n n - rho c_s v_t;
                        // Winkler t = -k u_n n.
                        for (unsigned int j = 0; j < dofs_per_cell; ++j)
                          {
                            const Tensor<1, 2> phi_j =
                              fe_face_values[u].value(j, q);
                            const double normal_i = phi_i * n,
                                         normal_j = phi_j * n;
                            face_matrix(i, j) +=
                              (normal_coefficient * normal_i * normal_j +
                               tangential_coefficient *
                                 (phi_i * phi_j - normal_i * normal_j)) *
                              dA;
                          }
                      }
                  }
              }

          cell->get_dof_indices(local_dofs);
          for (unsigned int m = 0; m < 5; ++m)
            constraints.distribute_local_to_global(cell_matrix[m],
                                                   local_dofs,
                                                   *global_matrix[m]);
          constraints.distribute_local_to_global(cell_momentum,
                                                 local_dofs,
                                                 on_sphere ?
                                                   weights.sphere_momentum :
                                                   weights.plate_momentum);
          constraints.distribute_local_to_global(cell_bottom,
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

    // Gravity on the sphere: f = -g M e_z restricted to the sphere.
    weights.body_force = weights.sphere_momentum;
    weights.body_force *= -(parameters.static_press ?
                              parameters.static_force / parameters.sphere_mass :
                              parameters.gravity);
  }


  void
  ImpactProblem::factorize_effective_stiffness()
  {
    TimerOutput::Scope t(*computing_timer, "factorize");
    const double       dt = parameters.time_step(time_stepper->mass_weight());
    effective_stiffness.copy_from(system.stiffness);
    effective_stiffness.add(time_stepper->mass_weight() / (dt * dt),
                            system.mass);
    effective_stiffness.add(time_stepper->damping_weight() / dt,
                            system.boundary_damping);
    effective_stiffness.add(time_stepper->damping_weight() / dt,
                            system.material_damping);
    // The Maxwell arms' algorithmic tangent (constant for a constant step).
    effective_stiffness.add(1., system.internal_stiffness);
    direct_solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      solver_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                     parameters.direct_solver));
    direct_solver->initialize(effective_stiffness);
  }


  void
  ImpactProblem::setup_contact()
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
  ImpactProblem::set_initial_conditions()
  {
    // The sphere moves down rigidly (-V e_z), the plate rests; before
    // contact the sphere is free, so a = -g e_z exactly.
    const IndexSet vertical_dofs =
      DoFTools::extract_dofs(dof_handler,
                             fe->component_mask(FEValuesExtractors::Scalar(1)));
    VectorType sphere_vertical(weights.sphere_mask);
    for (const auto i : locally_owned_dofs)
      if (!vertical_dofs.is_element(i))
        sphere_vertical[i] = 0;
    sphere_vertical.compress(VectorOperation::insert);
    constraints.set_zero(sphere_vertical);

    const bool   impact = !parameters.static_press;
    const double V = parameters.impact_velocity, g = parameters.gravity;
    const double g0 = parameters.geometry.initial_gap;
    // The flight across the initial gap is a rigid motion known exactly:
    // start at the first contact, so that every time step serves the
    // contact phase.
    const double t0 =
      impact && g0 > 0 ?
        (g > 0 ? (std::sqrt(V * V + 2 * g * g0) - V) / g : g0 / V) :
        0.;
    VectorType u0(locally_owned_dofs, mpi_communicator), v0(u0), a0(u0);
    u0.equ(impact ? -g0 : 0., sphere_vertical);
    first_contact_speed = impact ? V + g * t0 : 0.;
    v0.equ(-first_contact_speed, sphere_vertical);
    a0.equ(impact ? -g : 0., sphere_vertical);
    const double dt = parameters.time_step(time_stepper->mass_weight());
    time_stepper->initialize(u0, v0, a0, t0, dt);
    end_time = parameters.end_time(dt);

    // The bodies start unstrained (the flight is rigid) with relaxed arms.
    arms.initialize(
      dof_handler,
      *mapping,
      *quadrature,
      [this](const types::material_id id) -> const materials::Interface & {
        return material_of(id);
      },
      ghosted_u);
    internal_force_predictor = 0;
    refresh_ghosted_state();
  }


  void
  ImpactProblem::refresh_ghosted_state()
  {
    VectorType distributed(time_stepper->displacement());
    constraints.distribute(distributed);
    ghosted_u   = distributed;
    distributed = time_stepper->velocity();
    constraints.distribute(distributed);
    ghosted_v = distributed;
  }


  void
  ImpactProblem::solve_time_step()
  {
    VectorType rhs(locally_owned_dofs, mpi_communicator), mass_term(rhs),
      damping_term(rhs), damping_force(rhs), displacement(rhs);
    {
      TimerOutput::Scope t(*computing_timer, "assemble right-hand side");
      // f + M m + C c - (Maxwell arms' history force)
      time_stepper->history_terms(mass_term, damping_term);
      system.mass.vmult(rhs, mass_term);
      system.boundary_damping.vmult(damping_force, damping_term);
      rhs += damping_force;
      if (parameters.has_material_damping())
        {
          system.material_damping.vmult(damping_force, damping_term);
          rhs += damping_force;
        }
      rhs += weights.body_force;
      rhs -= internal_force_predictor;
    }
    if (arms.nonlinear())
      solve_nonlinear_step(rhs, displacement);
    else
      solve_linear_step(rhs, displacement);
    TimerOutput::Scope t(*computing_timer, "update state");
    time_stepper->advance(displacement);
    refresh_ghosted_state();
    if (arms.active())
      arms.update(dof_handler,
                  *mapping,
                  *quadrature,
                  constraints,
                  ghosted_u,
                  time_stepper->time_step(),
                  internal_force_predictor);
  }


  void
  ImpactProblem::solve_linear_step(const VectorType &rhs,
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


  void
  ImpactProblem::solve_nonlinear_step(const VectorType &rhs,
                                      VectorType       &displacement)
  {
    // The linear step with contact for a given plastic force f: K_eff u =
    // rhs + f + B^T lambda; returns the norm of the step's external forces.
    VectorType load(rhs), contact_force(rhs), distributed(rhs);
    const auto linear_solve = [&](const VectorType &plastic_force,
                                  VectorType       &u) {
      load = rhs;
      load += plastic_force;
      solve_linear_step(load, u);
      contact_force = 0;
      contact.add_contact_forces(pressures, contact_force);
      return contact_force.l2_norm() + weights.body_force.l2_norm();
    };
    const double dt            = time_stepper->time_step();
    const auto   plastic_force = [&](const VectorType &u, VectorType &force) {
      TimerOutput::Scope t(*computing_timer, "plastic force");
      distributed = u;
      constraints.distribute(distributed);
      ghosted_trial = distributed;
      arms.plastic_force(constraints, ghosted_trial, dt, force);
    };
    // Solved on the cells near yielding; again with the cells that the
    // states at the converged displacement add, if a point elsewhere yielded.
    auto         result = nonlinear_step.solve(arms.predicted_plastic_force(),
                                       time_stepper->displacement(),
                                       displacement,
                                       linear_solve,
                                       plastic_force);
    unsigned int iterations     = result.iterations;
    const auto   prepare_commit = [&]() {
      TimerOutput::Scope t(*computing_timer, "plastic state");
      return arms.prepare_commit(constraints, ghosted_trial, dt);
    };
    while (result.converged && !prepare_commit())
      {
        result = nonlinear_step.solve(arms.predicted_plastic_force(),
                                      time_stepper->displacement(),
                                      displacement,
                                      linear_solve,
                                      plastic_force);
        iterations += result.iterations;
      }
    result.iterations = iterations;
    step_iterations   = result.iterations;
    step_residual     = result.residual;
    if (!result.converged)
      {
        std::ostringstream message;
        message << std::setprecision(4) << "Time step "
                << time_stepper->step_number() + 1
                << " (t = " << time_stepper->time() + dt
                << " s) did not converge: after " << result.iterations
                << " iterations the residual is " << result.residual
                << " of the load and the increment " << result.increment
                << " of the step's; required " << nonlinear_step.criterion()
                << ".";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }


  void
  ImpactProblem::postprocess_step()
  {
    if (arms.nonlinear())
      {
        history.append(result_files::newton_iterations_dataset,
                       step_iterations);
        history.append(result_files::newton_residual_dataset, step_residual);
      }
    history.append(result_files::time_dataset, time_stepper->time());
    for (auto &[name, postprocessor] : postprocessors)
      {
        TimerOutput::Scope t(*computing_timer, "postprocess: " + name);
        postprocessor->execute(*this, history);
      }
    // Phases of the impact: the run ends a fraction of the contact time
    // after the bodies separate.
    const double force = contact.total_force(pressures);
    const double now   = time_stepper->time();
    if (force > 0 && first_force_time < 0)
      first_force_time = now - time_stepper->time_step();
    else if (force <= 0 && first_force_time >= 0 && separation_time < 0)
      {
        separation_time = now;
        end_time        = std::min(end_time,
                            now + parameters.time_after_separation *
                                    (now - first_force_time));
      }
  }


  std::map<std::string, std::string>
  ImpactProblem::parameter_attributes() const
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


  void
  ImpactProblem::write_results(const bool complete)
  {
    const double wall_time = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - wall_start)
                               .count();
    const summary::ImpactSummary s =
      summary::summarize_impact(history[result_files::time_dataset],
                                history[result_files::contact_force_dataset],
                                history[result_files::approach_dataset],
                                history[result_files::sphere_velocity_dataset],
                                first_contact_speed,
                                parameters.gravity,
                                parameters.static_press ?
                                  summary::nan :
                                  history[result_files::time_dataset].front());

    nlohmann::json     result;
    std::ostringstream report;
    result[result_files::complete_key]           = complete;
    result[result_files::impact_velocity_key]    = parameters.impact_velocity;
    result[result_files::contact_velocity_key]   = first_contact_speed;
    result[result_files::first_contact_time_key] = number(s.first_contact_time);
    result["separation_time"]                    = number(s.separation_time);
    result[result_files::contact_time_key]       = number(s.contact_time);
    result[result_files::force_max_key]          = number(s.force_max);
    result[result_files::time_force_max_key]     = number(s.time_force_max);
    result[result_files::approach_max_key]       = number(s.approach_max);
    result["time_approach_max"]                  = number(s.time_approach_max);
    result[result_files::rebound_velocity_key]   = number(s.rebound_velocity);
    result[result_files::restitution_key]        = number(s.restitution);
    result[result_files::lost_energy_fraction_key] =
      number(1 - s.restitution * s.restitution);
    result[result_files::force_oscillation_key] = number(s.force_oscillation);
    result[result_files::force_after_release_key] =
      number(s.force_after_release);
    for (auto &[name, postprocessor] : postprocessors)
      postprocessor->finalize(*this, history, result, report);
    result[result_files::sphere_mass_key] = parameters.sphere_mass;
    result[result_files::materials_key]   = {
        {body_name(sphere), parameters.material_used[sphere].to_json()},
        {body_name(plate), parameters.material_used[plate].to_json()}};
    result[result_files::discretisation_key] = discretisation_choice.to_json();
    result["scheme"]                         = parameters.scheme;
    result[result_files::time_step_key]      = time_stepper->time_step();
    result["cells"]         = triangulation.n_global_active_cells();
    result["dofs"]          = dof_handler.n_dofs();
    result["contact_nodes"] = contact.n_contact_nodes();
    result["steps"]         = time_stepper->step_number();
    result["ranks"]         = Utilities::MPI::n_mpi_processes(mpi_communicator);
    result["wall_time"]     = wall_time;

    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;

    // The parameters, the derived results and their definitions travel
    // with the histories.
    std::map<std::string, std::string> text_attributes = parameter_attributes();
    text_attributes["definition: contact_time"] =
      "separation_time - first_contact_time; both are zeros of the power law "
      "F = A |t - t*|^p through the three force samples next to each end of "
      "the contact phase (first run of F > 0), kept within the bracketing step";
    text_attributes["definition: force_max"] =
      "vertex of the parabola through the largest force sample and its "
      "neighbours (time_force_max its time; approach_max likewise)";
    text_attributes["definition: force_oscillation"] =
      "max |F_i - (F_{i-1} + F_{i+1})/2| / force_max inside the contact phase, "
      "5 samples at each end excluded";
    text_attributes["definition: force_after_release"] =
      "max F after the first zero-force sample following the peak / force_max";
    std::map<std::string, double> numeric_attributes;
    for (const auto &[key, value] : result.items())
      if (value.is_number())
        numeric_attributes[result_files::result_attribute_prefix + key] =
          value.get<double>();
    numeric_attributes[result_files::sphere_mass_attribute] =
      parameters.sphere_mass;
    numeric_attributes["hertz_contact_time [s]"] =
      parameters.hertz.contact_time();
    history.write_hdf5(parameters.output_directory + "/" +
                         result_files::history_file,
                       text_attributes,
                       numeric_attributes,
                       complete);
    if (!complete)
      return;

    const std::string summary_file =
      parameters.output_directory + "/" + result_files::summary_file;
    {
      std::ofstream out(summary_file + ".tmp");
      out << std::setw(2) << result << std::endl;
    }
    std::filesystem::rename(summary_file + ".tmp", summary_file);

    const std::size_t n = history.n_steps();
    pcout << "\nResult (" << parameters.output_directory << "):\n"
          << std::setprecision(5);
    if (parameters.static_press)
      pcout << "  contact force     "
            << history[result_files::contact_force_dataset][n - 1] << " N\n"
            << "  contact radius    " << history["contact_radius"][n - 1] * 1e3
            << " mm\n"
            << "  max pressure      " << history["max_pressure"][n - 1] / 1e9
            << " GPa\n"
            << "  approach          "
            << history[result_files::approach_dataset][n - 1] * 1e6 << " um\n";
    else
      pcout << "  first contact     " << s.first_contact_time * 1e6
            << " us, separation " << s.separation_time * 1e6 << " us\n"
            << "  contact time      " << s.contact_time * 1e6 << " us\n"
            << "  peak force        " << s.force_max / 1e3 << " kN at "
            << s.time_force_max * 1e6 << " us\n"
            << "  peak approach     " << s.approach_max * 1e6 << " um\n"
            << "  rebound velocity  " << s.rebound_velocity << " m/s\n"
            << "  restitution       " << s.restitution
            << " (lost energy fraction "
            << (1 - s.restitution * s.restitution) * 100 << " %)\n"
            << "  force oscillation " << s.force_oscillation * 100
            << " % of the peak step to step, " << s.force_after_release * 100
            << " % after release\n";
    pcout << report.str() << "  cells " << triangulation.n_global_active_cells()
          << ", dofs " << dof_handler.n_dofs() << ", steps "
          << time_stepper->step_number() << " (" << parameters.scheme
          << "), ranks " << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << ", wall time " << wall_time << " s" << std::endl;
  }


  void
  ImpactProblem::run()
  {
    // Installed before anything else: a signal during the setup is kept
    // and stops the run at the first step, leaving history.incomplete.h5.
    const ScopedInterruptHandler interrupt_handler;
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

    make_mesh();
    setup_system();
    assemble_system();
    if (parameters.indentation)
      {
        run_indentation();
        computing_timer->print_summary();
        return;
      }
    factorize_effective_stiffness();
    setup_contact();
    set_initial_conditions();
    history.declare(result_files::time_dataset,
                    result_files::time_unit,
                    "simulated time");
    if (arms.nonlinear())
      history.declare(
        {{result_files::newton_iterations_dataset,
          "1",
          "iterations of the step's nonlinear solve (Nonlinear solver)"},
         {result_files::newton_residual_dataset,
          "1",
          "out-of-balance force of the accepted iterate / (||B^T lambda|| + "
          "||f_body||)"}});
    for (auto &[name, postprocessor] : postprocessors)
      postprocessor->initialize(*this, history);
    postprocess_step();

    // An interrupted run (SIGINT, SIGTERM) and a failing one keep what they
    // computed in history.incomplete.h5. It is also written after the first
    // step and refreshed every minute, so that even a killed run leaves its
    // history behind: mpirun kills ranks that have not stopped within a
    // second of its SIGTERM, and a rank in a long step (or on a loaded
    // machine) cannot reach its next check in that time.
    // Checked before every step and once more after the last one, so that a
    // signal received at any time of the loop leaves the run incomplete.
    const auto stop_if_interrupted = [&]() {
      const int signal = Utilities::MPI::max(static_cast<int>(interrupt_signal),
                                             mpi_communicator);
      AssertThrow(signal == 0,
                  ExcMessage("Interrupted by signal " + std::to_string(signal) +
                             " at t = " + as_written(time_stepper->time()) +
                             " s; the history so far is in " + directory +
                             "/history.incomplete.h5."));
    };
    auto last_checkpoint = std::chrono::steady_clock::now();
    try
      {
        while (time_stepper->time() <
               end_time - 0.5 * time_stepper->time_step())
          {
            stop_if_interrupted();
            solve_time_step();
            postprocess_step();
            const bool checkpoint_due =
              time_stepper->step_number() == 1 ||
              Utilities::MPI::broadcast(mpi_communicator,
                                        std::chrono::steady_clock::now() -
                                            last_checkpoint >
                                          std::chrono::seconds(60),
                                        0);
            if (checkpoint_due)
              {
                write_results(false);
                last_checkpoint = std::chrono::steady_clock::now();
              }
          }
        stop_if_interrupted();
      }
    catch (...)
      {
        // Keep what was computed, marked incomplete, then report the cause.
        write_results(false);
        throw;
      }
    if (separation_time < 0 && !parameters.static_press)
      pcout << "Warning: the bodies did not separate before the end of the "
               "run (Time integration/Maximum time)."
            << std::endl;
    write_results(true);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::remove(directory + "/history.incomplete.h5");
    computing_timer->print_summary();
  }
} // namespace impact_fem
