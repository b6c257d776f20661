#include <impact_fem/analysis/indentation.h>
#include <impact_fem/impact_problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace impact_fem
{
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
    maximum_approach = prm.get_double("Maximum approach");
    const long n     = prm.get_integer("Steps");
    base_fixed_radially = prm.get("Base radial displacement") == "fixed";
    prm.leave_subsection();
    AssertThrow(maximum_approach > 0,
                ExcMessage("Indentation/Maximum approach must be positive, got " +
                           std::to_string(maximum_approach) + " m."));
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


  void
  ImpactProblem::setup_indentation()
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
    AssertThrow(Utilities::MPI::sum(base_dofs.n_elements(), mpi_communicator) > 0,
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
    direct_solver = std::make_unique<TrilinosWrappers::SolverDirect>(
      solver_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                     parameters.direct_solver));
    direct_solver->initialize(effective_stiffness);

    // The response to a unit approach: the base moved by -1 m in z.
    VectorType unit_load(locally_owned_dofs, mpi_communicator);
    for (const auto i : owned_base)
      unit_load[i] = -1;
    unit_load.compress(VectorOperation::insert);
    unit_approach_response.reinit(locally_owned_dofs, mpi_communicator);
    direct_solver->solve(unit_approach_response, unit_load);
  }


  void
  ImpactProblem::solve_indentation_step(const double approach,
                                        VectorType  &displacement)
  {
    // Elastic bodies: K is constant, so the equilibrium with the base at
    // -approach is u = approach u_1 + W lambda (u_1 the response to a unit
    // approach, W = K'^{-1} B^T), lambda from one complementarity problem,
    // solved exactly. A nonlinear material replaces this by Newton
    // iterations on r(u) = f_int(u) - B^T lambda with the base prescribed:
    // each iteration refactorises its tangent with the same base rows, and
    // solves the same complementarity problem for the increment (fem/
    // README.md, "Indentation").
    displacement.equ(approach, unit_approach_response);
    pressures = contact.solve_complementarity(contact.weighted_gaps(displacement));
    contact.add_contact_response(pressures, displacement);
  }


  void
  ImpactProblem::run_indentation()
  {
    setup_indentation();
    setup_contact();

    history.declare({
      {"approach", "m", "displacement of the hemisphere's base towards the plate minus the mean displacement of the plate bottom (downward positive): the interference omega"},
      {"base_displacement", "m", "prescribed downward displacement of the hemisphere's base"},
      {"contact_force", "N", "total normal contact force, 2 pi int p r dr"},
      {"contact_radius", "m", "contact radius: between the outermost loaded node and the next, where p^2 extrapolated linearly in r^2 vanishes"},
      {"max_pressure", "Pa", "largest nodal contact pressure"},
      {"penetration", "m", "largest pointwise penetration of a contact node (the constraint holds in the weighted sense)"},
      {"unloading", "1", "0 on the loading branch (and the start), 1 on the unloading branch"}});
    history.set_profile("contact_node_radius",
                        "m",
                        "radius of the contact nodes",
                        contact.node_radii());

    const std::vector<double> approaches = indentation_control.approaches();
    VectorType   displacement(locally_owned_dofs, mpi_communicator);
    double       force_max = 0, radius_at_force_max = 0, deepest = 0;
    double       residual_approach = 0, last_loaded_approach = 0;
    bool         released = false;
    std::size_t  step     = 0;
    for (; step < approaches.size() && !released; ++step)
      {
        AssertThrow(interrupt_received() == 0,
                    ExcMessage("Interrupted by signal " +
                               std::to_string(interrupt_received()) +
                               " at indentation step " + std::to_string(step) +
                               "."));
        const bool unloading = step > indentation_control.steps;
        {
          TimerOutput::Scope t(*computing_timer, "solve indentation step");
          solve_indentation_step(approaches[step], displacement);
        }
        const double force = contact.total_force(pressures);
        const double plate_displacement =
          -(weights.plate_bottom_mean * displacement);
        const double penetration = contact.penetration(displacement);
        double       max_pressure = 0;
        for (const double p : pressures)
          max_pressure = std::max(max_pressure, p);
        deepest = std::max(deepest, penetration);
        history.append("approach", approaches[step] - plate_displacement);
        history.append("base_displacement", approaches[step]);
        history.append("contact_force", force);
        history.append("contact_radius", contact.contact_radius(pressures));
        history.append("max_pressure", max_pressure);
        history.append("penetration", penetration);
        history.append("unloading", unloading ? 1. : 0.);
        if (force > force_max)
          {
            force_max           = force;
            radius_at_force_max = contact.contact_radius(pressures);
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
            released          = true;
            residual_approach = approaches[step] - plate_displacement;
          }
        else if (unloading)
          last_loaded_approach = approaches[step] - plate_displacement;
      }

    const double wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start)
        .count();
    const double R          = parameters.geometry.sphere_radius;
    const double omega      = indentation_control.maximum_approach;
    const double hertz_force =
      parameters.hertz.stiffness() * std::pow(omega, 1.5);
    nlohmann::json result;
    result["complete"]            = true;
    result["analysis"]            = "indentation";
    result["maximum_approach"]    = omega;
    result["steps"]               = indentation_control.steps;
    result["force_max"]           = force_max;
    result["contact_radius_max"]  = radius_at_force_max;
    result["residual_approach"]   = residual_approach;
    result["residual_approach_upper_bound"] = released ? last_loaded_approach : omega;
    result["released"]            = released;
    result["max_penetration"]     = deepest;
    result["hertz_force_max"]     = hertz_force;
    result["hertz_contact_radius_max"] = std::sqrt(R * omega);
    result["effective_modulus"]   = parameters.hertz.effective_modulus;
    result["cells"]               = triangulation.n_global_active_cells();
    result["dofs"]                = dof_handler.n_dofs();
    result["contact_nodes"]       = contact.n_contact_nodes();
    result["ranks"]               = Utilities::MPI::n_mpi_processes(mpi_communicator);
    result["wall_time"]           = wall_time;
    AssertThrow(released,
                ExcMessage("Internal error: the contact force did not vanish "
                           "at zero approach."));

    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::map<std::string, std::string> text_attributes = parameter_attributes();
    text_attributes["definition: residual_approach"] =
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
    pcout << "\nResult (" << directory << "):\n"
          << std::setprecision(5) << "  maximum approach  " << omega * 1e6
          << " um in " << indentation_control.steps << " steps each way\n"
          << "  peak force        " << force_max << " N (Hertz " << hertz_force
          << " N)\n"
          << "  contact radius    " << radius_at_force_max * 1e3 << " mm (Hertz "
          << std::sqrt(R * omega) * 1e3 << " mm)\n"
          << "  residual approach " << residual_approach * 1e6 << " um\n"
          << "  max penetration   " << deepest * 1e9 << " nm\n"
          << "  cells " << triangulation.n_global_active_cells() << ", dofs "
          << dof_handler.n_dofs() << ", steps " << step << ", wall time "
          << wall_time << " s" << std::endl;
  }
} // namespace impact_fem
