#include <impact_fem/time_integration/newmark.h>

#include <deal.II/base/exceptions.h>

namespace impact_fem
{
  void
  Newmark::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry("Steps per contact time",
                      "300",
                      Patterns::Double(),
                      "Time step = Hertz contact time / this number [-], "
                      ">= 10. 300 resolves the contact force to well below "
                      "0.1 %.");
    prm.declare_entry("Time step",
                      "0",
                      Patterns::Double(),
                      "Fixed time step [s], >= 0; 0 takes it from "
                      "'Steps per contact time'.");
    prm.declare_entry("Time after separation",
                      "0.1",
                      Patterns::Double(),
                      "How long the run continues after the bodies separate, "
                      "as a fraction of the contact time [-], in [0, 10]; "
                      "the rebound velocity is read at the end.");
    prm.declare_entry("Maximum time",
                      "0",
                      Patterns::Double(),
                      "Hard end of the run [s], >= 0; 0 means the time of "
                      "flight to the plate plus three Hertz contact times.");
    prm.declare_entry("Newmark beta",
                      "0.25",
                      Patterns::Double(),
                      "Newmark's beta [-], in (0, 0.5]; 0.25 with gamma = 0.5 "
                      "is the energy-conserving average-acceleration rule.");
    prm.declare_entry("Newmark gamma",
                      "0.5",
                      Patterns::Double(),
                      "Newmark's gamma [-], in [0.5, 1]; > 0.5 adds numerical "
                      "damping (first order).");
    prm.leave_subsection();
  }


  void
  Newmark::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    steps_per_contact_time = prm.get_double("Steps per contact time");
    prescribed_time_step   = prm.get_double("Time step");
    time_after_separation  = prm.get_double("Time after separation");
    maximum_time           = prm.get_double("Maximum time");
    beta                   = prm.get_double("Newmark beta");
    gamma                  = prm.get_double("Newmark gamma");
    prm.leave_subsection();

    AssertThrow(steps_per_contact_time >= 10,
                ExcMessage("Time integration/Steps per contact time must be "
                           "at least 10, got " +
                           std::to_string(steps_per_contact_time) + "."));
    AssertThrow(prescribed_time_step >= 0,
                ExcMessage("Time integration/Time step must not be negative."));
    AssertThrow(time_after_separation >= 0 && time_after_separation <= 10,
                ExcMessage("Time integration/Time after separation must lie "
                           "in [0, 10]."));
    AssertThrow(maximum_time >= 0,
                ExcMessage("Time integration/Maximum time must not be "
                           "negative."));
    AssertThrow(gamma >= 0.5 && gamma <= 1,
                ExcMessage("Time integration/Newmark gamma must lie in "
                           "[0.5, 1] for stability."));
    AssertThrow(beta >= 0.25 * (gamma + 0.5) * (gamma + 0.5) - 1e-12 &&
                  beta <= 0.5,
                ExcMessage("Time integration/Newmark beta must lie in "
                           "[(gamma + 1/2)^2 / 4, 1/2] for unconditional "
                           "stability."));
  }


  void
  Newmark::set_time_step(const double hertz_contact_time)
  {
    time_step = prescribed_time_step > 0 ?
                  prescribed_time_step :
                  hertz_contact_time / steps_per_contact_time;
    const double dt = time_step;
    c_M             = 1 / (beta * dt * dt);
    c_C             = gamma / (beta * dt);
    c_v             = 1 / (beta * dt);
    c_a             = 1 / (2 * beta) - 1;
    d_v             = gamma / beta - 1;
    d_a             = dt / 2 * (gamma / beta - 2);
  }
} // namespace impact_fem
