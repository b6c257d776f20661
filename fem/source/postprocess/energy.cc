#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/interface.h>
#include <impact_fem/result_files.h>

namespace impact_fem
{
  namespace postprocess
  {
    /**
     * Where the energy goes: kinetic and strain energy of both bodies (and of
     * the sphere alone), viscous dissipation, radiation through the
     * absorbing boundaries, work of gravity and of the contact forces, and
     * the balance error. The rates are integrated with the trapezoidal rule
     * over each step; for the average-acceleration rule this is its exact
     * discrete energy identity, for a dissipative scheme the balance error
     * also holds the scheme's numerical dissipation (fem/README.md).
     *
     * The mass and stiffness matrices do not couple the two bodies, so one
     * product M v (K u) gives both the total and the sphere's energy.
     */
    class Energy : public Interface
    {
    public:
      using VectorType = ImpactProblem::VectorType;

      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      initialize(const ImpactProblem &problem, History &history) override
      {
        history.declare(
          {{"kinetic_energy", "J", "kinetic energy of both bodies"},
           {"strain_energy",
            "J",
            "stored elastic energy of both bodies, including internal_energy"},
           {"internal_energy",
            "J",
            "elastic energy stored in the springs of the Maxwell arms (part of "
            "strain_energy)"},
           {"dissipated_energy",
            "J",
            "cumulative viscous and plastic dissipation in the materials"},
           {"radiated_energy",
            "J",
            "cumulative energy absorbed by the far-boundary dashpots"},
           {"gravity_work",
            "J",
            "cumulative work of the body force on the sphere"},
           {"contact_work",
            "J",
            "cumulative work of the contact forces (zero for an ideal "
            "constraint)"},
           {"energy_error",
            "1",
            "(kinetic + strain + dissipated + radiated - initial - gravity "
            "work) / initial energy"},
           {"sphere_kinetic_energy", "J", "kinetic energy of the sphere"},
           {"sphere_strain_energy", "J", "strain energy of the sphere"}});
        const auto &stepper = problem.stepper();
        product.reinit(stepper.velocity());
        masked.reinit(stepper.velocity());
        mean_velocity.reinit(stepper.velocity());
        previous_u         = stepper.displacement();
        previous_v         = stepper.velocity();
        previous_pressures = problem.contact_pressures();
        if (problem.internal_variables().nonlinear())
          history.declare("plastic_work",
                          "J",
                          "cumulative plastic work int sigma : d eps^p of both "
                          "bodies (part of dissipated_energy)");
        previous_gaps = problem.contact_conditions().weighted_gaps(previous_u);
        problem.matrices().mass.vmult(product, previous_v);
        // At first contact (an initial gap is crossed before the run
        // starts): the energy the impact has to account for.
        initial = 0.5 * (previous_v * product);
      }

      void
      execute(const ImpactProblem &problem, History &history) override
      {
        const auto &stepper = problem.stepper();
        const auto &m       = problem.matrices();
        const auto &w       = problem.functionals();
        const auto &u = stepper.displacement(), &v = stepper.velocity();
        const bool  first = stepper.step_number() == 0;

        if (!first)
          {
            // Power of the dashpots and of the viscosity, trapezoidal in v.
            const double dt = stepper.time_step();
            mean_velocity   = v;
            mean_velocity += previous_v;
            mean_velocity *= 0.5;
            m.boundary_damping.vmult(product, mean_velocity);
            radiated += dt * (mean_velocity * product);
            if (problem.scenario().has_material_damping())
              {
                m.material_damping.vmult(product, mean_velocity);
                viscous += dt * (mean_velocity * product);
              }
            masked = u;
            masked -= previous_u;
            gravity_work += w.body_force * masked;
            const auto          &contact  = problem.contact_conditions();
            const auto          &pressure = problem.contact_pressures();
            const Vector<double> gaps     = contact.weighted_gaps(u);
            for (unsigned int j = 0; j < pressure.size(); ++j)
              contact_work += 0.5 * (pressure[j] + previous_pressures[j]) *
                              (gaps[j] - previous_gaps[j]);
            previous_gaps      = gaps;
            previous_pressures = pressure;
            previous_u         = u;
            previous_v         = v;
          }

        const auto &arms = problem.internal_variables();
        m.mass.vmult(product, v);
        const double kinetic = 0.5 * (v * product);
        masked               = v;
        masked.scale(w.sphere_mask);
        const double sphere_kinetic = 0.5 * (masked * product);
        m.stiffness.vmult(product, u);
        // The long-term springs plus the springs of the Maxwell arms.
        const double arm_energy =
          arms.stored_energy(sphere) + arms.stored_energy(plate);
        // 1/2 u^T K u is the elastic energy of the total strain; a plastic
        // body stores 1/2 (eps - eps^p) : C : (eps - eps^p).
        const double strain = 0.5 * (u * product) + arm_energy +
                              arms.plastic_energy_correction(sphere) +
                              arms.plastic_energy_correction(plate);
        masked = u;
        masked.scale(w.sphere_mask);
        const double sphere_strain = 0.5 * (masked * product) +
                                     arms.stored_energy(sphere) +
                                     arms.plastic_energy_correction(sphere);
        const double dissipated =
          viscous + arms.dissipated_energy() + arms.plastic_work();
        const double balance =
          kinetic + strain + radiated + dissipated - initial - gravity_work;
        // A static press starts without energy: its balance is relative to
        // the work of the load.
        const double reference =
          initial > 0 ? initial : std::max(gravity_work, 1e-300);
        largest_error = std::max(largest_error, std::abs(balance / reference));

        history.append("kinetic_energy", kinetic);
        history.append("strain_energy", strain);
        history.append("internal_energy", arm_energy);
        history.append("dissipated_energy", dissipated);
        history.append("radiated_energy", radiated);
        history.append("gravity_work", gravity_work);
        history.append("contact_work", contact_work);
        history.append("energy_error", balance / reference);
        if (arms.nonlinear())
          history.append("plastic_work", arms.plastic_work());
        history.append("sphere_kinetic_energy", sphere_kinetic);
        history.append("sphere_strain_energy", sphere_strain);
      }

