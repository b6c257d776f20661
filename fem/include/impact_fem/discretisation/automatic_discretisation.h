#ifndef IMPACT_FEM_DISCRETISATION_AUTOMATIC_DISCRETISATION_H
#define IMPACT_FEM_DISCRETISATION_AUTOMATIC_DISCRETISATION_H

#include <deal.II/base/parameter_handler.h>

#include <impact_fem/discretisation/expected_contact.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace impact_fem
{
  namespace discretisation
  {
    using namespace dealii;

    /**
     * The mesh and the time step of a run sized from its expected contact:
     * the entries Mesh/Contact element size, Uniform zone radius, Contact
     * surface radius and Time integration/Steps per contact time take the
     * value "auto" (their default) or a number, which wins.
     *
     * The rule, with a the expected contact radius and t_c the expected
     * contact time (expected_contact.h): contact elements a / 20 (a / 30
     * when a body is expected to yield), a uniform zone of 1.5 a and a
     * contact surface of 2.5 a (at most R/2, the largest the mesh allows),
     * the contact surfaces' cells refined three times more when a body is
     * expected to yield (contact nodes every a / 240),
     * 300 time steps per expected contact time, raised when the run's contact
     * activation loses more energy than the energy balance allows
     * (step_refinement_for_energy(); the run is then made again).
     * The sizes are the ones the rigid-flat bench (fem/bench/
     * dynamic_plastic.sh) measured as the coarsest meeting its GCI targets
     * at 1 and 10 V_y; the step count is the default scenario's, whose
     * contact time is then converged to 0.1 % (fem/README.md). Their
     * accuracy over a table of material pairs and velocities is measured by
     * fem/bench/automatic_discretisation.sh.
     */
    struct AutomaticDiscretisation
    {
      static constexpr double elements_per_contact_radius = 20;
      /// Contact elements per expected contact radius when a body is
      /// expected to yield. With plastic_contact_surface_refinements, the
      /// contact nodes lie every a / 240. A fully plastic contact carries
      /// nearly the same pressure up to its edge, so its force rises in a
      /// step each time a contact node enters contact: 2 dr / a of the force
      /// for a uniform pressure, 10 % at a / 20. Near the peak the contact
      /// radius stops growing between two nodes, and a level's F_max holds
      /// or misses the last node's force: the verified GCI of F_max was 0.9
      /// to 1.7 times that force. At a / 160 the GCI of F_max was 2.0 % on
      /// annealed copper on AISI 1006 at 2 m/s (V/V_y ~ 10^4), at a / 240
      /// 0.61 % (doc/results/fem-benchmarks.md); a node then adds at most
      /// 0.83 % of the force, below issue 30's 1 % target for that GCI.
      static constexpr double plastic_elements_per_contact_radius = 30;
      static constexpr double uniform_zone_per_contact_radius     = 1.5;
      static constexpr double surface_per_contact_radius          = 2.5;
      static constexpr double steps_per_expected_contact_time     = 300;
      /// Refinements of the contact surfaces' cells when a body is expected
      /// to yield: contact nodes every a / 240, for the force steps above
      /// (one refinement of the cells costs less than finer elements over
      /// the whole uniform zone).
      static constexpr unsigned int plastic_contact_surface_refinements = 3;

      /// The energy balance a run with automatic steps is sized for: at the
      /// end of the run |error| <= 1e-4 of the impact energy (the target the
      /// report flags, issue 30's item 1).
      static constexpr double energy_balance_target = 1e-4;
      /// The share of energy_balance_target a refined step aims at: a margin
      /// for the uncertainty of activation_work_order.
      static constexpr double energy_design_fraction = 0.8;
      /// The order p of "the balance's error falls as dt^p" the refinement
      /// assumes: the lowest order measured for the activation work (1.2
      /// to 1.9), so that the one refinement suffices.
      static constexpr double activation_work_order = 1.2;
      /// The most the automatic step count is raised for the energy balance.
      static constexpr double maximum_step_refinement = 8;
      /// The share of energy_balance_target left to the contact activation
      /// where the step's factor is capped: those are the most plastic
      /// impacts, whose rest of the error took up to 0.64 of the target with
      /// contact nodes at a / 320 (C11000 annealed on AISI 1006 at 5 m/s,
      /// doc/results/fem-benchmarks.md).
      static constexpr double capped_activation_fraction = 0.4;
      /// The most sub-steps at contact entry the rule asks for (the entry's
      /// own bound).
      static constexpr unsigned int maximum_entry_sub_steps = 64;
      /// How a run's automatic step and contact nodes are refined for its
      /// energy balance: each at most once (run_impact() makes a run at
      /// most three times).
      struct EnergyRefinement
      {
        /// The factor of the automatic step count [-], >= 1.
        double step = 1;
        /// Halvings of the automatic contact nodes' spacing: 0 or 1.
        unsigned int contact_spacing_halvings = 0;
        /// Sub-steps of the steps in which the contact's active set
        /// changes (Time integration/Sub-steps at contact entry), >= 1.
        unsigned int entry_sub_steps = 1;
      };

      /**
       * The factor by which a run's automatic step count is raised so that
       * its energy balance meets energy_balance_target, from what the run
       * measured at its end: @p balance, the balance's error, and
       * @p activation_work, the work the contact conditions did (the
       * trapezoidal rule on the multipliers and the weighted gaps: -1/2 p g
       * of each node in the step it enters contact), both per impact energy
       * [-]. The activation work is an error of the time discretisation: it
       * falls as dt^1.2 to dt^1.9 and does not change with the mesh; the
       * rest of the error fell as dt on a plastic sphere on a rigid flat and
       * not at all on 304 on 6061-T6 (doc/results/fem-model.md, "Where the
       * rest goes"). So the whole error is taken to fall as
       * dt^activation_work_order: the factor is (|balance| / (
       * energy_design_fraction target))^(1 / activation_work_order), at most
       * maximum_step_refinement; 1 when the balance meets the target, or
       * when the activation is not the larger part of its error (a finer
       * step is then no remedy).
       */
      static double
      step_refinement_for_energy(double balance, double activation_work);

      /**
       * Whether a run's automatic contact nodes are made twice as dense for
       * its energy balance (one more refinement of the contact surfaces'
       * cells), from the same @p balance and @p activation_work as
       * step_refinement_for_energy(), of a run whose step that rule has
       * already refined: when the balance misses energy_balance_target and
       * the rest of it (balance - activation work, of the balance's sign)
       * is the larger part. That rest is then BDF2's damping of what the
       * nodes entering contact excite in the mesh: on AISI 52100 on AISI
       * 1006 at 5 m/s it grew with a finer step (-4.8e-5 at 308 steps to
       * -1.1e-4 at 2228) and halving the contact nodes' spacing from a / 160
       * to a / 320 divided it by 2.6 to 3.1, leaving the activation work
       * within 15 % (doc/results/fem-benchmarks.md). (A rest that dominates
       * the first run has another cause: Newmark with gamma = 0.6 on a
       * 52100 ball on a rigid flat at 15 m/s lost -2.7e-3 with the contact
       * nodes at a / 160 and at a / 320 alike.) false for a non-finite
       * input.
       */
      static bool
      contact_spacing_halving_for_energy(double balance,
                                         double activation_work);

      /**
       * The sub-steps at contact entry a run asks for together with its
       * step factor, from the same @p balance and @p activation_work as
       * step_refinement_for_energy(): 1 unless that factor is capped at
       * maximum_step_refinement; then as many as take the activation work
       * to capped_activation_fraction of the target, it falling as the step
       * (by maximum_step_refinement) and as the sub-step (by n):
       *   n = ceil(|activation_work| / (maximum_step_refinement
       *            capped_activation_fraction energy_balance_target)),
       * in [1, maximum_entry_sub_steps]. Measured: the activation work fell
       * as dt^1.0 over the capped factor (C11000 annealed on AISI 1006 at 5
       * m/s), and as 1 / n with n = 4 and 8 sub-steps (the same case on a
       * coarse mesh: by 4.0 and 8.2); doc/results/fem-benchmarks.md.
       */
      static unsigned int
      entry_sub_steps_for_energy(double balance, double activation_work);

      /**
       * The refinement of a run's next try, from the refinement @p current
       * it ran with and its @p balance and @p activation_work (as
       * step_refinement_for_energy()); @p current itself when the run is
       * kept. Each refinement is made once: the step
       * (step_refinement_for_energy()) after the first run; the contact
       * nodes (only where @p spacing_refinable: the rule placed them and
       * one more refinement is allowed) after a refined step when the run
       * still misses mostly by the rest
       * (contact_spacing_halving_for_energy()). A capped step comes with
       * sub-steps at contact entry (entry_sub_steps_for_energy(); only
       * where @p sub_steps_refinable: the scenario left them "auto").
       */
      static EnergyRefinement
      next_refinement_for_energy(const EnergyRefinement &current,
                                 double                  balance,
                                 double                  activation_work,
                                 bool                    spacing_refinable,
                                 bool                    sub_steps_refinable);

      /// The sizes of the rule for @p expected on a sphere of radius R [m]
      /// whose Hertz contact time is @p hertz_contact_time [s] (the time
      /// step is Hertz's contact time / Steps per contact time). Throws an
      /// ExcMessage when the expected contact radius does not fit on the
      /// sphere (a > 0.4 R).
      AutomaticDiscretisation(const ExpectedContact &expected,
                              double                 sphere_radius,
                              double                 hertz_contact_time);

      /// The rule of each entry in words, for the log: "a / 20, a / 30 if
      /// a body is expected to yield", "1.5 a",
      /// "2.5 a, at most R/2", "300 per expected contact time; ...".
      static std::string
      contact_element_size_rule();
      static std::string
      uniform_zone_rule();
      static std::string
      contact_surface_rule();
      static std::string
      steps_rule();
      static std::string
      contact_surface_refinements_rule();

      ExpectedContact expected;
      double          contact_element_size   = 0; ///< [m]
      double          uniform_zone_radius    = 0; ///< [m]
      double          contact_surface_radius = 0; ///< [m]
      /// plastic_contact_surface_refinements if the expected contact yields
      /// (V > V_y), else 0 [-]; the mesh applies it only where it sizes the
      /// contact elements too (an explicit size is the scenario's mesh).
      unsigned int contact_surface_refinements = 0;
      double       steps_per_contact_time      = 0; ///< per Hertz t_c [-]
    };

    /// The pattern of an entry that is "auto" or a number.
    std::unique_ptr<Patterns::PatternBase>
    number_or_auto_pattern();

    /**
     * The value of the entry @p entry of the current subsection of @p prm
     * (named @p path in messages): @p automatic if it reads "auto", else
     * its number. @p was_automatic tells which.
     */
    double
    number_or_auto(const ParameterHandler &prm,
                   const std::string      &entry,
                   const std::string      &path,
                   double                  automatic,
                   bool                   &was_automatic);

    /**
     * What a run chose: each of the four entries with its value and whether
     * the rule ("auto") or the scenario set it, and the expected contact;
     * for the log and for summary.json.
     */
    struct DiscretisationChoice
    {
      struct Entry
      {
        std::string path; ///< "Mesh/Contact element size", ...
        std::string unit; ///< "m" or "1"
        double      value     = 0;
        bool        automatic = false;
        std::string rule; ///< how "auto" sized it (AutomaticDiscretisation)
      };
      ExpectedContact    expected;
      std::vector<Entry> entries;

      /// The log's lines, one per entry, with the rule that gave the value.
      std::string
      describe() const;

      nlohmann::json
      to_json() const;
    };
  } // namespace discretisation
} // namespace impact_fem

#endif
