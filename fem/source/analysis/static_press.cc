// Scenario/Analysis = static press: the sphere, at rest, pressed into the
// plate by a body force.

#include <impact_fem/analysis/interface.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/result_files.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

namespace impact_fem
{
  namespace
  {
    /// Scenario/Static force [N], read and checked.
    double
    read_static_force(ParameterHandler &prm)
    {
      prm.enter_subsection(result_files::scenario_subsection);
      const double force = prm.get_double("Static force");
      prm.leave_subsection();
      std::ostringstream got;
      got << force;
      AssertThrow(force > 0,
                  ExcMessage("Scenario/Static force must be positive, got " +
                             got.str() + " N."));
      return force;
    }


    /**
     * The time loop of the impact with the sphere at rest on the plate
     * under a uniform body force of resultant Scenario/Static force: one
     * step of length time_step(), which ties every degree of freedom to
     * the ground by soft springs, is the static problem.
     */
    class StaticPress : public ImpactProblem
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection(result_files::scenario_subsection);
        prm.declare_entry("Static force",
                          "1000",
                          Patterns::Double(),
                          "Resultant of the body force pressing the sphere "
                          "in the 'static press' analysis [N], > 0.");
        prm.leave_subsection();
      }

      /// The mesh is sized for Hertz's contact under the static force.
      StaticPress(ParameterHandler &prm, const MPI_Comm comm)
        : ImpactProblem(
            prm,
            comm,
            std::cout,
            Loading{[&prm](const Parameters &parameters) {
                      return discretisation::ExpectedContact::of_static_force(
                        parameters.hertz, read_static_force(prm));
                    },
                    false,
                    &require_plate_held},
            false)
        , static_force(read_static_force(prm))
      {}

    protected:
      /**
       * One step of length dt from rest is the static problem with every
       * degree of freedom tied to the ground by a spring of stiffness
       * mass_weight / dt^2 times its mass: chosen soft (a rigid-sphere
       * compliance 1000 times the contact's) they only regularise the free
       * sphere's rigid motion, and the contact force is measured anyway.
       */
      double
      time_step() const override
      {
        const HertzImpact &hertz = parameters.hertz;
        const double       contact_compliance =
          std::pow(hertz.stiffness() * hertz.stiffness() * static_force,
                   -1. / 3.) /
          1.5;
        return std::sqrt(1e3 * contact_compliance * parameters.sphere_mass *
                         stepper().mass_weight());
      }

      /// One step.
      double
      hard_end_time(const double dt) const override
      {
        return dt;
      }

      /// At rest, touching the plate.
      InitialMotion
      initial_motion() const override
      {
        return InitialMotion();
      }

      double
      body_acceleration() const override
      {
        return static_force / parameters.sphere_mass;
      }

      /// No first contact: the bodies touch from the start.
      double
      contact_start_time() const override
      {
        return summary::nan;
      }

      void
      print_result(const summary::ImpactSummary &) const override
      {
        const std::size_t n = history.n_steps();
        pcout << "  contact force     "
              << history[result_files::contact_force_dataset][n - 1] << " N\n"
              << "  contact radius    "
              << history["contact_radius"][n - 1] * 1e3 << " mm\n"
              << "  max pressure      " << history["max_pressure"][n - 1] / 1e9
              << " GPa\n"
              << "  approach          "
              << history[result_files::approach_dataset][n - 1] * 1e6
              << " um\n";
      }

      /// The bodies are not meant to separate.
      void
      warn_if_not_separated() const override
      {}

    private:
      /// Scenario/Static force [N].
      const double static_force;
    };


    /// `Scenario/Analysis = static press`: one StaticPress.
    class StaticPressAnalysis : public analysis::Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        StaticPress::declare_parameters(prm);
      }

      void
      parse_parameters(ParameterHandler           &prm,
                       const analysis::Invocation &invocation,
                       const MPI_Comm              comm) override
      {
        analysis::require_single_run(prm, invocation, "static press", "");
        problem = std::make_unique<StaticPress>(prm, comm);
      }

      int
      run() override
      {
        problem->run();
        return 0;
      }

    private:
      std::unique_ptr<StaticPress> problem;
    };
  } // namespace

  IMPACT_FEM_REGISTER_ANALYSIS(
    StaticPressAnalysis,
    "static press",
    1,
    "the sphere, at rest, is pressed into the plate by a uniform body force "
    "of resultant 'Static force' (use with a clamped far boundary); one "
    "quasi-static solve, the Hertz check.")
} // namespace impact_fem