      void
      finalize(const ImpactProblem &problem,
               const History       &history,
               nlohmann::json      &summary,
               std::ostream        &report) override
      {
        const std::size_t n = history.n_steps();
        if (n == 0)
          return;
        const auto last = [&](const char *name) {
          return history[name][n - 1];
        };
        // What the sphere holds beyond its rigid motion (>= 0: the kinetic
        // energy of the centre of mass is at most the sphere's).
        const double v_cm =
          history[result_files::sphere_velocity_dataset][n - 1];
        const double rigid = 0.5 * problem.scenario().sphere_mass * v_cm * v_cm;
        const double sphere_vibration =
          last("sphere_kinetic_energy") + last("sphere_strain_energy") - rigid;
        const double plate_stored =
          last("kinetic_energy") + last("strain_energy") -
          last("sphere_kinetic_energy") - last("sphere_strain_energy");
        const double E0                               = initial;
        summary[result_files::energy_error_key]       = largest_error;
        summary[result_files::energy_error_final_key] = last("energy_error");
        summary["initial_energy"]                     = E0;
        summary["sphere_vibration_energy_fraction"]   = sphere_vibration / E0;
        summary["plate_energy_fraction"]              = plate_stored / E0;
        summary[result_files::radiated_energy_fraction_key] =
          last("radiated_energy") / E0;
        summary[result_files::dissipated_energy_fraction_key] =
          last("dissipated_energy") / E0;
        summary["internal_energy_fraction"] = last("internal_energy") / E0;
        report << "  energy: sphere vibration " << sphere_vibration / E0 * 100
               << " %, plate " << plate_stored / E0 * 100 << " %, radiated "
               << last("radiated_energy") / E0 * 100 << " %, dissipated "
               << last("dissipated_energy") / E0 * 100 << " %, balance error "
               << largest_error * 100 << " %\n";
      }

      void
      save(checkpoint::Writer &writer) const override
      {
        checkpoint::save(writer, previous_u);
        checkpoint::save(writer, previous_v);
        writer &previous_pressures &previous_gaps &initial &radiated &viscous
          &gravity_work &contact_work &largest_error;
      }

      void
      load(checkpoint::Reader &reader, const ImpactProblem &problem) override
      {
        const IndexSet &owned = problem.dofs().locally_owned_dofs();
        checkpoint::load(reader, previous_u, owned, problem.communicator());
        checkpoint::load(reader, previous_v, owned, problem.communicator());
        reader &previous_pressures &previous_gaps &initial &radiated &viscous
          &gravity_work &contact_work &largest_error;
      }

    private:
      VectorType     product, masked, mean_velocity, previous_u, previous_v;
      Vector<double> previous_pressures, previous_gaps;
      double         initial = 0, radiated = 0, viscous = 0, gravity_work = 0,
             contact_work = 0, largest_error = 0;
    };
    IMPACT_FEM_REGISTER_POSTPROCESSOR(Energy,
                                      "energy",
                                      "kinetic, strain, dissipated, radiated "
                                      "energies and the balance error")
  } // namespace postprocess
} // namespace impact_fem
