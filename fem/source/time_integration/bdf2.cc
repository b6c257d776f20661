#include <impact_fem/time_integration/interface.h>

namespace impact_fem
{
  namespace time_integration
  {
    /**
     * The second-order backward differentiation formula applied to
     * displacement and velocity:
     *   v_{n+1} = (3 u_{n+1} - 4 u_n + u_{n-1}) / (2 dt),
     *   a_{n+1} = (3 v_{n+1} - 4 v_n + v_{n-1}) / (2 dt).
     * L-stable: a mode that relaxes much faster than the step is damped in
     * one step instead of alternating (Newmark's average-acceleration rule
     * maps it to -1), and a mode of frequency omega loses amplitude only at
     * fourth order in omega dt per step (for the contact mode, omega dt =
     * pi / 300 by default: 1e-8 per step). The past of the first step is the
     * free flight before it, u_{-1} = u_0 - dt v_0 + dt^2 / 2 a_0,
     * v_{-1} = v_0 - dt a_0: exact, no starting step.
     */
    class BDF2 : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      parse_parameters(ParameterHandler &) override
      {}

      double
      mass_weight() const override
      {
        return 9. / 4.;
      }

      double
      damping_weight() const override
      {
        return 3. / 2.;
      }

      void
      history_terms(VectorType &mass_term,
                    VectorType &damping_term) const override
      {
        // v_{n+1} = 3/(2dt) u_{n+1} - w,   w = (4 u_n - u_{n-1}) / (2 dt)
        // a_{n+1} = 3/(2dt) v_{n+1} - q,   q = (4 v_n - v_{n-1}) / (2 dt)
        // M a_{n+1} + C v_{n+1} = (9/(4 dt^2) M + 3/(2 dt) C) u_{n+1}
        //                         - M (3/(2 dt) w + q) - C w
        VectorType w(u), q(v);
        past_terms(w, q);
        mass_term.equ(1.5 / dt, w);
        mass_term += q;
        damping_term = w;
      }

    protected:
      void
      start() override
      {
        previous_u = u;
        previous_u.add(-dt, v, 0.5 * dt * dt, a);
        previous_v = v;
        previous_v.add(-dt, a);
      }

      void
      update(const VectorType &new_displacement) override
      {
        VectorType w(u), q(v);
        past_terms(w, q);
        previous_u = u;
        previous_v = v;
        u          = new_displacement;
        v.equ(1.5 / dt, u);
        v -= w;
        a.equ(1.5 / dt, v);
        a -= q;
      }

      void
      past_for_sub_steps(const double full_dt) override
      {
        // The quadratic through u_{n-1} (at t - full_dt) with value u_n and
        // slope v_n at t, evaluated at t - dt; the same for v with slope a_n:
        //   u(t - s) = u_n - s v_n + (s / H)^2 (u_{n-1} - u_n + H v_n).
        // Its error, O(dt^2 H) in u, is O(dt H) in the first sub-step's
        // velocity and acceleration: second order, like the scheme.
        const double ratio = dt / full_dt;
        VectorType   correction(previous_u);
        correction -= u;
        correction.add(full_dt, v);
        previous_u = u;
        previous_u.add(-dt, v, ratio * ratio, correction);
        correction = previous_v;
        correction -= v;
        correction.add(full_dt, a);
        previous_v = v;
        previous_v.add(-dt, a, ratio * ratio, correction);
      }

      void
      save_past(checkpoint::Writer &writer) const override
      {
        checkpoint::save(writer, previous_u);
        checkpoint::save(writer, previous_v);
      }

      void
      load_past(checkpoint::Reader &reader,
                const IndexSet     &owned,
                const MPI_Comm      comm) override
      {
        checkpoint::load(reader, previous_u, owned, comm);
        checkpoint::load(reader, previous_v, owned, comm);
      }

      void
      past_after_sub_steps(const VectorType &u_start,
                           const VectorType &v_start) override
      {
        previous_u = u_start;
        previous_v = v_start;
      }

    private:
      // w = (4 u_n - u_{n-1}) / (2 dt), q = (4 v_n - v_{n-1}) / (2 dt).
      void
      past_terms(VectorType &w, VectorType &q) const
      {
        w.sadd(2 / dt, -0.5 / dt, previous_u);
        q.sadd(2 / dt, -0.5 / dt, previous_v);
      }

      VectorType previous_u, previous_v;
    };
    IMPACT_FEM_REGISTER_TIME_STEPPER(
      BDF2,
      "bdf2",
      "second-order backward differentiation (L-stable: damps the modes that "
      "relax faster than the step, e.g. Kelvin-Voigt mesh modes, in one step)")
  } // namespace time_integration
} // namespace impact_fem
