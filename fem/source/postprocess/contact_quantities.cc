#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/interface.h>
#include <impact_fem/result_files.h>

namespace impact_fem
{
  namespace postprocess
  {
    /**
     * The quantities of the contact and of the bodies' motion that the
     * reduced models speak of: contact force, approach (the "x" of the
     * reduced models), contact radius, pressures, penetration; and the
     * pressure profile at the largest force.
     */
    class ContactQuantities : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      initialize(const ImpactProblem &problem, History &history) override
      {
        history.declare(
          {{result_files::contact_force_dataset,
            result_files::contact_force_unit,
            "total normal contact force, 2 pi int p r dr"},
           {"sphere_displacement",
            "m",
            "centre-of-mass displacement of the sphere, downward positive"},
           {result_files::sphere_velocity_dataset,
            result_files::sphere_velocity_unit,
            "centre-of-mass velocity of the sphere, downward positive"},
           {"plate_displacement",
            "m",
            "mean vertical displacement of the plate bottom, downward "
            "positive"},
           {"plate_momentum",
            "kg m/s",
            "axial momentum of the plate, int rho v_z dV, downward positive "
            "(the sphere's is sphere_velocity times its mass)"},
           {result_files::approach_dataset,
            result_files::approach_unit,
            "sphere_displacement - initial gap - plate_displacement"},
           {"contact_radius",
            "m",
            "contact radius: between the outermost loaded node and the next, "
            "where p^2 extrapolated linearly in r^2 vanishes"},
           {"max_pressure", "Pa", "largest nodal contact pressure"},
           {"penetration",
            "m",
            "largest pointwise penetration of a contact node (the constraint "
            "holds in the weighted sense)"}});
        history.set_profile("contact_node_radius",
                            "m",
                            "radius of the contact nodes (vertices of the "
                            "plate's contact surface)",
                            problem.contact_conditions().node_radii());
      }

      void
      execute(const ImpactProblem &problem, History &history) override
      {
        const auto  &contact   = problem.contact_conditions();
        const auto  &pressures = problem.contact_pressures();
        const auto  &w         = problem.functionals();
        const auto  &stepper   = problem.stepper();
        const double mass      = problem.scenario().sphere_mass;
        const double force     = contact.total_force(pressures);
        // Centre-of-mass motion of the sphere and mean motion of the plate
        // bottom, downward positive.
        const double sphere_displacement =
          -(w.sphere_momentum * stepper.displacement()) / mass;
        const double sphere_velocity =
          -(w.sphere_momentum * stepper.velocity()) / mass;
        const double plate_displacement =
          -(w.plate_bottom_mean * stepper.displacement());
        double max_pressure = 0;
        for (const double p : pressures)
          max_pressure = std::max(max_pressure, p);
        const double deepest = contact.penetration(stepper.displacement());
        penetration          = std::max(penetration, deepest);

        history.append(result_files::contact_force_dataset, force);
        history.append("sphere_displacement", sphere_displacement);
        history.append(result_files::sphere_velocity_dataset, sphere_velocity);
        history.append("plate_displacement", plate_displacement);
        history.append("plate_momentum",
                       -(w.plate_momentum * stepper.velocity()));
        history.append(result_files::approach_dataset,
                       sphere_displacement -
                         problem.scenario().geometry.initial_gap -
                         plate_displacement);
        history.append("contact_radius", contact.contact_radius(pressures));
        history.append("max_pressure", max_pressure);
        history.append("penetration", deepest);
        if (force > largest_force)
          {
            largest_force = force;
            history.set_profile("pressure_at_force_max",
                                "Pa",
                                "contact pressure at the contact nodes at the "
                                "time of the largest contact force",
                                std::vector<double>(pressures.begin(),
                                                    pressures.end()));
          }
      }

      void
      finalize(const ImpactProblem &,
               const History &,
               nlohmann::json &summary,
               std::ostream   &report) override
      {
        summary["max_penetration"] = penetration;
        report << "  max penetration   " << penetration * 1e9 << " nm\n";
      }

      void
      save(checkpoint::Writer &writer) const override
      {
        writer &largest_force &penetration;
      }

      void
      load(checkpoint::Reader &reader, const ImpactProblem &) override
      {
        reader &largest_force &penetration;
      }

    private:
      double largest_force = -1;
      double penetration   = 0;
    };
    IMPACT_FEM_REGISTER_POSTPROCESSOR(
      ContactQuantities,
      "contact",
      "contact force, approach, contact radius, "
      "pressures, penetration")
  } // namespace postprocess
} // namespace impact_fem
