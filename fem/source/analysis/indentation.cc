#include <impact_fem/analysis/indentation.h>
#include <impact_fem/analysis/interface.h>
#include <impact_fem/as_written.h>
#include <impact_fem/result_files.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace impact_fem
{
  namespace
  {
    // A quasi-static step has no duration: the plastic strain rate is zero
    // (Johnson-Cook's rate factor is 1) and no viscous stress arises.
    constexpr double quasi_static_time_step =
      std::numeric_limits<double>::infinity();


    // Elastic-plastic bodies are rate-independent in a quasi-static
    // analysis (the plastic strain rate is zero, so Johnson-Cook's rate
    // factor is 1); their Kelvin-Voigt retardation time is not.
    void
    require_rate_independent(const Parameters &parameters)
    {
      bool linear_memory = false;
      for (const auto &m : parameters.material)
        linear_memory = linear_memory ||
                        (m && m->is_linear() && m->n_internal_variables() > 0);
      AssertThrow(!parameters.has_material_damping() && !linear_memory,
                  ExcMessage("The 'indentation' analysis is quasi-static and "
                             "rate-independent: Sphere and Plate must be "
                             "elastic or elastic-plastic with Elastic-plastic/"
                             "Retardation time = 0 (Kelvin-Voigt and Maxwell "
                             "materials need a loading rate)."));
    }
  } // namespace


  void
  IndentationControl::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Indentation");
    prm.declare_entry("Maximum approach",
                      "1e-6",
                      Patterns::Double(),
                      "Largest approach of the indentation [m], > 0: the "
                      "displacement of the hemisphere's base towards the "
                      "plate (the interference omega of the sphere-flat "
                      "literature).");
    prm.declare_entry("Steps",
                      "20",
                      Patterns::Integer(),
                      "Number of equal load steps from zero to the maximum "
                      "approach, and again back [-], in [1, 100000].");
    prm.declare_entry("Base radial displacement",
                      "free",
                      Patterns::Selection("free|fixed"),
                      "Radial condition on the hemisphere's base, whose "
                      "vertical displacement is prescribed: 'free' (a "
                      "roller) or 'fixed' (u_r = 0 too).");
    prm.leave_subsection();
  }


  void
  IndentationControl::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Indentation");
    maximum_approach    = prm.get_double("Maximum approach");
    const long n        = prm.get_integer("Steps");
    base_fixed_radially = prm.get("Base radial displacement") == "fixed";
    prm.leave_subsection();
    AssertThrow(maximum_approach > 0,
                ExcMessage(
                  "Indentation/Maximum approach must be positive, got " +
                  as_written(maximum_approach) + " m."));
    AssertThrow(n >= 1 && n <= 100000,
                ExcMessage("Indentation/Steps must lie in [1, 100000], got " +
                           std::to_string(n) + "."));
    steps = static_cast<unsigned int>(n);
  }


  std::vector<double>
  IndentationControl::approaches() const
  {
    std::vector<double> result;
    for (unsigned int k = 0; k <= steps; ++k)
      result.push_back(maximum_approach * k / steps);
    for (unsigned int k = steps; k-- > 0;)
      result.push_back(maximum_approach * k / steps);
    return result;
  }


  // Where the accumulated plastic strain peaks: its value and the point
  // (radius, depth below the sphere's lowest point, reference
  // configuration) [-, m, m].
  struct IndentationProblem::PlasticZonePeak
  {
    double value = 0, radius = 0, depth = 0;
  };


  // What an elastic-plastic indentation reports beyond the elastic one.
  struct IndentationProblem::PlasticIndentation
  {
    unsigned int iterations = 0, most_iterations = 0, bisections = 0;
    // The first step with plastic strain: approach, contact radius and
    // where the plastic strain is largest then.
    bool            yielded        = false;
    double          onset_approach = 0, onset_contact_radius = 0;
    PlasticZonePeak onset, at_force_max;
    double          force_max = -1;
    // The permanent approach lies in [first, second].
    std::array<double, 2> released_between = {{0, 0}};

    void
    observe(const PlasticZonePeak &peak,
            const double           approach,
            const double           force,
            const double           contact_radius,
            const bool             unloading)
    {
      if (!yielded && peak.value > 0)
        {
          yielded              = true;
          onset                = peak;
          onset_approach       = approach;
          onset_contact_radius = contact_radius;
        }
      if (!unloading && force > force_max)
        {
          force_max    = force;
          at_force_max = peak;
        }
    }
  };


  struct IndentationProblem::Outcome
  {
    /// Elastic-plastic bodies: iterated steps, the plastic state committed
    /// after each, and what the plastic zone does.
    bool               plastic = false;
    PlasticIndentation plastic_record;
    VectorType         committed;
    /// The sphere's lowest point (reference configuration), from which
    /// the depth of the plastic zone is measured.
    double      lowest    = 0;
    double      force_max = 0, radius_at_force_max = 0, deepest = 0;
    double      residual_approach = 0, last_loaded_approach = 0;
    bool        released = false;
    std::size_t step     = 0;
  };


  IndentationProblem::IndentationProblem(ParameterHandler &prm,
                                         const MPI_Comm    comm,
                                         std::ostream     &log)
    : SpherePlateSetup(
        prm,
        comm,
        log,
        Loading{[&prm](const Parameters &parameters) {
                  // The mesh is made for the contact at the maximum
                  // approach.
                  IndentationControl control;
                  control.parse_parameters(prm);
                  return discretisation::ExpectedContact::of_indentation(
                    parameters.hertz, control.maximum_approach);
                },
                true,
                [](const Parameters &parameters) {
                  require_plate_held(parameters);
                  require_rate_independent(parameters);
                }})
  {
    indentation_control.parse_parameters(prm);
    describe_bodies();
    const HertzImpact &hertz                   = parameters.hertz;
    const double       expected_contact_radius = std::sqrt(
      parameters.geometry.sphere_radius * indentation_control.maximum_approach);
    check_contact_surface(expected_contact_radius);
    const double omega = indentation_control.maximum_approach;
    pcout << "impact-fem: indentation of a hemisphere R = "
          << parameters.geometry.sphere_radius * 1e3 << " mm to " << omega * 1e6
          << " um in " << indentation_control.steps << " steps"
          << (parameters.rigid_plate ? " (rigid flat)" : "")
          << "\n  Hertz at the maximum approach: force "
          << hertz.stiffness() * std::pow(omega, 1.5) << " N, contact radius "
          << expected_contact_radius * 1e3 << " mm" << std::endl;
  }


  void
  IndentationProblem::run()
  {
    // Installed before anything else: a signal during the setup is kept
    // and stops the run at the first step.
    const InterruptHandler interrupt_handler;
    start_run();
    make_mesh();
    setup_system();
    // The step only enters the internal tangent, which the quasi-static
    // steps do not use.
    assemble_system(parameters.time_step());
    setup_indentation();
    setup_contact();

    Outcome outcome;
    // Elastic-plastic bodies: iterated steps, the plastic state committed
    // after each, and what the plastic zone does.
    initialize_internal_variables();
    outcome.plastic = arms.nonlinear();
    outcome.committed.reinit(locally_owned_dofs, mpi_communicator);
    declare_history(outcome.plastic);
    // The sphere's lowest point (reference configuration), from which the
    // depth of the plastic zone is measured.
    double lowest = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->material_id() == body_ids::sphere)
        for (const unsigned int v : cell->vertex_indices())
          lowest = std::min(lowest, cell->vertex(v)[1]);
    outcome.lowest = Utilities::MPI::min(lowest, mpi_communicator);

    run_load_program(outcome);
    write_results(outcome);
    computing_timer->print_summary();
  }


  void
  IndentationProblem::setup_indentation()
  {
    TimerOutput::Scope t(*computing_timer, "factorize");
    // The vertical displacement of the base is prescribed: its rows of K
    // become identity rows (the columns stay, so that the solve of
    // K' u = b with b = prescribed value on the base rows carries the
    // prescribed value into the body). Any other load that vanishes on the
    // base, like the contact forces B^T lambda, sees the body with its base
    // held in place.
    const IndexSet base_dofs =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      fe->component_mask(
                                        FEValuesExtractors::Scalar(1)),
                                      {boundary_ids::sphere_base});
    // Held radially as well: identity rows with the value 0 (u_r = 0 on
    // the axis is already a constraint).
    const IndexSet radial_base_dofs =
      indentation_control.base_fixed_radially ?
        DoFTools::extract_boundary_dofs(dof_handler,
                                        fe->component_mask(
                                          FEValuesExtractors::Scalar(0)),
                                        {boundary_ids::sphere_base}) :
        IndexSet(dof_handler.n_dofs());
    AssertThrow(Utilities::MPI::sum(base_dofs.n_elements(), mpi_communicator) >
                  0,
                ExcMessage("The indentation mesh has no hemisphere base "
                           "(physical group 8 of the geometry file)."));
    std::vector<types::global_dof_index> owned_base;
    for (const auto i : base_dofs)
      if (locally_owned_dofs.is_element(i))
        {
          AssertThrow(!constraints.is_constrained(i),
                      ExcMessage("Internal error: a base dof is constrained."));
          owned_base.push_back(i);
        }
    std::vector<types::global_dof_index> held_rows(owned_base);
    for (const auto i : radial_base_dofs)
      if (locally_owned_dofs.is_element(i) && !constraints.is_constrained(i))
        held_rows.push_back(i);
    effective_stiffness.copy_from(system.stiffness);
    effective_stiffness.clear_rows(held_rows, 1.);
    factorize();

    // The response to a unit approach: the base moved by -1 m in z.
    VectorType unit_load(locally_owned_dofs, mpi_communicator);
    for (const auto i : owned_base)
      unit_load[i] = -1;
    unit_load.compress(VectorOperation::insert);
    unit_approach_response.reinit(locally_owned_dofs, mpi_communicator);
    direct_solver->solve(unit_approach_response, unit_load);
    unit_approach_load    = unit_load;
    indentation_held_rows = held_rows;
  }


  void
  IndentationProblem::solve_indentation_step(const double approach,
                                             VectorType  &displacement)
  {
    // Elastic bodies: K is constant, so the equilibrium with the base at
    // -approach is u = approach u_1 + W lambda (u_1 the response to a unit
    // approach, W = K'^{-1} B^T), lambda from one complementarity problem,
    // solved exactly. Elastic-plastic bodies iterate this step on their
    // plastic force (solve_plastic_indentation_step).
    displacement.equ(approach, unit_approach_response);
    pressures =
      contact.solve_complementarity(contact.weighted_gaps(displacement));
    contact.add_contact_response(pressures, displacement);
  }


  time_integration::NonlinearStep::Result
  IndentationProblem::solve_plastic_indentation_step(
    const double      approach,
    const VectorType &committed_displacement,
    VectorType       &displacement)
  {
    // K' u = approach e + f_p(u) + B^T lambda with the plastic force f_p
    // of the committed state, iterated like an impact step
    // (NonlinearStep): every iteration is the elastic step above for a
    // given plastic force. The held rows of the base are prescribed, so
    // their plastic force is dropped (their equation is u = prescribed).
    const auto hold = [this](VectorType &force) {
      for (const auto i : indentation_held_rows)
        force[i] = 0;
      force.compress(VectorOperation::insert);
    };
    VectorType load(unit_approach_load), contact_force(load), distributed(load),
      start(arms.committed_plastic_force());
    hold(start);
    // The force scale of the convergence criterion: the contact force of
    // the iterate plus the committed plastic force (which, like the body
    // force of an impact step, does not vanish when the contact opens: near
    // the release the contact force alone tends to zero).
    const double committed_norm = start.l2_norm();
    const auto   linear_solve   = [&](const VectorType &plastic_force,
                                  VectorType       &u) {
      load = plastic_force;
      hold(load);
      load.add(approach, unit_approach_load);
      solve_linear_step(load, u);
      contact_force = 0;
      contact.add_contact_forces(pressures, contact_force);
      return contact_force.l2_norm() + committed_norm;
    };
    const auto plastic_force = [&](const VectorType &u, VectorType &force) {
      TimerOutput::Scope t(*computing_timer, "plastic force");
      distributed = u;
      constraints.distribute(distributed);
      ghosted_trial = distributed;
      arms.plastic_force(constraints,
                         ghosted_trial,
                         quasi_static_time_step,
                         force);
      hold(force);
    };
    return nonlinear_step.solve(
      start, committed_displacement, displacement, linear_solve, plastic_force);
  }


  void
  IndentationProblem::declare_history(const bool plastic)
  {
    history.declare(
      {{"approach",
        "m",
        "displacement of the hemisphere's base towards the plate minus the "
        "mean displacement of the plate bottom (downward positive): the "
        "interference omega"},
       {"base_displacement",
        "m",
        "prescribed downward displacement of the hemisphere's base"},
       {"contact_force", "N", "total normal contact force, 2 pi int p r dr"},
       {"contact_radius",
        "m",
        "contact radius: between the outermost loaded node and the next, where "
        "p^2 extrapolated linearly in r^2 vanishes"},
       {"max_pressure", "Pa", "largest nodal contact pressure"},
       {"penetration",
        "m",
        "largest pointwise penetration of a contact node (the constraint holds "
        "in the weighted sense)"},
       {"unloading",
        "1",
        "0 on the loading branch (and the start), 1 on the unloading branch"}});
    history.set_profile("contact_node_radius",
                        "m",
                        "radius of the contact nodes",
                        contact.node_radii());
    if (plastic)
      {
        declare_iteration_history("||f_p,n||");
        history.declare({{"max_accumulated_plastic_strain",
                          "1",
                          "largest accumulated plastic strain of both bodies"},
                         {"plastic_work",
                          "J",
                          "cumulative plastic work int sigma : d eps^p"}});
      }
  }


  IndentationProblem::PlasticZonePeak
  IndentationProblem::plastic_zone_peak(const double lowest) const
  {
    FEValues<2> fe_values(*mapping, *fe, *quadrature, update_quadrature_points);
    PlasticZonePeak local;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto states = arms.states(cell);
          if (states.empty())
            continue;
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < states.size(); ++q)
            if (states[q]->accumulated_plastic_strain > local.value)
              {
                local.value  = states[q]->accumulated_plastic_strain;
                local.radius = fe_values.quadrature_point(q)[0];
                local.depth  = fe_values.quadrature_point(q)[1] - lowest;
              }
        }
    PlasticZonePeak global;
    global.value = Utilities::MPI::max(local.value, mpi_communicator);
    // The rank that holds the peak gives its place (the others send 0).
    const bool         mine = local.value == global.value && global.value > 0;
    const unsigned int owner =
      Utilities::MPI::min(mine ?
                            Utilities::MPI::this_mpi_process(mpi_communicator) :
                            Utilities::MPI::n_mpi_processes(mpi_communicator),
                          mpi_communicator);
    const bool sends =
      owner == Utilities::MPI::this_mpi_process(mpi_communicator);
    global.radius =
      Utilities::MPI::sum(sends ? local.radius : 0., mpi_communicator);
    global.depth =
      Utilities::MPI::sum(sends ? local.depth : 0., mpi_communicator);
    return global;
  }


  // Solve one step; a plastic step that does not converge stops the run.
  // A step to be committed (@p prepare) is solved on the candidate cells
  // of the plastic states and again if a point elsewhere yielded
  // (InternalVariables::prepare_commit, as for an impact step); the
  // bisection's trials are not committed and leave the prepared state of
  // the step alone.
  void
  IndentationProblem::solve_step(const std::size_t step,
                                 const double      approach,
                                 VectorType       &displacement,
                                 const bool        prepare,
                                 Outcome          &outcome)
  {
    TimerOutput::Scope t(*computing_timer, "solve indentation step");
    if (!outcome.plastic)
      {
        solve_indentation_step(approach, displacement);
        return;
      }
    const VectorType &committed = outcome.committed;
    auto              result =
      solve_plastic_indentation_step(approach, committed, displacement);
    unsigned int iterations = result.iterations;
    while (
      prepare && result.converged &&
      !arms.prepare_commit(constraints, ghosted_trial, quasi_static_time_step))
      {
        result =
          solve_plastic_indentation_step(approach, committed, displacement);
        iterations += result.iterations;
      }
    result.iterations                  = iterations;
    step_iterations                    = result.iterations;
    step_residual                      = result.residual;
    PlasticIndentation &plastic_record = outcome.plastic_record;
    plastic_record.iterations += result.iterations;
    plastic_record.most_iterations =
      std::max(plastic_record.most_iterations, result.iterations);
    if (!result.converged)
      {
        // The criterion in words, with the force scale of this analysis.
        std::string       criterion    = nonlinear_step.criterion();
        const std::string impact_scale = "||f_body||";
        const auto        at           = criterion.find(impact_scale);
        if (at != std::string::npos)
          criterion.replace(at, impact_scale.size(), "||f_p,n||");
        std::ostringstream message;
        message << std::setprecision(6) << "Indentation step " << step
                << " (approach " << approach << " m, "
                << (step > indentation_control.steps ? "unloading" : "loading")
                << ") did not converge: after " << result.iterations
                << " iterations the residual is " << result.residual
                << " of the load and the increment " << result.increment
                << " of the step's; required " << criterion << ".";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }


  void
  IndentationProblem::commit(const VectorType &displacement, Outcome &outcome)
  {
    outcome.committed = displacement;
    VectorType distributed(displacement), unused(displacement);
    constraints.distribute(distributed);
    ghosted_u = distributed;
    arms.update(dof_handler,
                *mapping,
                *quadrature,
                constraints,
                ghosted_u,
                quasi_static_time_step,
                unused);
  }


  void
  IndentationProblem::run_load_program(Outcome &outcome)
  {
    const std::vector<double> approaches = indentation_control.approaches();
    VectorType  displacement(locally_owned_dofs, mpi_communicator);
    std::size_t step = 0;
    for (; step < approaches.size() && !outcome.released; ++step)
      {
        AssertThrow(interrupt_received() == 0,
                    ExcMessage("Interrupted by signal " +
                               std::to_string(interrupt_received()) +
                               " at indentation step " + std::to_string(step) +
                               "."));
        const bool unloading = step > indentation_control.steps;
        solve_step(step, approaches[step], displacement, true, outcome);
        const double force = contact.total_force(pressures);
        // The permanent approach of a plastic body lies between this step
        // and the last loaded one: bisected from the last committed state
        // (elastic unloading, no new plastic flow expected) until the
        // bracket is 1e-4 of the maximum approach.
        const unsigned int step_iterations_kept = step_iterations;
        const double       step_residual_kept   = step_residual;
        if (outcome.plastic && unloading && force <= 0)
          bisect_release(step, displacement, outcome);
        if (outcome.plastic)
          {
            commit(displacement, outcome);
            history.append(result_files::newton_iterations_dataset,
                           step_iterations_kept);
            history.append(result_files::newton_residual_dataset,
                           step_residual_kept);
            history.append("max_accumulated_plastic_strain",
                           std::max(arms.max_accumulated_plastic_strain(0),
                                    arms.max_accumulated_plastic_strain(1)));
            history.append("plastic_work", arms.plastic_work());
            outcome.plastic_record.observe(plastic_zone_peak(outcome.lowest),
                                           approaches[step],
                                           force,
                                           contact.contact_radius(pressures),
                                           unloading);
          }
        record_step(step, displacement, outcome);
      }
    outcome.step = step;
  }


  void
  IndentationProblem::bisect_release(const std::size_t step,
                                     const VectorType &displacement,
                                     Outcome          &outcome)
  {
    const std::vector<double> approaches = indentation_control.approaches();
    double               low = approaches[step], high = approaches[step - 1];
    VectorType           trial(displacement);
    const Vector<double> kept_pressures(pressures);
    while (high - low > 1e-4 * indentation_control.maximum_approach)
      {
        const double middle = 0.5 * (low + high);
        solve_step(step, middle, trial, false, outcome);
        (contact.total_force(pressures) > 0 ? high : low) = middle;
        ++outcome.plastic_record.bisections;
      }
    pressures                               = kept_pressures;
    outcome.plastic_record.released_between = {{low, high}};
  }


  void
  IndentationProblem::record_step(const std::size_t step,
                                  const VectorType &displacement,
                                  Outcome          &outcome)
  {
    const std::vector<double> approaches = indentation_control.approaches();
    const bool                unloading  = step > indentation_control.steps;
    const double              force      = contact.total_force(pressures);
    const double              plate_displacement =
      -(weights.plate_bottom_mean * displacement);
    const double penetration  = contact.penetration(displacement);
    double       max_pressure = 0;
    for (const double p : pressures)
      max_pressure = std::max(max_pressure, p);
    outcome.deepest = std::max(outcome.deepest, penetration);
    history.append("approach", approaches[step] - plate_displacement);
    history.append("base_displacement", approaches[step]);
    history.append("contact_force", force);
    history.append("contact_radius", contact.contact_radius(pressures));
    history.append("max_pressure", max_pressure);
    history.append("penetration", penetration);
    history.append("unloading", unloading ? 1. : 0.);
    if (force > outcome.force_max)
      {
        outcome.force_max           = force;
        outcome.radius_at_force_max = contact.contact_radius(pressures);
        history.set_profile("pressure_at_force_max",
                            "Pa",
                            "contact pressure at the contact nodes at the "
                            "largest contact force",
                            std::vector<double>(pressures.begin(),
                                                pressures.end()));
      }
    // Unloading ends where the force vanishes: the approach left then
    // is the permanent one (zero for an elastic body).
    if (unloading && force <= 0)
      {
        outcome.released          = true;
        outcome.residual_approach = approaches[step] - plate_displacement;
        if (outcome.plastic)
          {
            outcome.residual_approach =
              outcome.plastic_record.released_between[0];
            outcome.last_loaded_approach =
              outcome.plastic_record.released_between[1];
          }
      }
    else if (unloading)
      outcome.last_loaded_approach = approaches[step] - plate_displacement;
  }


  void
  IndentationProblem::write_results(const Outcome &outcome)
  {
    const double wall_time = std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - wall_start)
                               .count();
    const double R     = parameters.geometry.sphere_radius;
    const double omega = indentation_control.maximum_approach;
    const double hertz_force =
      parameters.hertz.stiffness() * std::pow(omega, 1.5);
    nlohmann::json result;
    result["complete"]           = true;
    result["analysis"]           = "indentation";
    result["maximum_approach"]   = omega;
    result["steps"]              = indentation_control.steps;
    result["force_max"]          = outcome.force_max;
    result["contact_radius_max"] = outcome.radius_at_force_max;
    result["residual_approach"]  = outcome.residual_approach;
    result["residual_approach_upper_bound"] =
      outcome.released ? outcome.last_loaded_approach : omega;
    result["released"]                 = outcome.released;
    result["max_penetration"]          = outcome.deepest;
    result["hertz_force_max"]          = hertz_force;
    result["hertz_contact_radius_max"] = std::sqrt(R * omega);
    result["effective_modulus"]        = parameters.hertz.effective_modulus;
    result["cells"]                    = triangulation.n_global_active_cells();
    result["dofs"]                     = dof_handler.n_dofs();
    result["contact_nodes"]            = contact.n_contact_nodes();
    result["ranks"]     = Utilities::MPI::n_mpi_processes(mpi_communicator);
    result["wall_time"] = wall_time;
    if (outcome.plastic)
      {
        // The permanent approach bisected to 1e-4 of the maximum approach;
        // the yield onset and the plastic zone at the largest force.
        result["residual_approach_bisections"] =
          outcome.plastic_record.bisections;
        result["plastic_work"] = arms.plastic_work();
        result["max_accumulated_plastic_strain"] =
          std::max(arms.max_accumulated_plastic_strain(0),
                   arms.max_accumulated_plastic_strain(1));
        result["newton_iterations"] = outcome.plastic_record.iterations;
        result["newton_iterations_max"] =
          outcome.plastic_record.most_iterations;
        result["yielded"]              = outcome.plastic_record.yielded;
        result["yield_onset_approach"] = outcome.plastic_record.onset_approach;
        result["yield_onset_contact_radius"] =
          outcome.plastic_record.onset_contact_radius;
        result["yield_onset_r"]     = outcome.plastic_record.onset.radius;
        result["yield_onset_depth"] = outcome.plastic_record.onset.depth;
        result["plastic_strain_peak_at_force_max"] =
          outcome.plastic_record.at_force_max.value;
        result["plastic_strain_peak_r_at_force_max"] =
          outcome.plastic_record.at_force_max.radius;
        result["plastic_strain_peak_depth_at_force_max"] =
          outcome.plastic_record.at_force_max.depth;
      }
    AssertThrow(outcome.released,
                ExcMessage("Internal error: the contact force did not vanish "
                           "at zero approach."));

    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::map<std::string, std::string> text_attributes = parameter_attributes();
    text_attributes["definition: residual_approach"] =
      outcome.plastic ?
        "permanent approach: the largest approach with zero contact force "
        "found by bisection between the last unloading step with force and "
        "the first without (to 1e-4 of the maximum approach; "
        "residual_approach_upper_bound the smallest with force)" :
        "approach of the first unloading step with zero contact force (the "
        "permanent approach lies between it and residual_approach_upper_bound, "
        "the approach of the step before)";
    std::map<std::string, double> numeric_attributes;
    for (const auto &[key, value] : result.items())
      if (value.is_number())
        numeric_attributes["result: " + key] = value.get<double>();
    const std::string &directory = parameters.output_directory;
    history.write_hdf5(directory + "/history.h5",
                       text_attributes,
                       numeric_attributes,
                       true);
    {
      std::ofstream out(directory + "/summary.json.tmp");
      out << std::setw(2) << result << std::endl;
    }
    std::filesystem::rename(directory + "/summary.json.tmp",
                            directory + "/summary.json");
    print_result(outcome, result, wall_time);
  }


  void
  IndentationProblem::print_result(const Outcome        &outcome,
                                   const nlohmann::json &result,
                                   const double          wall_time) const
  {
    const std::string &directory = parameters.output_directory;
    const double       R         = parameters.geometry.sphere_radius;
    const double       omega     = indentation_control.maximum_approach;
    const double       hertz_force =
      parameters.hertz.stiffness() * std::pow(omega, 1.5);
    pcout << "\nResult (" << directory << "):\n"
          << std::setprecision(5) << "  maximum approach  " << omega * 1e6
          << " um in " << indentation_control.steps << " steps each way\n"
          << "  peak force        " << outcome.force_max << " N (Hertz "
          << hertz_force << " N)\n"
          << "  contact radius    " << outcome.radius_at_force_max * 1e3
          << " mm (Hertz " << std::sqrt(R * omega) * 1e3 << " mm)\n"
          << "  residual approach " << outcome.residual_approach * 1e6
          << " um\n";
    if (outcome.plastic)
      pcout << "  plastic work      " << arms.plastic_work()
            << " J, max accumulated "
            << "plastic strain "
            << result["max_accumulated_plastic_strain"].get<double>()
            << "\n  yield onset       at approach "
            << outcome.plastic_record.onset_approach * 1e6
            << " um, peak at r = " << outcome.plastic_record.onset.radius * 1e6
            << " um, depth " << outcome.plastic_record.onset.depth * 1e6
            << " um (contact radius "
            << outcome.plastic_record.onset_contact_radius * 1e6 << " um)\n"
            << "  iterations        " << outcome.plastic_record.iterations
            << " (max " << outcome.plastic_record.most_iterations
            << " in a step)\n";
    pcout << "  max penetration   " << outcome.deepest * 1e9 << " nm\n"
          << "  cells " << triangulation.n_global_active_cells() << ", dofs "
          << dof_handler.n_dofs() << ", steps " << outcome.step
          << ", wall time " << wall_time << " s" << std::endl;
  }


  /**
   * `Scenario/Analysis = indentation`: one IndentationProblem.
   */
  class IndentationAnalysis : public analysis::Interface
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      IndentationControl::declare_parameters(prm);
    }

    void
    parse_parameters(ParameterHandler           &prm,
                     const analysis::Invocation &invocation,
                     const MPI_Comm              comm) override
    {
      // One load program per run: campaigns and the verification's
      // grid-convergence study are built on impact results.
      analysis::require_single_run(
        prm,
        invocation,
        "indentation",
        "; run each indentation by itself (fem/bench/indentation.sh shows "
        "the mesh convergence)");
      problem = std::make_unique<IndentationProblem>(prm, comm);
    }

    int
    run() override
    {
      problem->run();
      return 0;
    }

  private:
    std::unique_ptr<IndentationProblem> problem;
  };

  IMPACT_FEM_REGISTER_ANALYSIS(
    IndentationAnalysis,
    "indentation",
    2,
    "quasi-static, displacement-controlled: the base (equatorial plane) of a "
    "hemisphere is pushed towards the plate by the approach of the subsection "
    "'Indentation' in steps and back until the force vanishes (use with a "
    "rigid plate or a plate bottom that is clamped or supported).")
} // namespace impact_fem
