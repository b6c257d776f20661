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
