#include <impact_fem/as_written.h>
#include <impact_fem/campaign/run_identity.h>
#include <impact_fem/discretisation/automatic_discretisation.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/result_files.h>
#include <impact_fem/summary/impact_summary.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace impact_fem
{
  namespace
  {
    nlohmann::json
    number(const double x)
    {
      return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
    }

    /// The run identity of the entries in @p prm (what a checkpoint must
    /// match to be resumed).
    std::string
    identity_of(const ParameterHandler &prm)
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      return run_identity::of(text.str());
    }
  } // namespace


  void
  ImpactProblem::declare_parameters(ParameterHandler &prm)
  {
    SpherePlateSetup::declare_parameters(prm);
    postprocess::declare_parameters(prm);
  }


  discretisation::ExpectedContact
  ImpactProblem::expected_contact(const Parameters &parameters)
  {
    std::vector<discretisation::ExpectedContact::YieldingBody> bodies;
    for (const unsigned int body : {sphere, plate})
      if (parameters.material[body] && parameters.material_used[body].model ==
                                         result_files::elastic_plastic_model)
        bodies.push_back({body_name(body),
                          parameters.material_used[body].yield_strength,
                          parameters.material[body]->poissons_ratio()});
    return discretisation::ExpectedContact::of_impact(parameters.hertz, bodies);
  }


  ImpactProblem::ImpactProblem(ParameterHandler       &prm,
                               const MPI_Comm          comm,
                               std::ostream           &log,
                               const EnergyRefinement &refinement)
    : ImpactProblem(prm,
                    comm,
                    log,
                    Loading{&expected_contact, false, {}},
                    true,
                    refinement)
  {}


  ImpactProblem::ImpactProblem(ParameterHandler       &prm,
                               const MPI_Comm          comm,
                               std::ostream           &log,
                               const Loading          &loading,
                               const bool              impact,
                               const EnergyRefinement &refinement)
    : SpherePlateSetup(prm, comm, log, loading)
    , time_stepper(time_integration::create_time_stepper(prm))
    , postprocessors(postprocess::create_postprocessors(prm))
  {
    resumable = impact;
    if (resumable)
      identity = identity_of(prm);
    step_sized_for_energy = impact && parameters.prescribed_time_step == 0 &&
                            parameters.steps_per_contact_time_automatic;
    // The rule refines only contact nodes it placed itself.
    spacing_sized_for_energy = step_sized_for_energy &&
                               mesh.automatic_surface_refinements &&
                               mesh.automatic_size[0];
    if (step_sized_for_energy)
      energy_refinement.step = refinement.step;
    sub_steps_sized_for_energy =
      step_sized_for_energy && parameters.entry_sub_steps_automatic;
    if (sub_steps_sized_for_energy)
      energy_refinement.entry_sub_steps = refinement.entry_sub_steps;
    if (spacing_sized_for_energy && refinement.contact_spacing_halvings > 0)
      {
        energy_refinement.contact_spacing_halvings =
          refinement.contact_spacing_halvings;
        mesh.contact_surface_refinements += refinement.contact_spacing_halvings;
        for (auto &entry : discretisation_choice.entries)
          if (entry.path == "Mesh/Contact surface refinements")
            {
              entry.value = mesh.contact_surface_refinements;
              entry.rule +=
                "; +" + std::to_string(refinement.contact_spacing_halvings) +
                " here: the energy balance missed mostly by the "
                "integrator's damping";
            }
      }
    if (impact && parameters.prescribed_time_step == 0)
      {
        std::ostringstream rule;
        rule << discretisation::AutomaticDiscretisation::steps_rule();
        if (energy_refinement.step > 1)
          rule << std::setprecision(3) << "; x " << energy_refinement.step
               << " here: the rule's step lost too much energy to the "
                  "contact activation";
        discretisation_choice.entries.push_back(
          {"Time integration/Steps per contact time",
           "1",
           parameters.steps_per_contact_time * energy_refinement.step,
           parameters.steps_per_contact_time_automatic,
           rule.str()});
      }
    if (impact)
      {
        std::string rule =
          "1, unless the step's refinement for the energy balance is capped "
          "at " +
          as_written(
            discretisation::AutomaticDiscretisation::maximum_step_refinement) +
          " times: then as many as take the contact activation's work to " +
          as_written(discretisation::AutomaticDiscretisation::
                       capped_activation_fraction) +
          " of the target";
        if (energy_refinement.entry_sub_steps > 1)
          rule +=
            "; " + std::to_string(energy_refinement.entry_sub_steps) + " here";
        discretisation_choice.entries.push_back(
          {"Time integration/Sub-steps at contact entry",
           "1",
           double(sub_steps_sized_for_energy ?
                    energy_refinement.entry_sub_steps :
                    parameters.entry_sub_steps),
           parameters.entry_sub_steps_automatic,
           rule});
      }
    describe_bodies();
    if (impact)
      check_contact_surface(parameters.hertz.contact_radius_max());
  }


  void
  ImpactProblem::describe_run() const
  {
    const HertzImpact &hertz = parameters.hertz;
    pcout << "impact-fem: sphere R = "
          << parameters.geometry.sphere_radius * 1e3
          << " mm, m = " << parameters.sphere_mass
          << " kg, V = " << parameters.impact_velocity << " m/s\n"
          << "  Hertz: approach " << hertz.approach_max() * 1e6 << " um, force "
          << hertz.force_max() / 1e3 << " kN, contact radius "
          << hertz.contact_radius_max() * 1e3 << " mm, contact time "
          << hertz.contact_time() * 1e6 << " us\n"
          << "  time step " << time_step() * 1e9 << " ns (" << parameters.scheme
          << ") on " << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " rank(s)" << std::endl;
  }


  double
  ImpactProblem::time_step() const
  {
    return parameters.time_step() / energy_refinement.step;
  }


  ImpactProblem::EnergyRefinement
  ImpactProblem::next_energy_refinement(std::string &reason) const
  {
    using discretisation::AutomaticDiscretisation;
    // The balance at the end of an impact: a run cut before the bodies
    // separate (Maximum time) is not judged.
    if (!step_sized_for_energy || separation_time < 0 ||
        !history.has("energy_error") || !history.has("contact_work") ||
        !history.has("kinetic_energy") || history.n_steps() == 0)
      return energy_refinement;
    // The balance's error is relative to the impact energy, the kinetic
    // energy at the start (the bodies unstrained, gravity's work zero).
    const double balance = history["energy_error"].back();
    const double activation =
      history["contact_work"].back() / history["kinetic_energy"].front();
    const EnergyRefinement next =
      AutomaticDiscretisation::next_refinement_for_energy(
        energy_refinement,
        balance,
        activation,
        spacing_sized_for_energy && mesh.contact_surface_refinements < 6,
        sub_steps_sized_for_energy);
    std::ostringstream why;
    why << std::setprecision(3) << "the energy balance ends " << balance
        << " off (target " << AutomaticDiscretisation::energy_balance_target
        << "), of which the contact activation " << activation << ": ";
    const bool denser = next.contact_spacing_halvings !=
                        energy_refinement.contact_spacing_halvings;
    if (next.step != energy_refinement.step)
      {
        why << "the automatic step is made " << next.step
            << " times finer than the rule's";
        if (next.entry_sub_steps != energy_refinement.entry_sub_steps)
          why << " (the most it is made), the steps in which the "
                 "contact's active set changes are taken as "
              << next.entry_sub_steps << " sub-steps";
        if (denser)
          why << ", the automatic contact nodes are made twice as dense";
      }
    else if (denser)
      why << "the automatic contact nodes are made twice as dense";
    else
      return next;
    why << " and the run made again";
    reason = why.str();
    return next;
  }


  double
  ImpactProblem::hard_end_time(const double) const
  {
    return parameters.end_time();
  }


  ImpactProblem::InitialMotion
  ImpactProblem::initial_motion() const
  {
    // The sphere moves down rigidly (-V e_z); before contact it is free,
    // so a = -g e_z exactly.
    const double V = parameters.impact_velocity, g = parameters.gravity;
    const double g0 = parameters.geometry.initial_gap;
    // The flight across the initial gap is a rigid motion known exactly:
    // start at the first contact, so that every time step serves the
    // contact phase.
    InitialMotion motion;
    motion.t0 =
      g0 > 0 ? (g > 0 ? (std::sqrt(V * V + 2 * g * g0) - V) / g : g0 / V) : 0.;
    motion.displacement = -g0;
    motion.speed        = V + g * motion.t0;
    motion.acceleration = -g;
    return motion;
  }


  double
  ImpactProblem::body_acceleration() const
  {
    return parameters.gravity;
  }


  double
  ImpactProblem::contact_start_time() const
  {
    return history[result_files::time_dataset].front();
  }


  void
  ImpactProblem::warn_if_not_separated() const
  {
    if (separation_time < 0)
      pcout << "Warning: the bodies did not separate before the end of the "
               "run (Time integration/Maximum time)."
            << std::endl;
  }


  void
  ImpactProblem::setup_dynamic_state()
  {
    internal_force_predictor.reinit(locally_owned_dofs, mpi_communicator);
    ghosted_v.reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);
  }


  void
  ImpactProblem::factorize_effective_stiffness()
  {
    TimerOutput::Scope t(*computing_timer, "factorize");
    assemble_effective_stiffness(time_step(), effective_stiffness);
    factorize();
  }


  void
  ImpactProblem::assemble_effective_stiffness(
    const double                    dt,
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    matrix.copy_from(system.stiffness);
    matrix.add(time_stepper->mass_weight() / (dt * dt), system.mass);
    matrix.add(time_stepper->damping_weight() / dt, system.boundary_damping);
    matrix.add(time_stepper->damping_weight() / dt, system.material_damping);
    // The Maxwell arms' algorithmic tangent (constant for a constant step).
    matrix.add(1., system.internal_stiffness);
  }


  void
  ImpactProblem::setup_entry_sub_steps()
  {
    entry_sub_steps = sub_steps_sized_for_energy ?
                        energy_refinement.entry_sub_steps :
                        parameters.entry_sub_steps;
    bool maxwell_arms =
      material_of(body_ids::sphere).internal_tangent(1).norm() > 0;
    if (!parameters.rigid_plate)
      maxwell_arms =
        maxwell_arms ||
        material_of(body_ids::plate).internal_tangent(1).norm() > 0;
    if (entry_sub_steps > 1 && maxwell_arms)
      {
        // The Maxwell arms' tangent and history force are made for one
        // step length.
        pcout << "  no sub-steps at contact entry: a body has Maxwell arms"
              << std::endl;
        entry_sub_steps = 1;
      }
    if (entry_sub_steps == 1)
      return;
    TimerOutput::Scope t(*computing_timer, "factorize");
    entry_stiffness = std::make_unique<TrilinosWrappers::SparseMatrix>();
    entry_stiffness->reinit(effective_stiffness);
    assemble_effective_stiffness(time_step() / entry_sub_steps,
                                 *entry_stiffness);
    entry_solver  = direct_solver_of(*entry_stiffness, false);
    entry_contact = contact;
    entry_contact.compute_influence(
      [this](VectorType &x, const VectorType &b) { entry_solver->solve(x, b); },
      locally_owned_dofs,
      mpi_communicator);
    pcout << "  a step in which a contact node enters is taken as "
          << entry_sub_steps << " sub-steps" << std::endl;
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
  ImpactProblem::solve_step_equation(VectorType &displacement)
  {
    VectorType rhs(locally_owned_dofs, mpi_communicator), mass_term(rhs),
      damping_term(rhs), damping_force(rhs);
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
  }


  void
  ImpactProblem::accept_step(const VectorType &displacement)
  {
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
  ImpactProblem::take_time_step()
  {
    const auto active_set_changed = [this](const Vector<double> &before) {
      bool changed = false;
      for (unsigned int j = 0; j < pressures.size(); ++j)
        changed = changed || ((pressures[j] > 0) != (before[j] > 0));
      return changed;
    };
    Vector<double> start_pressures = pressures;
    VectorType     displacement(locally_owned_dofs, mpi_communicator);
    if (entry_sub_steps == 1 || !divide_next_step)
      {
        solve_step_equation(displacement);
        if (entry_sub_steps == 1 || !active_set_changed(start_pressures))
          {
            accept_step(displacement);
            postprocess_step();
            return;
          }
        pressures = start_pressures;
      }
    // A node entered or left contact: its pressure at the end of the step,
    // times the gap it closed within the step, is work lost (or gained) by
    // the activation, trapezoidal, first order in the step. The step is
    // taken again in sub-steps, with their own factorisation and contact
    // influence swapped in for them (solve_linear_step uses the setup's).
    // So is the next step: its three-point stencil would otherwise span the
    // jump of the force, and BDF2's velocity across it gains energy.
    ++entry_steps_divided;
    divide_next_step = false;
    time_stepper->begin_sub_steps(entry_sub_steps);
    const auto swap_systems = [this]() {
      std::swap(direct_solver, entry_solver);
      std::swap(contact, entry_contact);
    };
    swap_systems();
    try
      {
        for (unsigned int i = 0; i < entry_sub_steps; ++i)
          {
            start_pressures = pressures;
            solve_step_equation(displacement);
            divide_next_step =
              divide_next_step || active_set_changed(start_pressures);
            accept_step(displacement);
            postprocess_step();
          }
      }
    catch (...)
      {
        swap_systems();
        throw;
      }
    swap_systems();
    time_stepper->end_sub_steps();
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
    // The solve again starts from the plastic force at the converged
    // displacement, now with the cells that yielded: started from the
    // predictor, it took as many iterations as the first solve.
    VectorType restart_force(rhs);
    while (result.converged && !prepare_commit())
      {
        plastic_force(displacement, restart_force);
        result = nonlinear_step.solve(restart_force,
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

    const InitialMotion motion = initial_motion();
    const double        t0     = motion.t0;
    VectorType u0(locally_owned_dofs, mpi_communicator), v0(u0), a0(u0);
    u0.equ(motion.displacement, sphere_vertical);
    first_contact_speed = motion.speed;
    v0.equ(-first_contact_speed, sphere_vertical);
    a0.equ(motion.acceleration, sphere_vertical);
    const double dt = time_step();
    time_stepper->initialize(u0, v0, a0, t0, dt);
    end_time = hard_end_time(dt);

    // The bodies start unstrained (the flight is rigid) with relaxed arms.
    initialize_internal_variables();
    internal_force_predictor = 0;
    refresh_ghosted_state();
  }


  void
  ImpactProblem::time_loop()
  {
    const std::string &directory = parameters.output_directory;
    // An interrupted run (SIGINT, SIGTERM) and a failing one keep what they
    // computed in history.incomplete.h5, and an impact the checkpoint its
    // next attempt goes on from (output/checkpoint.h). Both are also written
    // after the first step and refreshed every minute, so that even a
    // killed run leaves them behind: mpirun kills ranks that have not
    // stopped within a second of its SIGTERM, and a rank in a long step (or
    // on a loaded machine) cannot reach its next check in that time.
    // Checked before every step and once more after the last one, so that a
    // signal received at any time of the loop leaves the run incomplete.
    const auto write_checkpoint = [&]() {
      TimerOutput::Scope t(*computing_timer, "write checkpoint");
      if (resumable)
        checkpoint::write(
          directory,
          checkpoint_stamp(),
          [this](checkpoint::Writer &writer) { save_state(writer); },
          mpi_communicator);
    };
    // Between two steps: the state of the last one is kept for the run to
    // go on from.
    const auto stop_if_interrupted = [&]() {
      const int signal =
        Utilities::MPI::max(interrupt_received(), mpi_communicator);
      if (signal != 0)
        write_checkpoint();
      AssertThrow(signal == 0,
                  ExcMessage("Interrupted by signal " + std::to_string(signal) +
                             " at t = " + as_written(time_stepper->time()) +
                             " s; the history so far is in " + directory +
                             "/history.incomplete.h5" +
                             (resumable ? ", and the run made again with the "
                                          "same entries goes on from there" :
                                          "") +
                             "."));
    };
    auto last_checkpoint    = std::chrono::steady_clock::now();
    bool checkpoint_written = false;
    try
      {
        while (time_stepper->time() <
               end_time - 0.5 * time_stepper->time_step())
          {
            stop_if_interrupted();
            take_time_step();
            const bool checkpoint_due =
              !checkpoint_written ||
              Utilities::MPI::broadcast(mpi_communicator,
                                        std::chrono::steady_clock::now() -
                                            last_checkpoint >
                                          std::chrono::seconds(60),
                                        0);
            if (checkpoint_due)
              {
                write_results(false);
                write_checkpoint();
                checkpoint_written = true;
                last_checkpoint    = std::chrono::steady_clock::now();
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
  }


  double
  ImpactProblem::run_wall_time() const
  {
    return earlier_wall_time + std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - wall_start)
                                 .count();
  }


  checkpoint::Stamp
  ImpactProblem::checkpoint_stamp() const
  {
    checkpoint::Stamp stamp;
    stamp.identity                 = identity;
    stamp.step_refinement          = energy_refinement.step;
    stamp.contact_spacing_halvings = energy_refinement.contact_spacing_halvings;
    stamp.entry_sub_steps          = energy_refinement.entry_sub_steps;
    stamp.ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    stamp.dofs  = dof_handler.n_dofs();
    stamp.cells = triangulation.n_global_active_cells();
    stamp.step  = time_stepper->step_number();
    stamp.time  = time_stepper->time();
    return stamp;
  }


  void
  ImpactProblem::save_state(checkpoint::Writer &writer) const
  {
    time_stepper->save(writer);
    arms.save(writer, dof_handler);
    contact.save(writer);
    if (entry_sub_steps > 1)
      entry_contact.save(writer);
    writer &pressures;
    checkpoint::save(writer, internal_force_predictor);
    const double wall_time = run_wall_time();
    writer &first_contact_speed &divide_next_step &entry_steps_divided &end_time
      &separation_time &first_force_time &wall_time;
    history.save(writer);
    for (const auto &[name, postprocessor] : postprocessors)
      {
        std::string kind = name;
        writer     &kind;
        postprocessor->save(writer);
      }
  }


  void
  ImpactProblem::load_state(checkpoint::Reader &reader)
  {
    time_stepper->load(reader, locally_owned_dofs, mpi_communicator);
    arms.load(reader, dof_handler);
    contact.load(reader);
    if (entry_sub_steps > 1)
      entry_contact.load(reader);
    reader &pressures;
    checkpoint::load(reader,
                     internal_force_predictor,
                     locally_owned_dofs,
                     mpi_communicator);
    reader &first_contact_speed &divide_next_step &entry_steps_divided &end_time
      &separation_time &first_force_time &earlier_wall_time;
    history.load(reader);
    for (const auto &[name, postprocessor] : postprocessors)
      {
        std::string kind;
        reader     &kind;
        AssertThrow(kind == name,
                    ExcMessage("The checkpoint has the postprocessor " + kind +
                               " where the run has " + name + "."));
        postprocessor->load(reader, *this);
      }
  }


  bool
  ImpactProblem::resume_from_checkpoint()
  {
    if (!resumable)
      return false;
    checkpoint::Stamp found;
    if (!checkpoint::read(
          parameters.output_directory,
          checkpoint_stamp(),
          found,
          [this](checkpoint::Reader &reader) { load_state(reader); },
          mpi_communicator))
      return false;
    refresh_ghosted_state();
    pcout << "impact-fem: resumed from the checkpoint of step " << found.step
          << " (t = " << found.time * 1e6 << " us, " << earlier_wall_time
          << " s of wall time before) in "
          << checkpoint::directory_of(parameters.output_directory) << std::endl;
    return true;
  }


  nlohmann::json
  ImpactProblem::results(const summary::ImpactSummary &s,
                         const bool                    complete,
                         const double                  wall_time,
                         std::ostringstream           &report)
  {
    nlohmann::json result;
    result[result_files::complete_key]         = complete;
    result[result_files::summary_version_key]  = result_files::summary_version;
    result[result_files::impact_velocity_key]  = parameters.impact_velocity;
    result[result_files::contact_velocity_key] = first_contact_speed;
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
    result["steps_divided_at_contact_entry"] = entry_steps_divided;
    result["ranks"]     = Utilities::MPI::n_mpi_processes(mpi_communicator);
    result["wall_time"] = wall_time;
    return result;
  }


  void
  ImpactProblem::write_history(const nlohmann::json &result,
                               const bool            complete)
  {
    // The parameters, the derived results and their definitions travel
    // with the histories.
    std::map<std::string, std::string> text_attributes = parameter_attributes();
    text_attributes["definition: contact_time"] =
      "separation_time - first_contact_time. first_contact_time: the instant "
      "the bodies touch (the run starts there). separation_time: the zero t* "
      "of the power law F = A (t* - t)^p (A, p, t* free) fitted by weighted "
      "least squares in ln F to the falling flank of the contact phase (first "
      "run of F > 0), the samples with F <= 25 % of the peak, each weighted "
      "(1 - F / (0.25 max F))^2";
    // From the constants fitted_peak uses, so that the file states the
    // definition of the build that wrote it.
    text_attributes["definition: force_max"] =
      "vertex of the parabola fitted by least squares to the contiguous force "
      "samples around the largest one within " +
      as_written(100 * summary::peak_window_fraction) +
      " % of it (time_force_max its time; fewer than " +
      std::to_string(summary::peak_window_minimum_samples) +
      " samples there: the parabola through the largest sample and its "
      "neighbours). approach_max: vertex of the parabola through the largest "
      "approach sample and its neighbours";
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
  }


  void
  ImpactProblem::write_results(const bool complete)
  {
    const double                 wall_time = run_wall_time();
    const summary::ImpactSummary s =
      summary::summarize_impact(history[result_files::time_dataset],
                                history[result_files::contact_force_dataset],
                                history[result_files::approach_dataset],
                                history[result_files::sphere_velocity_dataset],
                                first_contact_speed,
                                parameters.gravity,
                                contact_start_time());
    std::ostringstream   report;
    const nlohmann::json result = results(s, complete, wall_time, report);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    write_history(result, complete);
    if (!complete)
      return;

    const std::string summary_file =
      parameters.output_directory + "/" + result_files::summary_file;
    {
      std::ofstream out(summary_file + ".tmp");
      out << std::setw(2) << result << std::endl;
    }
    std::filesystem::rename(summary_file + ".tmp", summary_file);

    pcout << "\nResult (" << parameters.output_directory << "):\n"
          << std::setprecision(5);
    print_result(s);
    pcout << report.str() << "  cells " << triangulation.n_global_active_cells()
          << ", dofs " << dof_handler.n_dofs() << ", steps "
          << time_stepper->step_number() << " (" << parameters.scheme
          << "), ranks " << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << ", wall time " << wall_time << " s" << std::endl;
  }


  void
  ImpactProblem::print_result(const summary::ImpactSummary &s) const
  {
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
  }


  void
  ImpactProblem::run()
  {
    // Installed before anything else: a signal during the setup is kept
    // and stops the run at the first step, leaving history.incomplete.h5.
    const InterruptHandler interrupt_handler;
    describe_run();
    start_run();
    const double dt = time_step();
    make_mesh();
    setup_system();
    setup_dynamic_state();
    assemble_system(dt);
    // Gravity on the sphere: f = -g M e_z restricted to the sphere.
    weights.body_force = weights.sphere_momentum;
    weights.body_force *= -body_acceleration();
    factorize_effective_stiffness();
    setup_contact();
    setup_entry_sub_steps();
    set_initial_conditions();
    history.declare(result_files::time_dataset,
                    result_files::time_unit,
                    "simulated time");
    if (arms.nonlinear())
      declare_iteration_history("||f_body||");
    for (auto &[name, postprocessor] : postprocessors)
      postprocessor->initialize(*this, history);
    if (!resume_from_checkpoint())
      postprocess_step();

    time_loop();
    warn_if_not_separated();
    // Decided on the first rank, so that every rank throws or none.
    std::string      reason;
    EnergyRefinement next = next_energy_refinement(reason);
    next.step = Utilities::MPI::broadcast(mpi_communicator, next.step, 0);
    next.contact_spacing_halvings =
      Utilities::MPI::broadcast(mpi_communicator,
                                next.contact_spacing_halvings,
                                0);
    next.entry_sub_steps =
      Utilities::MPI::broadcast(mpi_communicator, next.entry_sub_steps, 0);
    reason = Utilities::MPI::broadcast(mpi_communicator, reason, 0);
    // A reason is given exactly when the next run differs from this one.
    if (!reason.empty())
      {
        write_results(false);
        // The next run is another run: it starts from the first contact.
        checkpoint::remove(parameters.output_directory, mpi_communicator);
        throw TooCoarseForEnergy(reason, next);
      }
    write_results(true);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::remove(parameters.output_directory +
                              "/history.incomplete.h5");
    checkpoint::remove(parameters.output_directory, mpi_communicator);
    computing_timer->print_summary();
  }


  void
  run_impact(ParameterHandler              &prm,
             const MPI_Comm                 comm,
             std::ostream                  &log,
             std::unique_ptr<ImpactProblem> problem)
  {
    // The problem outlives each try block: its destructor (collective
    // over comm) must not run while an exception unwinds.
    ImpactProblem::EnergyRefinement refinement;
    // A run stopped in a later try goes on in that try, with its refinement.
    prm.enter_subsection("Output");
    const std::string directory = prm.get("Directory");
    prm.leave_subsection();
    checkpoint::Stamp stamp;
    if (checkpoint::read_stamp(directory, stamp, comm) &&
        stamp.identity == identity_of(prm) &&
        (stamp.step_refinement != 1 || stamp.contact_spacing_halvings != 0 ||
         stamp.entry_sub_steps != 1))
      {
        refinement.step                     = stamp.step_refinement;
        refinement.contact_spacing_halvings = stamp.contact_spacing_halvings;
        refinement.entry_sub_steps          = stamp.entry_sub_steps;
        problem.reset();
      }
    for (;;)
      {
        try
          {
            if (!problem)
              problem =
                std::make_unique<ImpactProblem>(prm, comm, log, refinement);
            problem->run();
            problem.reset();
            return;
          }
        catch (const ImpactProblem::TooCoarseForEnergy &finer)
          {
            // Each refinement is asked for once: at most three runs.
            problem.reset();
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              log << "impact-fem: " << finer.what() << "." << std::endl;
            refinement = finer.refinement();
          }
        catch (...)
          {
            problem.reset();
            throw;
          }
      }
  }
} // namespace impact_fem
