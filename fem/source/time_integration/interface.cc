#include <impact_fem/time_integration/interface.h>

namespace impact_fem
{
  namespace time_integration
  {
    namespace
    {
      using Kinds = Registry<Interface>;
    }


    void
    Interface::initialize(const VectorType &u0,
                          const VectorType &v0,
                          const VectorType &a0,
                          const double      t0,
                          const double      time_step)
    {
      u    = u0;
      v    = v0;
      a    = a0;
      t    = t0;
      dt   = time_step;
      step = 0;
      start();
    }


    void
    Interface::advance(const VectorType &new_displacement)
    {
      update(new_displacement);
      t += dt;
      ++step;
    }


    void
    Interface::save(checkpoint::Writer &writer) const
    {
      checkpoint::save(writer, u);
      checkpoint::save(writer, v);
      checkpoint::save(writer, a);
      writer &dt &t &step;
      save_past(writer);
    }


    void
    Interface::load(checkpoint::Reader &reader,
                    const IndexSet     &owned,
                    const MPI_Comm      comm)
    {
      checkpoint::load(reader, u, owned, comm);
      checkpoint::load(reader, v, owned, comm);
      checkpoint::load(reader, a, owned, comm);
      reader &dt &t &step;
      load_past(reader, owned, comm);
    }


    void
    Interface::begin_sub_steps(const unsigned int n)
    {
      Assert(n >= 1, ExcMessage("at least one sub-step"));
      u_start   = u;
      v_start   = v;
      t_start   = t;
      full_step = dt;
      dt        = full_step / n;
      past_for_sub_steps(full_step);
    }


    void
    Interface::end_sub_steps()
    {
      dt = full_step;
      // The end of the step exactly, not t_start plus n rounded sub-steps.
      t = t_start + full_step;
      past_after_sub_steps(u_start, v_start);
    }


    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      prm.declare_entry("Scheme",
                        "bdf2",
                        Patterns::Selection(Kinds::selection()),
                        "Time integration of the equations of motion. Known "
                        "schemes:" +
                          Kinds::descriptions());
      for (const auto &kind : Kinds::all())
        kind.second.declare_parameters(prm);
      prm.leave_subsection();
    }


    std::unique_ptr<Interface>
    create_time_stepper(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      std::unique_ptr<Interface> stepper =
        Kinds::get(prm.get("Scheme")).create();
      stepper->parse_parameters(prm);
      prm.leave_subsection();
      return stepper;
    }
  } // namespace time_integration
} // namespace impact_fem
