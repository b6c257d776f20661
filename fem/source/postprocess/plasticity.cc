#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/interface.h>

#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <limits>

namespace impact_fem
{
  namespace postprocess
  {
    /**
     * What an elastic-plastic impact leaves behind (nothing for linear
     * bodies): the plastic work, the largest accumulated plastic strain,
     * the start of yielding, the permanent approach and the dent.
     *
     * Definitions (also written into history.h5):
     * - yield onset: the first step after which a quadrature point has
     *   yielded; the sphere's velocity v then, and sqrt(V^2 - v^2) (V the
     *   velocity at first contact), the impact velocity whose whole kinetic
     *   energy equals the energy the sphere had given up when yielding
     *   started: the velocity at which an impact would just reach yield if
     *   that energy were all stored elastically (it neglects the waves
     *   radiated until then).
     * - permanent approach: the approach at the separation time (force back
     *   to zero after the peak, summary's separation_time), linearly
     *   interpolated: for an elastic impact it is 0, for a plastic one the
     *   depth of the dent plus the sphere's flattening.
     * - dent radius (plate; sphere_dent_radius likewise): the largest radius
     *   of a yielded quadrature point in the layer of cells along the
     *   body's contact surface at the end of the run, i.e. where the plastic
     *   zone meets the surface; 0 while the plastic zone stays buried below
     *   the surface (the first yield of a Hertz contact is subsurface).
     */
    class Plasticity : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      initialize(const ImpactProblem &problem, History &history) override
      {
        active = problem.internal_variables().nonlinear();
        if (active)
          history.declare("max_accumulated_plastic_strain",
                          "1",
                          "largest accumulated plastic strain of both bodies");
      }

      void
      execute(const ImpactProblem &problem, History &history) override
      {
        if (!active)
          return;
        const auto  &states = problem.internal_variables();
        const double largest =
          std::max(states.max_accumulated_plastic_strain(sphere),
                   states.max_accumulated_plastic_strain(plate));
        history.append("max_accumulated_plastic_strain", largest);
        if (largest > 0 && onset_time < 0)
          {
            onset_time            = problem.stepper().time();
            onset_sphere_velocity = history["sphere_velocity"].back();
          }
      }

      void
      finalize(const ImpactProblem &problem,
               const History       &history,
               nlohmann::json      &summary,
               std::ostream        &report) override
      {
        if (!active)
          return;
        const auto  &states = problem.internal_variables();
        const double V      = problem.contact_velocity();
        const auto   number = [](const double x) {
          return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
        };
        summary["plastic_work"] = states.plastic_work();
        summary["plastic_work_fraction"] =
          states.plastic_work() /
          (0.5 * problem.scenario().sphere_mass * V * V);
        summary["max_accumulated_plastic_strain_sphere"] =
          states.max_accumulated_plastic_strain(sphere);
        // A rigid flat is no body: its keys are null, not a plate that
        // stayed elastic.
        const bool rigid_flat = problem.scenario().rigid_plate;
        summary["max_accumulated_plastic_strain_plate"] =
          rigid_flat ?
            nlohmann::json(nullptr) :
            nlohmann::json(states.max_accumulated_plastic_strain(plate));
        summary["max_accumulated_plastic_strain"] =
          std::max(states.max_accumulated_plastic_strain(sphere),
                   states.max_accumulated_plastic_strain(plate));
        const double nan = std::numeric_limits<double>::quiet_NaN();
        summary["yield_onset_time"] =
          number(onset_time >= 0 ? onset_time : nan);
        summary["yield_onset_sphere_velocity"] =
          number(onset_time >= 0 ? onset_sphere_velocity : nan);
        summary["yield_onset_velocity"] = number(
          onset_time >= 0 ? std::sqrt(std::max(V * V - onset_sphere_velocity *
                                                         onset_sphere_velocity,
                                               0.)) :
                            nan);

        // Permanent approach: the approach at the separation time.
        double permanent = nan;
        if (summary.contains("separation_time") &&
            summary["separation_time"].is_number())
          {
            const double ts = summary["separation_time"].get<double>();
            const auto  &t  = history["time"];
            const auto  &a  = history["approach"];
            for (std::size_t i = 1; i < t.size(); ++i)
              if (t[i - 1] <= ts && ts <= t[i])
                {
                  const double w = (ts - t[i - 1]) / (t[i] - t[i - 1]);
                  permanent      = (1 - w) * a[i - 1] + w * a[i];
                  break;
                }
          }
        summary["permanent_approach"] = number(permanent);

        const double plate_dent =
          dent_radius(problem, boundary_ids::plate_contact);
        const double sphere_dent =
          dent_radius(problem, boundary_ids::sphere_contact);
        summary["dent_radius"] =
          rigid_flat ? nlohmann::json(nullptr) : nlohmann::json(plate_dent);
        summary["sphere_dent_radius"] = sphere_dent;
        report << "  plasticity: plastic work "
               << summary["plastic_work_fraction"].get<double>() * 100
               << " % of the impact energy, max accumulated plastic strain "
               << summary["max_accumulated_plastic_strain"].get<double>()
               << ", permanent approach " << permanent * 1e6
               << " um, dent radius ";
        if (rigid_flat)
          report << "(rigid flat) sphere " << sphere_dent * 1e3 << " mm";
        else
          report << plate_dent * 1e3 << " mm (sphere " << sphere_dent * 1e3
                 << " mm)";
        report << ", yield from " << (onset_time >= 0 ? onset_time * 1e6 : nan)
               << " us, at an impact-equivalent velocity "
               << summary["yield_onset_velocity"] << " m/s\n";
      }

      void
      save(checkpoint::Writer &writer) const override
      {
        writer &active &onset_time &onset_sphere_velocity;
      }

      void
      load(checkpoint::Reader &reader, const ImpactProblem &) override
      {
        reader &active &onset_time &onset_sphere_velocity;
      }

    private:
      /// Largest radius of a yielded quadrature point in the cells along
      /// the boundary @p surface, all ranks [m].
      static double
      dent_radius(const ImpactProblem     &problem,
                  const types::boundary_id surface)
      {
        const auto &states = problem.internal_variables();
        FEValues<2> fe_values(problem.geometric_mapping(),
                              problem.dofs().get_fe(),
                              problem.cell_quadrature(),
                              update_quadrature_points);
        double      radius = 0;
        for (const auto &cell : problem.dofs().active_cell_iterators())
          if (cell->is_locally_owned() && cell->at_boundary())
            {
              bool on_surface = false;
              for (const auto f : cell->face_indices())
                on_surface |= cell->face(f)->at_boundary() &&
                              cell->face(f)->boundary_id() == surface;
              const auto point_states = states.states(cell);
              if (!on_surface || point_states.empty())
                continue;
              fe_values.reinit(cell);
              for (unsigned int q = 0; q < point_states.size(); ++q)
                if (point_states[q]->accumulated_plastic_strain > 0)
                  radius = std::max(radius, fe_values.quadrature_point(q)[0]);
            }
        return Utilities::MPI::max(radius, problem.communicator());
      }

      bool   active                = false;
      double onset_time            = -1;
      double onset_sphere_velocity = 0;
    };
    IMPACT_FEM_REGISTER_POSTPROCESSOR(
      Plasticity,
      "plasticity",
      "plastic work, largest accumulated plastic "
      "strain, yield onset, permanent approach, "
      "dent radius")
  } // namespace postprocess
} // namespace impact_fem
