#ifndef IMPACT_FEM_TIME_INTEGRATION_INTERFACE_H
#define IMPACT_FEM_TIME_INTEGRATION_INTERFACE_H

#include <impact_fem/output/checkpoint.h>
#include <impact_fem/registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

namespace impact_fem
{
  namespace time_integration
  {
    using namespace dealii;
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * A scheme of constant step for M a + C v + K u = f whose equation holds
     * at the end of the step, written for the displacement u_{n+1}:
     *   (K + mass_coefficient() M + damping_coefficient() C) u_{n+1}
     *       = f_{n+1} + M m_n + C c_n,
     * with m_n, c_n from the past (history_terms). The effective matrix is
     * constant for a constant step, so it is factorised once per run; the
     * contact multipliers and the Maxwell arms' forces are evaluated at the
     * end of the step like f_{n+1}. The scheme owns the state (u, v, a), the
     * time and the step count.
     *
     * A new scheme is one new file: a class derived from Interface with a
     * static declare_parameters(ParameterHandler &) (entries inside the
     * subsection "Time integration") and IMPACT_FEM_REGISTER_TIME_STEPPER.
     */
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /// Read the scheme's entries (the handler is inside "Time integration").
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;

      /// kappa in mass_coefficient() = kappa / dt^2 [-].
      virtual double
      mass_weight() const = 0;

      /// delta in damping_coefficient() = delta / dt [-].
      virtual double
      damping_weight() const = 0;

      /**
       * Start at time @p t0 with the step @p dt from the state (u0, v0, a0)
       * reached by a free flight of constant acceleration a0 (the bodies
       * unstrained, the plate at rest): multistep schemes take their past
       * from that flight, exactly.
       */
      void
      initialize(const VectorType &u0,
                 const VectorType &v0,
                 const VectorType &a0,
                 const double      t0,
                 const double      dt);

      /// m_n and c_n of the right-hand side (see the class documentation).
      virtual void
      history_terms(VectorType &mass_term, VectorType &damping_term) const = 0;

      /// Accept u_{n+1}: the velocity and acceleration follow, time advances.
      void
      advance(const VectorType &new_displacement);

      /**
       * Take the next step of length dt as @p n sub-steps of dt / n (n >= 1):
       * the step becomes dt / n and the scheme's past is rebuilt for it from
       * the state at the start (a multistep scheme's values at t - dt / n,
       * interpolated to third order in dt / n from its past at t - dt). The
       * caller takes n steps with the effective matrix of dt / n, then calls
       * end_sub_steps().
       */
      void
      begin_sub_steps(const unsigned int n);

      /// Back to the step dt at the time reached by the n sub-steps, the
      /// scheme's past the exact state at the start of the sub-steps.
      void
      end_sub_steps();

      /// The state (u, v, a), the time, the step and the scheme's past at
      /// the end of a step (not within sub-steps), for a checkpoint.
      void
      save(checkpoint::Writer &writer) const;

      /// Reads what save() wrote, the vectors made with the locally owned
      /// entries @p owned on @p comm.
      void
      load(checkpoint::Reader &reader,
           const IndexSet     &owned,
           const MPI_Comm      comm);

      double
      mass_coefficient() const
      {
        return mass_weight() / (dt * dt);
      }

      double
      damping_coefficient() const
      {
        return damping_weight() / dt;
      }

      const VectorType &
      displacement() const
      {
        return u;
      }
      const VectorType &
      velocity() const
      {
        return v;
      }
      const VectorType &
      acceleration() const
      {
        return a;
      }
      double
      time() const
      {
        return t;
      }
      double
      time_step() const
      {
        return dt;
      }
      unsigned int
      step_number() const
      {
        return step;
      }

    protected:
      /// Build whatever past the scheme needs from the initial free flight.
      virtual void
      start()
      {}

      /// Set u, v, a (and the scheme's past) to the end of the step.
      virtual void
      update(const VectorType &new_displacement) = 0;

      /// The scheme's past (beyond u, v, a) for a checkpoint, and back
      /// (vectors made with @p owned on @p comm); a scheme whose past is
      /// the state alone has nothing to add.
      virtual void
      save_past(checkpoint::Writer &) const
      {}
      virtual void
      load_past(checkpoint::Reader &, const IndexSet &, const MPI_Comm)
      {}

      /// The past rebuilt for sub-steps dt, the state (u, v, a) at t
      /// unchanged and the past made for the step @p full_dt.
      virtual void
      past_for_sub_steps(const double /*full_dt*/)
      {}

      /// The past after the sub-steps, the step dt again: @p u_start and
      /// @p v_start are the state at t - dt (the start of the sub-steps).
      virtual void
      past_after_sub_steps(const VectorType & /*u_start*/,
                           const VectorType & /*v_start*/)
      {}

      VectorType   u, v, a;
      double       dt   = 0;
      double       t    = 0;
      unsigned int step = 0;

    private:
      // The state at the start of the sub-steps and the step they divide.
      VectorType u_start, v_start;
      double     t_start = 0, full_step = 0;
    };


    /// "Scheme" and every scheme's entries, inside "Time integration".
    void
    declare_parameters(ParameterHandler &prm);

    /// The scheme chosen by "Time integration/Scheme", its entries parsed.
    std::unique_ptr<Interface>
    create_time_stepper(ParameterHandler &prm);
  } // namespace time_integration
} // namespace impact_fem

/// Register a scheme under a name usable in "Time integration/Scheme".
#define IMPACT_FEM_REGISTER_TIME_STEPPER(classname, name, description) \
  IMPACT_FEM_REGISTER(impact_fem::time_integration::Interface,         \
                      classname,                                       \
                      name,                                            \
                      description)

#endif
