#include <impact_fem/as_written.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/interface.h>

#include <iomanip>

namespace impact_fem
{
  namespace postprocess
  {
    /**
     * The progress line on the first rank: time, step, force, contact
     * radius and the remaining wall time. On a terminal it is redrawn in
     * place, at most every tenth of a second; in a log a new line follows
     * every 'Output/Progress interval'; the last step always ends a line.
     */
    class Progress : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Output");
        prm.declare_entry("Progress interval",
                          "1",
                          Patterns::Double(),
                          "Wall time between progress lines in a log [s], "
                          ">= 0; 0 prints every step.");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Output");
        interval = prm.get_double("Progress interval");
        prm.leave_subsection();
        AssertThrow(interval >= 0,
                    ExcMessage("Output/Progress interval must not be negative, "
                               "got " +
                               as_written(interval) + " s."));
      }

      void
      initialize(const ImpactProblem &problem, History &) override
      {
        start_time = problem.stepper().time();
        last       = problem.start_of_run();
      }

      void
      execute(const ImpactProblem &problem, History &) override
      {
        const auto  &stepper = problem.stepper();
        const double time    = stepper.time();
        const bool   done =
          time >= problem.expected_end_time() - 0.5 * stepper.time_step();
        const bool   terminal = problem.console_is_terminal();
        const auto   now      = std::chrono::steady_clock::now();
        const double since_last =
          std::chrono::duration<double>(now - last).count();
        if (!done && since_last < (terminal ? 0.1 : interval))
          return;
        last = now;

        const double elapsed =
          std::chrono::duration<double>(now - problem.start_of_run()).count();
        const double remaining =
          time > start_time ?
            elapsed * std::max(0., problem.expected_end_time() - time) /
              (time - start_time) :
            0;
        const auto &out = problem.console();
        if (terminal)
          out << '\r';
        out << "  t = " << std::setw(8) << std::fixed << std::setprecision(2)
            << time * 1e6 << " us  step " << std::setw(5)
            << stepper.step_number() << "  force " << std::setw(8)
            << std::setprecision(4)
            << problem.contact_conditions().total_force(
                 problem.contact_pressures()) /
                 1e3
            << " kN  contact radius " << std::setw(6)
            << problem.contact_conditions().contact_radius(
                 problem.contact_pressures()) *
                 1e3
            << " mm  remaining " << std::setprecision(0) << remaining << " s "
            << std::defaultfloat << std::setprecision(6);
        if (!terminal || done)
          out << std::endl;
        else
          out << std::flush;
      }

      /// Progress lines carry nothing into the results.
      void
      save(checkpoint::Writer &) const override
      {}

      /// The rate of the estimate of the remaining time starts anew.
      void
      load(checkpoint::Reader &, const ImpactProblem &problem) override
      {
        start_time = problem.stepper().time();
        last       = std::chrono::steady_clock::now();
      }

    private:
      double                                interval = 1, start_time = 0;
      std::chrono::steady_clock::time_point last;
    };
    IMPACT_FEM_REGISTER_POSTPROCESSOR(
      Progress,
      "progress",
      "progress line with the remaining wall time")
  } // namespace postprocess
} // namespace impact_fem
