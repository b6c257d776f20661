#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/hertz.h>
#include <impact_fem/impact_problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
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


    double
    von_mises(const SymmetricTensor<2, 3> &stress)
    {
      const SymmetricTensor<2, 3> s = deviator(stress);
      return std::sqrt(1.5 * scalar_product(s, s));
    }


    /**
     * The total stress at the quadrature points of a cell: elastic, viscous
     * (Kelvin-Voigt; the velocity is read only for a viscous material) and
     * that of the Maxwell arms (from the quadrature-point states, empty for
     * a material without internal variables).
     */
    class CellStress
    {
    public:
      CellStress(const Mapping<2> &mapping, const FiniteElement<2> &fe)
        : quadrature(fe.degree + 1)
        , fe_values(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_quadrature_points)
        , values(quadrature.size())
        , velocity_values(quadrature.size())
        , gradients(quadrature.size())
        , velocity_gradients(quadrature.size())
        , stress(quadrature.size())
      {}

      template <typename CellIterator, typename VectorType, typename States>
      const std::vector<SymmetricTensor<2, 3>> &
      evaluate(const CellIterator            &cell,
               const VectorType              &displacement,
               const VectorType              &velocity,
               const materials::Interface    &material,
               const States                  &states)
      {
        const FEValuesExtractors::Vector u(0);
        fe_values.reinit(cell);
        fe_values[u].get_function_values(displacement, values);
        fe_values[u].get_function_gradients(displacement, gradients);
        const auto C       = material.stiffness_tangent();
        const auto D       = material.damping_tangent();
        const bool viscous = D.norm() > 0;
        if (viscous)
          {
            fe_values[u].get_function_values(velocity, velocity_values);
            fe_values[u].get_function_gradients(velocity, velocity_gradients);
          }
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double r = fe_values.quadrature_point(q)[0];
            stress[q] = C * axisymmetric_strain(values[q], gradients[q], r);
            if (viscous)
              stress[q] += D * axisymmetric_strain(velocity_values[q],
                                                   velocity_gradients[q],
                                                   r);
            if (!states.empty())
              stress[q] += material.internal_stress(states[q]->internal);
          }
        return stress;
      }

      const QGauss<2> quadrature;
      FEValues<2>     fe_values;

    private:
      std::vector<Tensor<1, 2>>          values, velocity_values;
      std::vector<Tensor<2, 2>>          gradients, velocity_gradients;
      std::vector<SymmetricTensor<2, 3>> stress;
    };


    // Parameters flattened to "Section/Entry" -> value, from the JSON print.
    void
    flatten(const nlohmann::json                   &node,
            const std::string                      &path,
            std::map<std::string, std::string>     &entries)
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
  } // namespace


  int
  ImpactProblem::interrupt_received()
  {
    return interrupt_signal;
  }


  void
  ImpactProblem::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scenario");
    prm.declare_entry("Analysis",
                      "impact",
                      Patterns::Selection(
                        "impact|static press|material point|specimen"),
                      "'material point': the sphere's material at one point "
                      "under the history of the subsection 'Material point' "
                      "(no mesh, no contact). 'specimen': the same history "
                      "on a homogeneous cylinder of the sphere's material, "
                      "finite elements, quasi-static. "
                      "'impact': the sphere hits the plate at the impact "
                      "velocity. 'static press': the sphere, at rest, is "
                      "pressed into the plate by a uniform body force of "
                      "resultant 'Static force' (use with a clamped far "
                      "boundary); one quasi-static solve, the Hertz check.");
    prm.declare_entry("Static force",
                      "1000",
                      Patterns::Double(),
                      "Resultant of the body force pressing the sphere in "
                      "the 'static press' analysis [N], > 0.");
    prm.declare_entry("Impact velocity",
                      "1",
                      Patterns::Double(),
                      "Speed of the sphere towards the plate at t = 0 [m/s], "
                      "in (0, 100].");
    prm.declare_entry("Initial gap",
                      "0",
                      Patterns::Double(),
                      "Distance between sphere and plate at t = 0 [m], >= 0.");
    prm.declare_entry("Sphere radius",
                      "0.01452",
                      Patterns::Double(),
                      "Radius R of the sphere [m], > 0 (0.01452 m: a 0.1 kg "
                      "steel ball).");
    prm.declare_entry("Plate radius",
                      "0.1",
                      Patterns::Double(),
                      "Radius Rp of the plate [m], > 2 R.");
    prm.declare_entry("Plate thickness",
                      "0.05",
                      Patterns::Double(),
                      "Thickness H of the plate [m], > 0.");
    prm.declare_entry("Far boundary",
                      "absorbing",
                      Patterns::Selection("absorbing|clamped"),
                      "Side and bottom of the plate: 'absorbing' "
                      "(Lysmer-Kuhlemeyer dashpots rho c_p and rho c_s, so "
                      "the finite plate stands in for a half-space) or "
                      "'clamped' (zero displacement).");
    prm.declare_entry("Gravity",
                      "0",
                      Patterns::Double(),
                      "Gravitational acceleration acting on the sphere "
                      "[m/s^2], >= 0 (the plate is taken as pre-stressed "
                      "by its own weight).");
    prm.leave_subsection();

    for (const auto *body : {"Sphere", "Plate"})
      {
        prm.enter_subsection(body);
        materials::declare_parameters(prm, "elastic");
        prm.declare_entry("Yield strength",
                          "0",
                          Patterns::Double(0),
                          "Yield strength of the body [Pa], >= 0; 0: none. "
                          "The summary reports whether, when and where the "
                          "von Mises stress exceeded it (the viscoelastic "
                          "model is not valid beyond).");
        prm.leave_subsection();
      }

    SpherePlateMesh::declare_parameters(prm);
    Newmark::declare_parameters(prm);
    MortarContact::declare_parameters(prm);

    prm.enter_subsection("Solver");
    prm.declare_entry("Direct solver",
                      "Amesos_Mumps",
                      Patterns::Selection("Amesos_Mumps|Amesos_Klu"),
                      "Trilinos/Amesos sparse direct solver of the "
                      "effective stiffness (factorised once per run): "
                      "Amesos_Mumps (parallel) or Amesos_Klu (serial).");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "results/default",
                      Patterns::Anything(),
                      "Directory of the run's files (history.h5, "
                      "summary.json, mesh, snapshots); created if needed.");
    prm.declare_entry("Snapshot interval",
                      "0",
                      Patterns::Double(),
                      "Simulated time between ParaView snapshots [s], >= 0; "
                      "0 writes none.");
    prm.declare_entry("Progress interval",
                      "1",
                      Patterns::Double(),
                      "Wall time between progress lines on the terminal [s], "
                      ">= 0; 0 prints every step.");
    prm.leave_subsection();
  }


  ImpactProblem::ImpactProblem(ParameterHandler &prm,
                               const MPI_Comm    comm,
                               std::ostream     &log)
    : mpi_communicator(comm)
    , pcout(log, Utilities::MPI::this_mpi_process(comm) == 0)
    , log_is_terminal(&log == &std::cout && isatty(STDOUT_FILENO))
    , parameters(prm)
    , triangulation(comm,
                    Triangulation<2>::limit_level_difference_at_vertices)
    , dof_handler(triangulation)
    , solver_control(1, 0)
  {
    prm.enter_subsection("Scenario");
    static_press             = prm.get("Analysis") == "static press";
    static_force             = prm.get_double("Static force");
    impact_velocity          = prm.get_double("Impact velocity");
    geometry.initial_gap     = prm.get_double("Initial gap");
    geometry.sphere_radius   = prm.get_double("Sphere radius");
    geometry.plate_radius    = prm.get_double("Plate radius");
    geometry.plate_thickness = prm.get_double("Plate thickness");
    absorbing_boundaries     = prm.get("Far boundary") == "absorbing";
    gravity                  = prm.get_double("Gravity");
    prm.leave_subsection();

    AssertThrow(impact_velocity > 0 && impact_velocity <= 100,
                ExcMessage("Scenario/Impact velocity must lie in (0, 100] "
                           "m/s, got " + std::to_string(impact_velocity) +
                           "."));
    AssertThrow(geometry.initial_gap >= 0,
                ExcMessage("Scenario/Initial gap must not be negative, got " +
                           std::to_string(geometry.initial_gap) + " m."));
    AssertThrow(geometry.sphere_radius > 0,
                ExcMessage("Scenario/Sphere radius must be positive, got " +
                           std::to_string(geometry.sphere_radius) + " m."));
    AssertThrow(geometry.plate_thickness > 0,
                ExcMessage("Scenario/Plate thickness must be positive, got " +
                           std::to_string(geometry.plate_thickness) + " m."));
    AssertThrow(geometry.plate_radius > 2 * geometry.sphere_radius,
                ExcMessage("Scenario/Plate radius must exceed twice the "
                           "sphere radius, got " +
                           std::to_string(geometry.plate_radius) + " m."));
    AssertThrow(gravity >= 0,
                ExcMessage("Scenario/Gravity must not be negative."));
    AssertThrow(!static_press || static_force > 0,
                ExcMessage("Scenario/Static force must be positive."));
    AssertThrow(!static_press || !absorbing_boundaries,
                ExcMessage("The 'static press' analysis needs Scenario/Far "
                           "boundary = clamped: dashpots carry no static "
                           "load."));

    prm.enter_subsection("Sphere");
    sphere_material   = materials::create_material(prm);
    yield_strength[0] = prm.get_double("Yield strength");
    prm.leave_subsection();
    prm.enter_subsection("Plate");
    plate_material    = materials::create_material(prm);
    yield_strength[1] = prm.get_double("Yield strength");
    prm.leave_subsection();

    has_material_damping =
      sphere_material->damping_tangent().norm() > 0 ||
      plate_material->damping_tangent().norm() > 0;
    has_internal_variables = sphere_material->n_internal_variables() > 0 ||
                             plate_material->n_internal_variables() > 0;

    mesh.parse_parameters(prm, geometry);
    time_integrator.parse_parameters(prm);
    contact.parse_parameters(prm);

    prm.enter_subsection("Solver");
    direct_solver_name = prm.get("Direct solver");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_directory  = prm.get("Directory");
    snapshot_interval = prm.get_double("Snapshot interval");
    progress_interval = prm.get_double("Progress interval");
    prm.leave_subsection();
    AssertThrow(!output_directory.empty(),
                ExcMessage("Output/Directory must not be empty."));
    AssertThrow(snapshot_interval >= 0,
                ExcMessage("Output/Snapshot interval must not be negative."));
    AssertThrow(progress_interval >= 0,
                ExcMessage("Output/Progress interval must not be negative."));

    // Hertz estimates: they set the time step and the length of the run.
    const double R  = geometry.sphere_radius;
    sphere_mass     = sphere_material->density() * 4. / 3. * M_PI * R * R * R;
    auto compliance = [](const materials::Interface &m) {
      return (1 - m.poissons_ratio() * m.poissons_ratio()) / m.youngs_modulus();
    };
    const HertzImpact hertz{1 / (compliance(*sphere_material) +
                                 compliance(*plate_material)),
                            R,
                            sphere_mass,
                            impact_velocity};
    hertz_contact_time = hertz.contact_time();
    if (static_press)
      {
        // One step of length dt from rest is the static problem with the
        // bodies tied to the ground by springs of stiffness
        // m / (beta dt^2): chosen soft (a rigid sphere compliance 1000
        // times the contact's) they only regularise the free sphere's
        // rigid motion, and the contact force is measured anyway.
        gravity = static_force / sphere_mass;
        const double contact_compliance =
          std::pow(hertz.stiffness() * hertz.stiffness() * static_force,
                   -1. / 3.) / 1.5;
        time_integrator.prescribed_time_step =
          std::sqrt(1e3 * contact_compliance * sphere_mass /
                    time_integrator.beta);
        hertz_contact_time = time_integrator.prescribed_time_step;
      }
    time_integrator.set_time_step(hertz_contact_time);
    end_time = static_press ? time_integrator.time_step :
               time_integrator.maximum_time > 0 ?
                 time_integrator.maximum_time :
                 geometry.initial_gap / impact_velocity + 3 * hertz_contact_time;
    AssertThrow(hertz.contact_radius_max() < mesh.contact_surface_radius,
                ExcMessage("Mesh/Contact surface radius (" +
                           std::to_string(mesh.contact_surface_radius) +
                           " m) is smaller than the expected contact radius "
                           "(Hertz: " +
                           std::to_string(hertz.contact_radius_max()) +
                           " m); increase it."));

    pcout << "impact-fem: sphere R = " << R * 1e3 << " mm, m = " << sphere_mass
          << " kg, V = " << impact_velocity << " m/s\n"
          << "  Hertz: approach " << hertz.approach_max() * 1e6
          << " um, force " << hertz.force_max() / 1e3 << " kN, contact radius "
          << hertz.contact_radius_max() * 1e3 << " mm, contact time "
          << hertz_contact_time * 1e6 << " us\n"
          << "  time step " << time_integrator.time_step * 1e9 << " ns on "
          << Utilities::MPI::n_mpi_processes(comm) << " rank(s)" << std::endl;
  }


  const materials::Interface &
  ImpactProblem::material_of(const types::material_id body) const
  {
    return body == body_ids::sphere ? *sphere_material : *plate_material;
  }


  void
  ImpactProblem::make_mesh()
  {
    TimerOutput::Scope t(*computing_timer, "make mesh");
    mesh.create(triangulation, output_directory);
    fe = std::make_unique<FESystem<2>>(FE_Q<2>(mesh.polynomial_degree), 2);
    mapping = std::make_unique<MappingQ<2>>(mesh.polynomial_degree);
  }


  void
  ImpactProblem::setup_system()
  {
    TimerOutput::Scope t(*computing_timer, "setup system");
    dof_handler.distribute_dofs(*fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    // u_r = 0 on the axis; a clamped plate is fixed at its side and bottom.
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
    if (!absorbing_boundaries)
      for (const auto id : {boundary_ids::plate_side, boundary_ids::plate_bottom})
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
    for (auto *matrix : {&mass_matrix,
                         &stiffness_matrix,
                         &boundary_damping_matrix,
                         &material_damping_matrix,
                         &internal_stiffness_matrix,
                         &effective_stiffness})
      matrix->reinit(sparsity);

    for (auto *vector : {&displacement,
                         &velocity,
                         &acceleration,
                         &body_force,
                         &sphere_momentum_weights,
                         &plate_bottom_weights,
                         &sphere_mask,
                         &internal_force_predictor})
      vector->reinit(locally_owned_dofs, mpi_communicator);

    pcout << "  mesh: " << triangulation.n_global_active_cells()
          << " cells, " << dof_handler.n_dofs() << " degrees of freedom (Q"
          << mesh.polynomial_degree << ")" << std::endl;
  }


  void
  ImpactProblem::assemble_system()
  {
    TimerOutput::Scope t(*computing_timer, "assemble system");

    const QGauss<2>     quadrature(fe->degree + 1);
    const QGauss<1>     face_quadrature(fe->degree + 1);
    FEValues<2>         fe_values(*mapping,
                          *fe,
                          quadrature,
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    FEFaceValues<2>     fe_face_values(*mapping,
                                   *fe,
                                   face_quadrature,
                                   update_values | update_quadrature_points |
                                     update_normal_vectors |
                                     update_JxW_values);
    const unsigned int  dofs_per_cell = fe->n_dofs_per_cell();
    FullMatrix<double>  cell_mass(dofs_per_cell, dofs_per_cell),
      cell_stiffness(dofs_per_cell, dofs_per_cell),
      cell_boundary_damping(dofs_per_cell, dofs_per_cell),
      cell_material_damping(dofs_per_cell, dofs_per_cell),
      cell_internal_stiffness(dofs_per_cell, dofs_per_cell);
    Vector<double> cell_momentum(dofs_per_cell), cell_bottom(dofs_per_cell),
      cell_mask(dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<SymmetricTensor<2, 3>>   strain(dofs_per_cell);
    const FEValuesExtractors::Vector     u(0);
    const double bottom_area = M_PI * geometry.plate_radius *
                               geometry.plate_radius;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &material = material_of(cell->material_id());
          const SymmetricTensor<4, 3> C   = material.stiffness_tangent();
          const SymmetricTensor<4, 3> D   = material.damping_tangent();
          const SymmetricTensor<4, 3> C_internal =
            material.internal_tangent(time_integrator.time_step);
          const double                rho = material.density();
          const bool on_sphere = cell->material_id() == body_ids::sphere;

          cell_mass             = 0;
          cell_stiffness        = 0;
          cell_boundary_damping = 0;
          cell_material_damping = 0;
          cell_internal_stiffness = 0;
          cell_momentum         = 0;
          cell_bottom           = 0;
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double r  = fe_values.quadrature_point(q)[0];
              // The r-weighted measure of the axisymmetric body (2 pi r).
              const double dV = 2 * M_PI * r * fe_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                strain[i] = axisymmetric_strain(fe_values[u].value(i, q),
                                                fe_values[u].gradient(i, q),
                                                r);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const Tensor<1, 2>          phi_i = fe_values[u].value(i, q);
                  const SymmetricTensor<2, 3> C_eps = C * strain[i];
                  const SymmetricTensor<2, 3> D_eps = D * strain[i];
                  const SymmetricTensor<2, 3> Ci_eps = C_internal * strain[i];
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    {
                      cell_mass(i, j) +=
                        rho * (phi_i * fe_values[u].value(j, q)) * dV;
                      cell_stiffness(i, j) += (C_eps * strain[j]) * dV;
                      cell_material_damping(i, j) += (D_eps * strain[j]) * dV;
                      cell_internal_stiffness(i, j) += (Ci_eps * strain[j]) * dV;
                    }
                  if (on_sphere)
                    cell_momentum(i) += rho * phi_i[1] * dV;
                }
            }

          for (const auto face : cell->face_indices())
            if (cell->face(face)->at_boundary() &&
                (cell->face(face)->boundary_id() == boundary_ids::plate_side ||
                 cell->face(face)->boundary_id() == boundary_ids::plate_bottom))
              {
                fe_face_values.reinit(cell, face);
                const double rho_cp = rho * material.p_wave_speed();
                const double rho_cs = rho * material.s_wave_speed();
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    const double r  = fe_face_values.quadrature_point(q)[0];
                    const double dA = 2 * M_PI * r * fe_face_values.JxW(q);
                    const Tensor<1, 2> n = fe_face_values.normal_vector(q);
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        const Tensor<1, 2> phi_i =
                          fe_face_values[u].value(i, q);
                        if (cell->face(face)->boundary_id() ==
                            boundary_ids::plate_bottom)
                          cell_bottom(i) += phi_i[1] * dA / bottom_area;
                        if (!absorbing_boundaries)
                          continue;
                        // Lysmer-Kuhlemeyer: t = -rho c_p v_n n - rho c_s v_t.
                        for (unsigned int j = 0; j < dofs_per_cell; ++j)
                          {
                            const Tensor<1, 2> phi_j =
                              fe_face_values[u].value(j, q);
                            const double normal_i = phi_i * n,
                                         normal_j = phi_j * n;
                            cell_boundary_damping(i, j) +=
                              (rho_cp * normal_i * normal_j +
                               rho_cs * (phi_i * phi_j - normal_i * normal_j)) *
                              dA;
                          }
                      }
                  }
              }

          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_mass,
                                                 local_dofs,
                                                 mass_matrix);
          constraints.distribute_local_to_global(cell_stiffness,
                                                 local_dofs,
                                                 stiffness_matrix);
          constraints.distribute_local_to_global(cell_boundary_damping,
                                                 local_dofs,
                                                 boundary_damping_matrix);
          constraints.distribute_local_to_global(cell_material_damping,
                                                 local_dofs,
                                                 material_damping_matrix);
          constraints.distribute_local_to_global(cell_internal_stiffness,
                                                 local_dofs,
                                                 internal_stiffness_matrix);
          constraints.distribute_local_to_global(cell_momentum,
                                                 local_dofs,
                                                 sphere_momentum_weights);
          constraints.distribute_local_to_global(cell_bottom,
                                                 local_dofs,
                                                 plate_bottom_weights);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            if (on_sphere && locally_owned_dofs.is_element(local_dofs[i]))
              sphere_mask[local_dofs[i]] = 1;
        }

    for (auto *matrix : {&mass_matrix,
                         &stiffness_matrix,
                         &boundary_damping_matrix,
                         &material_damping_matrix,
                         &internal_stiffness_matrix})
      matrix->compress(VectorOperation::add);
    sphere_momentum_weights.compress(VectorOperation::add);
    plate_bottom_weights.compress(VectorOperation::add);
    sphere_mask.compress(VectorOperation::insert);

    // Gravity on the sphere: f = -g M e_z restricted to the sphere.
    body_force = sphere_momentum_weights;
    body_force *= -gravity;
  }


  void
  ImpactProblem::factorize_effective_stiffness()
  {
    TimerOutput::Scope t(*computing_timer, "factorize");
    effective_stiffness.copy_from(stiffness_matrix);
    effective_stiffness.add(time_integrator.c_M, mass_matrix);
    effective_stiffness.add(time_integrator.c_C, boundary_damping_matrix);
    effective_stiffness.add(time_integrator.c_C, material_damping_matrix);
    // The Maxwell arms' algorithmic tangent (constant for a constant step).
    effective_stiffness.add(1., internal_stiffness_matrix);
    direct_solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      solver_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                     direct_solver_name));
    direct_solver->initialize(effective_stiffness);
  }


  void
  ImpactProblem::setup_contact()
  {
    TimerOutput::Scope t(*computing_timer, "setup contact");
    contact.setup(dof_handler, *mapping, constraints);
    contact.compute_influence(
      [this](TrilinosWrappers::MPI::Vector       &x,
             const TrilinosWrappers::MPI::Vector &b) {
        direct_solver->solve(x, b);
      },
      locally_owned_dofs,
      mpi_communicator);
    contact_pressures.reinit(contact.n_contact_nodes());
    pcout << "  contact: " << contact.n_contact_nodes()
          << " nodes on the plate's contact surface" << std::endl;
  }


  void
  ImpactProblem::set_initial_conditions()
  {
    // The sphere moves down rigidly (-V e_z), the plate rests; before
    // contact the sphere is free, so a = -g e_z exactly.
    const IndexSet vertical_dofs =
      DoFTools::extract_dofs(dof_handler,
                             fe->component_mask(FEValuesExtractors::Scalar(1)));
    TrilinosWrappers::MPI::Vector sphere_vertical(sphere_mask);
    for (const auto i : locally_owned_dofs)
      if (!vertical_dofs.is_element(i))
        sphere_vertical[i] = 0;
    sphere_vertical.compress(VectorOperation::insert);
    constraints.set_zero(sphere_vertical);

    displacement = 0;
    velocity.equ(static_press ? 0. : -impact_velocity, sphere_vertical);
    acceleration.equ(static_press ? 0. : -gravity, sphere_vertical);
    initial_energy = 0.5 * mass_matrix.matrix_norm_square(velocity);
    time           = 0;
    step           = 0;

    // The flight across the initial gap is a rigid motion known exactly:
    // start at the first contact, so that every time step serves the
    // contact phase.
    if (!static_press && geometry.initial_gap > 0)
      {
        const double g0 = geometry.initial_gap, V = impact_velocity;
        time = gravity > 0 ? (std::sqrt(V * V + 2 * gravity * g0) - V) / gravity :
                             g0 / V;
        displacement.equ(-g0, sphere_vertical);
        velocity.equ(-(V + gravity * time), sphere_vertical);
        gravity_work = body_force * displacement;
      }
    contact_velocity = impact_velocity + (static_press ? 0. : gravity * time);
    weighted_gaps    = contact.weighted_gaps(displacement);

    // The bodies start unstrained (the flight is rigid) with relaxed arms.
    internal_force_predictor = 0;
    if (has_internal_variables)
      {
        const unsigned int n_q_points =
          QGauss<2>(fe->degree + 1).size();
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              material_of(cell->material_id()).n_internal_variables() > 0)
            {
              material_states.initialize(cell, n_q_points);
              for (const auto &state : material_states.get_data(cell))
                state->internal.assign(
                  material_of(cell->material_id()).n_internal_variables(),
                  SymmetricTensor<2, 3>());
            }
      }
  }


  void
  ImpactProblem::solve_time_step()
  {
    const Newmark &tn = time_integrator;
    TrilinosWrappers::MPI::Vector rhs(locally_owned_dofs, mpi_communicator),
      tmp(locally_owned_dofs, mpi_communicator),
      free_displacement(locally_owned_dofs, mpi_communicator);
    {
      TimerOutput::Scope t(*computing_timer, "assemble right-hand side");
      // M (c_M u + c_v v + c_a a) + C (c_C u + d_v v + d_a a) + f
      tmp.equ(tn.c_M, displacement);
      tmp.add(tn.c_v, velocity, tn.c_a, acceleration);
      mass_matrix.vmult(rhs, tmp);
      tmp.equ(tn.c_C, displacement);
      tmp.add(tn.d_v, velocity, tn.d_a, acceleration);
      TrilinosWrappers::MPI::Vector damping_force(rhs);
      boundary_damping_matrix.vmult(damping_force, tmp);
      rhs += damping_force;
      if (has_material_damping)
        {
          material_damping_matrix.vmult(damping_force, tmp);
          rhs += damping_force;
        }
      rhs += body_force;
      // History of the Maxwell arms.
      rhs -= internal_force_predictor;
    }
    {
      TimerOutput::Scope t(*computing_timer, "solve free step");
      direct_solver->solve(free_displacement, rhs);
    }

    Vector<double> pressures;
    {
      TimerOutput::Scope t(*computing_timer, "solve contact");
      const Vector<double> free_gaps = contact.weighted_gaps(free_displacement);
      pressures = contact.solve_complementarity(free_gaps);
      contact.add_contact_response(pressures, free_displacement);
    }

    TimerOutput::Scope t(*computing_timer, "update state");
    const Vector<double> new_gaps = contact.weighted_gaps(free_displacement);
    // Work of the contact forces (trapezoidal, as the Newmark identity).
    for (unsigned int j = 0; j < pressures.size(); ++j)
      contact_work += 0.5 * (pressures[j] + contact_pressures[j]) *
                      (new_gaps[j] - weighted_gaps[j]);

    // a_{n+1} = c_M (u_{n+1} - u_n) - c_v v_n - c_a a_n
    TrilinosWrappers::MPI::Vector increment(free_displacement);
    increment -= displacement;
    TrilinosWrappers::MPI::Vector new_acceleration(increment);
    new_acceleration *= tn.c_M;
    new_acceleration.add(-tn.c_v, velocity, -tn.c_a, acceleration);
    TrilinosWrappers::MPI::Vector new_velocity(velocity);
    new_velocity.add(tn.time_step * (1 - tn.gamma),
                     acceleration,
                     tn.time_step * tn.gamma,
                     new_acceleration);

    // Energy leaving through the dashpots and into viscosity over the step.
    TrilinosWrappers::MPI::Vector mean_velocity(velocity);
    mean_velocity += new_velocity;
    mean_velocity *= 0.5;
    radiated_energy +=
      tn.time_step * boundary_damping_matrix.matrix_norm_square(mean_velocity);
    if (has_material_damping)
      dissipated_energy +=
        tn.time_step * material_damping_matrix.matrix_norm_square(mean_velocity);
    gravity_work += body_force * increment;

    displacement      = free_displacement;
    velocity          = new_velocity;
    acceleration      = new_acceleration;
    contact_pressures = pressures;
    weighted_gaps     = new_gaps;
    time += tn.time_step;
    ++step;
    update_material_states();
  }


  void
  ImpactProblem::update_material_states()
  {
    if (!has_internal_variables)
      return;
    TimerOutput::Scope t(*computing_timer, "update material states");
    const double dt = time_integrator.time_step;
    TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs,
                                          locally_relevant_dofs,
                                          mpi_communicator);
    {
      TrilinosWrappers::MPI::Vector distributed(displacement);
      constraints.distribute(distributed);
      ghosted = distributed;
    }
    const QGauss<2>    quadrature(fe->degree + 1);
    FEValues<2>        fe_values(*mapping,
                          *fe,
                          quadrature,
                          update_values | update_gradients |
                            update_quadrature_points | update_JxW_values);
    const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
    Vector<double>     cell_force(dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<Tensor<1, 2>>            values(quadrature.size());
    std::vector<Tensor<2, 2>>            gradients(quadrature.size());
    const FEValuesExtractors::Vector     u(0);
    double dissipated = 0, stored[2] = {0, 0};

    internal_force_predictor = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          material_of(cell->material_id()).n_internal_variables() > 0)
        {
          const auto &material = material_of(cell->material_id());
          const auto  states   = material_states.get_data(cell);
          const unsigned int body = cell->material_id() == body_ids::sphere ? 0 : 1;
          fe_values.reinit(cell);
          fe_values[u].get_function_values(ghosted, values);
          fe_values[u].get_function_gradients(ghosted, gradients);
          cell_force = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double r  = fe_values.quadrature_point(q)[0];
              const double dV = 2 * M_PI * r * fe_values.JxW(q);
              QuadraturePointState &state = *states[q];
              const SymmetricTensor<2, 3> strain =
                axisymmetric_strain(values[q], gradients[q], r);
              dissipated += material.update_internal_variables(state.internal,
                                                               state.strain,
                                                               strain,
                                                               dt) *
                            dV;
              state.strain = strain;
              stored[body] += material.internal_energy(state.internal) * dV;
              const SymmetricTensor<2, 3> predictor =
                material.internal_stress_predictor(state.internal, strain, dt);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                cell_force(i) +=
                  (predictor * axisymmetric_strain(fe_values[u].value(i, q),
                                                   fe_values[u].gradient(i, q),
                                                   r)) *
                  dV;
            }
          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_force,
                                                 local_dofs,
                                                 internal_force_predictor);
        }
    internal_force_predictor.compress(VectorOperation::add);
    dissipated_energy += Utilities::MPI::sum(dissipated, mpi_communicator);
    for (unsigned int body = 0; body < 2; ++body)
      internal_energy[body] = Utilities::MPI::sum(stored[body], mpi_communicator);
  }


  void
  ImpactProblem::record_step()
  {
    TimerOutput::Scope t(*computing_timer, "postprocess step");
    const double force = contact.total_force(contact_pressures);

    // Centre-of-mass motion of the sphere and mean motion of the plate
    // bottom, downward positive.
    const double sphere_displacement =
      -(sphere_momentum_weights * displacement) / sphere_mass;
    const double sphere_velocity =
      -(sphere_momentum_weights * velocity) / sphere_mass;
    const double plate_displacement = -(plate_bottom_weights * displacement);

    const double kinetic = 0.5 * mass_matrix.matrix_norm_square(velocity);
    // Stored elastic energy: the long-term springs (the stiffness matrix)
    // plus the springs of the Maxwell arms (at the quadrature points).
    const double strain  = 0.5 * stiffness_matrix.matrix_norm_square(displacement) +
                          internal_energy[0] + internal_energy[1];
    TrilinosWrappers::MPI::Vector on_sphere(velocity);
    on_sphere.scale(sphere_mask);
    const double sphere_kinetic = 0.5 * mass_matrix.matrix_norm_square(on_sphere);
    on_sphere = displacement;
    on_sphere.scale(sphere_mask);
    const double sphere_strain =
      0.5 * stiffness_matrix.matrix_norm_square(on_sphere) + internal_energy[0];
    const double balance = kinetic + strain + radiated_energy +
                           dissipated_energy - initial_energy - gravity_work;
    // A static press starts without energy: its balance is relative to the
    // work of the load.
    const double reference_energy =
      initial_energy > 0 ? initial_energy : std::max(gravity_work, 1e-300);

    TimerOutput::Scope t_stress(*computing_timer, "postprocess stress");
    // Largest von Mises stress of each body over the quadrature points near
    // the contact, where it peaks (Hertz: 0.48 a below the surface); the
    // rest of the bodies only carries the much weaker radiated waves. The
    // stress is the total one: elastic, viscous (Kelvin-Voigt) and that of
    // the Maxwell arms.
    const double   stress_zone = 2 * mesh.contact_surface_radius;
    const Point<2> contact_points[2] = {Point<2>(0, 0),
                                        Point<2>(0, geometry.initial_gap)};
    TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs,
                                          locally_relevant_dofs,
                                          mpi_communicator),
      ghosted_velocity(ghosted);
    {
      TrilinosWrappers::MPI::Vector distributed(displacement);
      constraints.distribute(distributed);
      ghosted = distributed;
      if (has_material_damping)
        {
          distributed = velocity;
          constraints.distribute(distributed);
          ghosted_velocity = distributed;
        }
    }
    CellStress cell_stress(*mapping, *fe);
    double     body_max[2] = {0, 0};
    Point<2> body_location[2];
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          std::min(cell->center().distance(contact_points[0]),
                   cell->center().distance(contact_points[1])) < stress_zone)
        {
          const auto &material = material_of(cell->material_id());
          const unsigned int body =
            cell->material_id() == body_ids::sphere ? 0 : 1;
          std::vector<std::shared_ptr<QuadraturePointState>> states;
          if (material.n_internal_variables() > 0)
            states = material_states.get_data(cell);
          const auto &stress = cell_stress.evaluate(
            cell, ghosted, ghosted_velocity, material, states);
          for (unsigned int q = 0; q < stress.size(); ++q)
            {
              const Point<2> &x = cell_stress.fe_values.quadrature_point(q);
              const double    s = von_mises(stress[q]);
              if (s > body_max[body])
                {
                  body_max[body]      = s;
                  body_location[body] = x;
                }
            }
        }
    // Each location travels with the rank that holds the maximum.
    for (unsigned int body = 0; body < 2; ++body)
      {
        const double global = Utilities::MPI::max(body_max[body], mpi_communicator);
        const unsigned int holder = Utilities::MPI::min(
          body_max[body] == global ?
            Utilities::MPI::this_mpi_process(mpi_communicator) :
            Utilities::MPI::n_mpi_processes(mpi_communicator),
          mpi_communicator);
        body_location[body] =
          Utilities::MPI::broadcast(mpi_communicator, body_location[body], holder);
        body_max[body] = global;
        StressPeak &peak = stress_peak[body];
        if (global > peak.value)
          {
            peak.value    = global;
            peak.time     = time;
            peak.location = body_location[body];
          }
        if (yield_strength[body] > 0 && global > yield_strength[body] &&
            peak.first_yield_time < 0)
          {
            peak.first_yield_time     = time;
            peak.first_yield_location = body_location[body];
          }
      }
    const unsigned int max_body     = body_max[1] > body_max[0] ? 1 : 0;
    const double       global_max   = body_max[max_body];
    const Point<2>     max_location = body_location[max_body];

    double max_pressure = 0;
    for (const double p : contact_pressures)
      max_pressure = std::max(max_pressure, p);

    history.append("time", time);
    history.append("contact_force", force);
    history.append("sphere_displacement", sphere_displacement);
    history.append("sphere_velocity", sphere_velocity);
    history.append("plate_displacement", plate_displacement);
    history.append("approach",
                   sphere_displacement - geometry.initial_gap - plate_displacement);
    history.append("contact_radius", contact.contact_radius(contact_pressures));
    history.append("max_pressure", max_pressure);
    history.append("max_von_mises", global_max);
    history.append("max_von_mises_r", max_location[0]);
    history.append("max_von_mises_z", max_location[1]);
    for (unsigned int body = 0; body < 2; ++body)
      {
        const std::string name = body == 0 ? "sphere" : "plate";
        history.append("max_von_mises_" + name, body_max[body]);
        history.append("max_von_mises_" + name + "_r", body_location[body][0]);
        history.append("max_von_mises_" + name + "_z", body_location[body][1]);
      }
    history.append("internal_energy", internal_energy[0] + internal_energy[1]);
    history.append("kinetic_energy", kinetic);
    history.append("strain_energy", strain);
    history.append("dissipated_energy", dissipated_energy);
    history.append("radiated_energy", radiated_energy);
    history.append("gravity_work", gravity_work);
    history.append("contact_work", contact_work);
    history.append("energy_error", balance / reference_energy);
    history.append("sphere_kinetic_energy", sphere_kinetic);
    history.append("sphere_strain_energy", sphere_strain);
    history.append("penetration", contact.penetration(displacement));

    if (force > largest_force)
      {
        largest_force = force;
        history.set_profile("pressure_at_force_max",
                            "Pa",
                            "contact pressure at the contact nodes at the "
                            "time of the largest contact force",
                            std::vector<double>(contact_pressures.begin(),
                                                contact_pressures.end()));
      }

    // Phases of the impact.
    if (force > 0)
      contact_started = true;
    else if (contact_started && separation_time < 0)
      {
        separation_time = time;
        end_time        = std::min(end_time,
                            time + time_integrator.time_after_separation *
                                     (time - history["time"].front()));
      }
  }


  void
  ImpactProblem::output_results(const unsigned int snapshot)
  {
    TimerOutput::Scope t(*computing_timer, "output snapshots");
    TrilinosWrappers::MPI::Vector ghosted_u(locally_owned_dofs,
                                            locally_relevant_dofs,
                                            mpi_communicator),
      ghosted_v(ghosted_u);
    TrilinosWrappers::MPI::Vector tmp(displacement);
    constraints.distribute(tmp);
    ghosted_u = tmp;
    tmp       = velocity;
    constraints.distribute(tmp);
    ghosted_v = tmp;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(2, DataComponentInterpretation::component_is_part_of_vector);
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(ghosted_u,
                             std::vector<std::string>(2, "displacement"),
                             DataOut<2>::type_dof_data,
                             vector_field);
    data_out.add_data_vector(ghosted_v,
                             std::vector<std::string>(2, "velocity"),
                             DataOut<2>::type_dof_data,
                             vector_field);
    // Stress as cell averages over the quadrature points (r, z, theta
    // components and von Mises).
    Vector<float> body(triangulation.n_active_cells());
    std::vector<Vector<float>> stress(5, Vector<float>(triangulation.n_active_cells()));
    CellStress cell_stress(*mapping, *fe);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int index = cell->active_cell_index();
          body[index] = cell->material_id();
          // The total stress: elastic, viscous and the Maxwell arms'.
          const auto &material = material_of(cell->material_id());
          std::vector<std::shared_ptr<QuadraturePointState>> states;
          if (material.n_internal_variables() > 0)
            states = material_states.get_data(cell);
          const auto &sigmas =
            cell_stress.evaluate(cell, ghosted_u, ghosted_v, material, states);
          for (const auto &sigma : sigmas)
            {
              const double weight = 1. / sigmas.size();
              stress[0][index] += weight * sigma[0][0];
              stress[1][index] += weight * sigma[1][1];
              stress[2][index] += weight * sigma[2][2];
              stress[3][index] += weight * sigma[0][1];
              stress[4][index] += weight * von_mises(sigma);
            }
        }
    data_out.add_data_vector(body, "body");
    const char *stress_names[5] = {
      "stress_rr", "stress_zz", "stress_thetatheta", "stress_rz", "von_mises"};
    for (unsigned int c = 0; c < 5; ++c)
      data_out.add_data_vector(stress[c], stress_names[c]);
    data_out.build_patches(*mapping, fe->degree, DataOut<2>::curved_inner_cells);

    const std::string directory = output_directory + "/snapshots/";
    snapshot_records.emplace_back(time,
                         "snapshots/" +
                           data_out.write_vtu_with_pvtu_record(
                             directory, "solution", snapshot, mpi_communicator, 4));
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ofstream pvd(output_directory + "/snapshots.pvd");
        DataOutBase::write_pvd_record(pvd, snapshot_records);
      }
  }


  void
  ImpactProblem::print_progress(const bool last)
  {
    const auto   now     = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - wall_start).count();
    if (!last && progress_interval > 0 && !log_is_terminal &&
        std::chrono::duration<double>(now - last_progress).count() <
          progress_interval)
      return;
    last_progress = now;

    // Until the bodies separate the end is an estimate from Hertz.
    const double expected_end =
      separation_time >= 0 ?
        end_time :
        std::min(end_time,
                 geometry.initial_gap / impact_velocity +
                   hertz_contact_time *
                     (1 + time_integrator.time_after_separation));
    const double remaining =
      time > history["time"].front() ?
        elapsed * std::max(0., expected_end - time) /
          (time - history["time"].front()) :
        0;
    // On a terminal the line is updated in place every step; in a log file
    // a new line follows every progress interval.
    const bool terminal = log_is_terminal;
    if (terminal)
      pcout << '\r';
    pcout << "  t = " << std::setw(8) << std::fixed << std::setprecision(2)
          << time * 1e6 << " us  step " << std::setw(5) << step
          << "  force " << std::setw(8) << std::setprecision(4)
          << history["contact_force"].back() / 1e3 << " kN  contact radius "
          << std::setw(6) << history["contact_radius"].back() * 1e3
          << " mm  remaining " << std::setprecision(0) << remaining << " s "
          << std::defaultfloat << std::setprecision(6);
    if (!terminal || last)
      pcout << std::endl;
    else
      pcout << std::flush;
  }


  void
  ImpactProblem::write_results(const bool complete)
  {
    const double wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                    wall_start)
        .count();
    const std::vector<double> &t     = history["time"];
    const std::vector<double> &force = history["contact_force"];
    const std::size_t          n     = history.n_steps();

    // Contact begins and ends where F^(2/3) (linear in time near both ends,
    // F ~ delta^(3/2)) extrapolates to zero.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double       first_contact = nan, separation = nan;
    std::size_t  first = n, last = n;
    for (std::size_t i = 0; i < n; ++i)
      if (force[i] > 0)
        {
          if (first == n)
            first = i;
          last = i;
        }
      else if (first != n)
        break;
    auto zero_of = [&](const std::size_t i, const std::size_t j) {
      const double fi = std::cbrt(force[i] * force[i]),
                   fj = std::cbrt(force[j] * force[j]);
      return t[i] - fi * (t[j] - t[i]) / (fj - fi);
    };
    // Kept within the steps around the change: a force that does not grow
    // like t^(3/2) at first (a viscous contact starts with a finite force)
    // extrapolates elsewhere; then the last step without contact is taken.
    if (first + 1 < n && force[first + 1] > 0)
      {
        const double before = first > 0 ? t[first - 1] : 0.;
        const double zero   = zero_of(first, first + 1);
        first_contact = zero <= t[first] ? std::max(before, zero) : before;
      }
    if (last < n && last + 1 < n && last > first)
      separation = std::max(t[last],
                            std::min(t[last + 1], zero_of(last, last - 1)));
    const double contact_time = separation - first_contact;

    std::size_t peak = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (force[i] > force[peak])
        peak = i;
    double approach_max = 0, energy_error = 0, max_von_mises = 0,
           penetration  = 0;
    for (std::size_t i = 0; i < n; ++i)
      {
        approach_max  = std::max(approach_max, history["approach"][i]);
        energy_error  = std::max(energy_error, std::abs(history["energy_error"][i]));
        max_von_mises = std::max(max_von_mises, history["max_von_mises"][i]);
        penetration   = std::max(penetration, history["penetration"][i]);
      }
    const bool   separated        = !std::isnan(separation);
    // Rebound velocity at separation: gravity (if any) keeps acting on the
    // free sphere afterwards, so the final velocity is taken back to it.
    const double rebound_velocity =
      separated ? -(history["sphere_velocity"][n - 1] -
                    gravity * (t[n - 1] - separation)) :
                  nan;
    const double restitution = rebound_velocity / contact_velocity;

    // Where the initial energy went, at the end of the run.
    const double E0          = initial_energy;
    const double rigid       = 0.5 * sphere_mass * rebound_velocity * rebound_velocity;
    const double sphere_vib  = history["sphere_kinetic_energy"][n - 1] +
                              history["sphere_strain_energy"][n - 1] - rigid;
    const double plate_stored = history["kinetic_energy"][n - 1] +
                                history["strain_energy"][n - 1] -
                                history["sphere_kinetic_energy"][n - 1] -
                                history["sphere_strain_energy"][n - 1];

    nlohmann::json summary;
    auto           number = [](const double x) {
      return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
    };
    summary["complete"]               = complete;
    summary["impact_velocity"]        = impact_velocity;
    summary["contact_velocity"]       = contact_velocity;
    summary["first_contact_time"]     = number(first_contact);
    summary["separation_time"]        = number(separation);
    summary["contact_time"]           = number(contact_time);
    summary["force_max"]              = force[peak];
    summary["time_force_max"]         = t[peak];
    summary["approach_max"]           = approach_max;
    summary["rebound_velocity"]       = number(rebound_velocity);
    summary["restitution"]            = number(restitution);
    summary["lost_energy_fraction"]   = number(1 - restitution * restitution);
    summary["energy_error"]           = energy_error;
    summary["energy_error_final"]     = history["energy_error"][n - 1];
    summary["initial_energy"]         = E0;
    summary["sphere_vibration_energy_fraction"] = number(sphere_vib / E0);
    summary["plate_energy_fraction"]  = plate_stored / E0;
    summary["radiated_energy_fraction"] = history["radiated_energy"][n - 1] / E0;
    summary["dissipated_energy_fraction"] =
      history["dissipated_energy"][n - 1] / E0;
    summary["max_von_mises"]          = max_von_mises;
    summary["max_penetration"]        = penetration;
    // Yield check: the viscoelastic model holds only below the elastic limit.
    bool        any_yield_strength = false, yield_exceeded = false;
    std::string yield_report;
    for (unsigned int body = 0; body < 2; ++body)
      {
        const std::string name = body == 0 ? "sphere" : "plate";
        const StressPeak &peak = stress_peak[body];
        const bool has_limit   = yield_strength[body] > 0;
        const bool exceeded    = has_limit && peak.first_yield_time >= 0;
        any_yield_strength |= has_limit;
        yield_exceeded |= exceeded;
        summary["von_mises_max_" + name]           = peak.value;
        summary["von_mises_max_" + name + "_time"] = peak.time;
        summary["von_mises_max_" + name + "_r"]    = peak.location[0];
        summary["von_mises_max_" + name + "_z"]    = peak.location[1];
        summary["yield_strength_" + name] =
          has_limit ? nlohmann::json(yield_strength[body]) : nlohmann::json(nullptr);
        summary["yield_exceeded_" + name] =
          has_limit ? nlohmann::json(exceeded) : nlohmann::json(nullptr);
        summary["yield_time_" + name] =
          exceeded ? nlohmann::json(peak.first_yield_time) : nlohmann::json(nullptr);
        summary["yield_r_" + name] =
          exceeded ? nlohmann::json(peak.first_yield_location[0]) :
                     nlohmann::json(nullptr);
        summary["yield_z_" + name] =
          exceeded ? nlohmann::json(peak.first_yield_location[1]) :
                     nlohmann::json(nullptr);
        std::ostringstream line;
        line << std::setprecision(4) << "  von Mises " << name << " max "
             << peak.value / 1e9 << " GPa at t = " << peak.time * 1e6
             << " us, (r, z) = (" << peak.location[0] * 1e3 << ", "
             << peak.location[1] * 1e3 << ") mm";
        if (exceeded)
          line << "; YIELD STRENGTH " << yield_strength[body] / 1e9
               << " GPa EXCEEDED from t = " << peak.first_yield_time * 1e6
               << " us at (" << peak.first_yield_location[0] * 1e3 << ", "
               << peak.first_yield_location[1] * 1e3 << ") mm";
        else if (has_limit)
          line << " (below the yield strength " << yield_strength[body] / 1e9
               << " GPa)";
        yield_report += line.str() + "\n";
      }
    summary["yield_exceeded"] = any_yield_strength ?
                                  nlohmann::json(yield_exceeded) :
                                  nlohmann::json(nullptr);
    summary["sphere_mass"]    = sphere_mass;
    summary["internal_energy_fraction"] =
      history["internal_energy"][n - 1] / E0;
    summary["time_step"]              = time_integrator.time_step;
    summary["cells"]                  = triangulation.n_global_active_cells();
    summary["dofs"]                   = dof_handler.n_dofs();
    summary["contact_nodes"]          = contact.n_contact_nodes();
    summary["steps"]                  = step;
    summary["ranks"] = Utilities::MPI::n_mpi_processes(mpi_communicator);
    summary["wall_time"]              = wall_time;

    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;

    // The parameters and the derived results travel with the histories.
    std::stringstream prm_json;
    parameters.print_parameters(prm_json, ParameterHandler::ShortJSON);
    std::map<std::string, std::string> text_attributes;
    flatten(nlohmann::json::parse(prm_json.str()), "", text_attributes);
    std::map<std::string, double> numeric_attributes;
    for (const auto &[key, value] : summary.items())
      if (value.is_number())
        numeric_attributes["result: " + key] = value.get<double>();
    numeric_attributes["sphere_mass [kg]"]            = sphere_mass;
    numeric_attributes["hertz_contact_time [s]"]      = hertz_contact_time;
    history.write_hdf5(output_directory + "/history.h5",
                       text_attributes,
                       numeric_attributes,
                       complete);
    if (!complete)
      return;

    const std::string summary_file = output_directory + "/summary.json";
    {
      std::ofstream out(summary_file + ".tmp");
      out << std::setw(2) << summary << std::endl;
    }
    std::filesystem::rename(summary_file + ".tmp", summary_file);

    if (static_press)
      {
        pcout << "\nResult of the static press (" << output_directory
                  << "):\n"
                  << std::setprecision(5) << "  contact force     "
                  << force[n - 1] << " N\n"
                  << "  contact radius    "
                  << history["contact_radius"][n - 1] * 1e3 << " mm\n"
                  << "  max pressure      "
                  << history["max_pressure"][n - 1] / 1e9 << " GPa\n"
                  << "  approach          " << history["approach"][n - 1] * 1e6
                  << " um\n"
                  << "  max penetration   " << penetration * 1e9 << " nm\n"
                  << "  cells " << triangulation.n_global_active_cells()
                  << ", dofs " << dof_handler.n_dofs() << ", wall time "
                  << wall_time << " s" << std::endl;
        return;
      }
    pcout << "\nResult (" << output_directory << "):\n"
              << std::setprecision(5)
              << "  first contact     " << first_contact * 1e6
              << " us, separation " << separation * 1e6 << " us\n"
              << "  contact time      " << contact_time * 1e6 << " us\n"
              << "  peak force        " << force[peak] / 1e3 << " kN at "
              << t[peak] * 1e6 << " us\n"
              << "  peak approach     " << approach_max * 1e6 << " um\n"
              << "  rebound velocity  " << rebound_velocity << " m/s\n"
              << "  restitution       " << restitution
              << " (lost energy fraction " << (1 - restitution * restitution) * 100
              << " %)\n"
              << "  energy: sphere vibration " << sphere_vib / E0 * 100
              << " %, plate " << plate_stored / E0 * 100 << " %, radiated "
              << history["radiated_energy"][n - 1] / E0 * 100
              << " %, dissipated "
              << history["dissipated_energy"][n - 1] / E0 * 100
              << " %, balance error " << energy_error * 100 << " %\n"
              << yield_report
              << "  max penetration   " << penetration * 1e9 << " nm\n"
              << "  cells " << triangulation.n_global_active_cells()
              << ", dofs " << dof_handler.n_dofs() << ", steps " << step
              << ", ranks " << Utilities::MPI::n_mpi_processes(mpi_communicator)
              << ", wall time " << wall_time << " s" << std::endl;
  }


  void
  ImpactProblem::run()
  {
    wall_start = last_progress = std::chrono::steady_clock::now();
    computing_timer = std::make_unique<TimerOutput>(mpi_communicator,
                                                    pcout,
                                                    TimerOutput::never,
                                                    TimerOutput::wall_times);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::filesystem::create_directories(output_directory);
        if (snapshot_interval > 0)
          std::filesystem::create_directories(output_directory + "/snapshots");
        // Results of an earlier run in the same place would be mistaken for
        // this run's.
        for (const auto *name :
             {"history.h5", "history.incomplete.h5", "summary.json"})
          std::filesystem::remove(output_directory + "/" + name);
      }
    MPI_Barrier(mpi_communicator);

    make_mesh();
    setup_system();
    assemble_system();
    factorize_effective_stiffness();
    setup_contact();
    set_initial_conditions();
    history.set_profile("contact_node_radius",
                        "m",
                        "radius of the contact nodes (vertices of the "
                        "plate's contact surface)",
                        contact.node_radii());

    struct Quantity
    {
      std::string name, unit, description;
    };
    for (const auto &[name, unit, description] :
         std::vector<Quantity>{
           {"time", "s", "simulated time"},
           {"contact_force", "N", "total normal contact force, 2 pi int p r dr"},
           {"sphere_displacement", "m", "centre-of-mass displacement of the sphere, downward positive"},
           {"sphere_velocity", "m/s", "centre-of-mass velocity of the sphere, downward positive"},
           {"plate_displacement", "m", "mean vertical displacement of the plate bottom, downward positive"},
           {"approach", "m", "sphere_displacement - initial gap - plate_displacement"},
           {"contact_radius", "m", "contact radius: between the outermost loaded node and the next, where p^2 extrapolated linearly in r^2 vanishes"},
           {"max_pressure", "Pa", "largest nodal contact pressure"},
           {"max_von_mises", "Pa", "largest von Mises stress in both bodies within 2 contact surface radii of the contact point"},
           {"max_von_mises_r", "m", "radial position of max_von_mises"},
           {"max_von_mises_z", "m", "axial position of max_von_mises (reference configuration)"},
           {"max_von_mises_sphere", "Pa", "largest von Mises stress in the sphere (same zone)"},
           {"max_von_mises_sphere_r", "m", "radial position of max_von_mises_sphere"},
           {"max_von_mises_sphere_z", "m", "axial position of max_von_mises_sphere (reference configuration)"},
           {"max_von_mises_plate", "Pa", "largest von Mises stress in the plate (same zone)"},
           {"max_von_mises_plate_r", "m", "radial position of max_von_mises_plate"},
           {"max_von_mises_plate_z", "m", "axial position of max_von_mises_plate (reference configuration)"},
           {"kinetic_energy", "J", "kinetic energy of both bodies"},
           {"strain_energy", "J", "stored elastic energy of both bodies, including internal_energy"},
           {"internal_energy", "J", "elastic energy stored in the springs of the Maxwell arms (part of strain_energy)"},
           {"dissipated_energy", "J", "cumulative viscous dissipation in the materials"},
           {"radiated_energy", "J", "cumulative energy absorbed by the far-boundary dashpots"},
           {"gravity_work", "J", "cumulative work of gravity on the sphere"},
           {"contact_work", "J", "cumulative work of the contact forces (zero for an ideal constraint)"},
           {"energy_error", "1", "(kinetic + strain + dissipated + radiated - initial - gravity work) / initial energy"},
           {"sphere_kinetic_energy", "J", "kinetic energy of the sphere"},
           {"sphere_strain_energy", "J", "strain energy of the sphere"},
           {"penetration", "m", "largest weighted penetration of a contact node (round-off)"}})
      history.declare(name, unit, description);
    record_step();

    unsigned int snapshot = 0;
    double       next_snapshot = 0;
    auto write_snapshot_if_due = [&]() {
      if (snapshot_interval > 0 && time >= next_snapshot - 1e-3 * time_integrator.time_step)
        {
          output_results(snapshot++);
          next_snapshot += snapshot_interval;
        }
    };
    write_snapshot_if_due();

    // An interrupted run (SIGINT, SIGTERM) and a failing one keep what they
    // computed in history.incomplete.h5, which is also refreshed every
    // minute so that even a killed run leaves its history behind.
    const ScopedInterruptHandler interrupt_handler;
    // Checked before every step and once more after the last one, so that a
    // signal received at any time of the loop leaves the run incomplete.
    const auto stop_if_interrupted = [&]() {
      const int signal =
        Utilities::MPI::max(static_cast<int>(interrupt_signal),
                            mpi_communicator);
      AssertThrow(signal == 0,
                  ExcMessage("Interrupted by signal " + std::to_string(signal) +
                             " at t = " + std::to_string(time) +
                             " s; the history so far is in " +
                             output_directory + "/history.incomplete.h5."));
    };
    auto last_checkpoint = std::chrono::steady_clock::now();
    try
      {
        while (time < end_time - 0.5 * time_integrator.time_step)
          {
            stop_if_interrupted();
            solve_time_step();
            record_step();
            write_snapshot_if_due();
            print_progress(false);

            const bool checkpoint_due = Utilities::MPI::broadcast(
              mpi_communicator,
              std::chrono::steady_clock::now() - last_checkpoint >
                std::chrono::seconds(60),
              0);
            if (checkpoint_due)
              {
                write_results(false);
                last_checkpoint = std::chrono::steady_clock::now();
              }
          }
        print_progress(true);
        stop_if_interrupted();
      }
    catch (...)
      {
        // Keep what was computed, marked incomplete, then report the cause.
        write_results(false);
        throw;
      }
    if (separation_time < 0 && !static_press)
      pcout << "Warning: the bodies did not separate before the end of the "
               "run (Time integration/Maximum time)." << std::endl;
    write_results(true);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::remove(output_directory + "/history.incomplete.h5");
    computing_timer->print_summary();
  }
} // namespace impact_fem
