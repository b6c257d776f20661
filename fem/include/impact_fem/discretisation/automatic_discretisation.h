#ifndef IMPACT_FEM_DISCRETISATION_AUTOMATIC_DISCRETISATION_H
#define IMPACT_FEM_DISCRETISATION_AUTOMATIC_DISCRETISATION_H

#include <deal.II/base/parameter_handler.h>

#include <impact_fem/discretisation/expected_contact.h>

#include <nlohmann/json.hpp>

#include <string>

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
     * contact time (expected_contact.h): contact elements a / 20, a uniform
     * zone of 1.5 a and a contact surface of 2.5 a (at most R/2, the
     * largest the mesh allows), the contact surfaces' cells refined three
     * times more when a body is expected to yield (contact nodes every
     * a / 160),
     * 300 time steps per expected contact time.
     * The sizes are the ones the rigid-flat bench (fem/bench/
     * dynamic_plastic.sh) measured as the coarsest meeting its GCI targets
     * at 1 and 10 V_y; the step count is the default scenario's, whose
     * contact time is then converged to 0.1 % (fem/README.md). Their
     * accuracy over a table of material pairs and velocities is measured by
     * fem/bench/automatic_discretisation.sh.
     */
    struct AutomaticDiscretisation
    {
      static constexpr double elements_per_contact_radius     = 20;
      static constexpr double uniform_zone_per_contact_radius = 1.5;
      static constexpr double surface_per_contact_radius      = 2.5;
      static constexpr double steps_per_expected_contact_time = 300;
      /// Refinements of the contact surfaces' cells when a body is expected
      /// to yield: contact nodes every a / 160. A fully plastic contact
      /// carries nearly the same pressure up to its edge, so its force rises
      /// in a step each time a contact node enters contact (about 2 h / a of
      /// the force: 10 % at a / 20, a staircase that makes the GCI of F_max
      /// and e oscillatory); at a / 80 the GCI of F_max still reached 1.4 %
      /// (AISI 304 on 6061-T6 at 1 and 3 m/s) and 3.4 % (annealed copper at
      /// V/V_y ~ 10^4), at a / 160 it is 0.008-1.13 % on the former at 1-3
      /// m/s (fem/bench/automatic_discretisation.sh), for about a quarter
      /// more cells than a / 80.
      static constexpr unsigned int plastic_contact_surface_refinements = 3;

      /// The sizes of the rule for @p expected on a sphere of radius R [m]
      /// whose Hertz contact time is @p hertz_contact_time [s] (the time
      /// step is Hertz's contact time / Steps per contact time). Throws an
      /// ExcMessage when the expected contact radius does not fit on the
      /// sphere (a > 0.4 R).
      AutomaticDiscretisation(const ExpectedContact &expected,
                              double                 sphere_radius,
                              double                 hertz_contact_time);

      /// The rule of each entry in words, for the log: "a / 20", "1.5 a",
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
