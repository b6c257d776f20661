#include <impact_fem/as_written.h>
#include <impact_fem/time_integration/interface.h>

namespace impact_fem
{
  namespace time_integration
  {
    /**
     * Newmark's method: u_{n+1} = u_n + dt v_n + dt^2 ((1/2 - beta) a_n +
     * beta a_{n+1}), v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}).
     * (beta, gamma) = (1/4, 1/2), the average-acceleration rule, is second
     * order and free of numerical dissipation: its discrete energy balance is
     * exact for the linear part. That is also its weakness here: a mode that
     * relaxes much faster than the step (the inertia of a mesh mode against
     * Kelvin-Voigt viscosity, rate c/m >> 1/dt) is mapped to an amplification
     * factor near -1 and alternates from step to step for the whole contact
     * (fem/README.md, "Time integration"). gamma > 1/2 damps it, at first
     * order accuracy.
     */
    class Newmark : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Newmark beta",
                          "0.25",
                          Patterns::Double(),
                          "Newmark's beta [-] (Scheme = newmark), in "
                          "[(gamma + 1/2)^2 / 4, 1/2]; 0.25 with gamma = 0.5 "
                          "is the energy-conserving average-acceleration "
                          "rule.");
        prm.declare_entry("Newmark gamma",
                          "0.5",
                          Patterns::Double(),
                          "Newmark's gamma [-] (Scheme = newmark), in [0.5, "
                          "1]; > 0.5 adds numerical damping (first order).");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        beta  = prm.get_double("Newmark beta");
        gamma = prm.get_double("Newmark gamma");
        AssertThrow(gamma >= 0.5 && gamma <= 1,
                    ExcMessage("Time integration/Newmark gamma must lie in "
                               "[0.5, 1] for stability, got " +
                               as_written(gamma) + "."));
        AssertThrow(beta >= 0.25 * (gamma + 0.5) * (gamma + 0.5) - 1e-12 &&
                      beta <= 0.5,
                    ExcMessage("Time integration/Newmark beta must lie in "
                               "[(gamma + 1/2)^2 / 4, 1/2] for unconditional "
                               "stability, got " +
                               as_written(beta) + "."));
      }

      double
      mass_weight() const override
      {
        return 1 / beta;
      }

      double
      damping_weight() const override
      {
        return gamma / beta;
      }

      void
      history_terms(VectorType &mass_term,
                    VectorType &damping_term) const override
      {
        // M (c_M u + c_v v + c_a a) + C (c_C u + d_v v + d_a a)
        mass_term.equ(1 / (beta * dt * dt), u);
        mass_term.add(1 / (beta * dt), v, 1 / (2 * beta) - 1, a);
        damping_term.equ(gamma / (beta * dt), u);
        damping_term.add(gamma / beta - 1, v, dt / 2 * (gamma / beta - 2), a);
      }

    protected:
      void
      update(const VectorType &new_displacement) override
      {
        // a_{n+1} = (u_{n+1} - u_n - dt v_n) / (beta dt^2) - (1/(2 beta) - 1) a_n
        VectorType new_acceleration(new_displacement);
        new_acceleration -= u;
        new_acceleration *= 1 / (beta * dt * dt);
        new_acceleration.add(-1 / (beta * dt), v, -(1 / (2 * beta) - 1), a);
        v.add(dt * (1 - gamma), a, dt * gamma, new_acceleration);
        a = new_acceleration;
        u = new_displacement;
      }

    private:
      double beta  = 0.25;
      double gamma = 0.5;
    };
    IMPACT_FEM_REGISTER_TIME_STEPPER(
      Newmark,
      "newmark",
      "Newmark's method with 'Newmark beta' and 'Newmark gamma' (default: the "
      "average-acceleration rule, no numerical dissipation; its step-to-step "
      "force oscillation with Kelvin-Voigt bodies is fem/README.md's example)")
  } // namespace time_integration
} // namespace impact_fem
