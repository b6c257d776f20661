#include <impact_fem/as_written.h>
#include <impact_fem/discretisation/automatic_discretisation.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace impact_fem
{
  namespace discretisation
  {
    AutomaticDiscretisation::AutomaticDiscretisation(
      const ExpectedContact &expected,
      const double           sphere_radius,
      const double           hertz_contact_time)
      : expected(expected)
    {
      const double a = expected.contact_radius;
      // The mesh generator allows contact surfaces up to R/2; a contact that
      // would fill most of that is far outside the small-strain model.
      AssertThrow(a > 0 && a <= 0.4 * sphere_radius,
                  ExcMessage("The " + expected.describe() +
                             " does not fit on the sphere (at most 0.4 R = " +
                             as_written(0.4 * sphere_radius) +
                             " m, so that a contact surface of 1.25 a fits "
                             "within R/2): the impact is beyond the model's "
                             "small strains. Give Mesh/Contact element "
                             "size, Uniform zone radius and Contact surface "
                             "radius explicitly only if you know better."));
      const bool yields    = expected.velocity_ratio > 1;
      contact_element_size = a / (yields ? plastic_elements_per_contact_radius :
                                           elements_per_contact_radius);
      contact_surface_radius =
        std::min(surface_per_contact_radius * a, 0.5 * sphere_radius);
      uniform_zone_radius =
        std::min(uniform_zone_per_contact_radius * a, contact_surface_radius);
      contact_surface_refinements =
        yields ? plastic_contact_surface_refinements : 0;
      steps_per_contact_time = expected.contact_time > 0 ?
                                 steps_per_expected_contact_time *
                                   hertz_contact_time / expected.contact_time :
                                 steps_per_expected_contact_time;
    }


    double
    AutomaticDiscretisation::step_refinement_for_energy(
      const double balance,
      const double activation_work)
    {
      const double design = energy_design_fraction * energy_balance_target;
      // The activation, of the balance's sign, is the larger part of it.
      const bool activation_dominates =
        activation_work * balance > 0 &&
        std::abs(activation_work) >= 0.5 * std::abs(balance);
      if (!std::isfinite(balance) || !std::isfinite(activation_work) ||
          std::abs(balance) <= energy_balance_target || !activation_dominates)
        return 1;
      return std::min(std::pow(std::abs(balance) / design,
                               1 / activation_work_order),
                      maximum_step_refinement);
    }


    unsigned int
    AutomaticDiscretisation::entry_sub_steps_for_energy(
      const double balance,
      const double activation_work)
    {
      if (step_refinement_for_energy(balance, activation_work) <
          maximum_step_refinement)
        return 1;
      const double design = energy_design_fraction * energy_balance_target;
      // The factor the balance asks for, had it no cap.
      if (std::pow(std::abs(balance) / design, 1 / activation_work_order) <=
          maximum_step_refinement)
        return 1;
      const double n =
        std::ceil(std::abs(activation_work) /
                  (maximum_step_refinement * capped_activation_fraction *
                   energy_balance_target));
      return static_cast<unsigned int>(
        std::clamp(n, 1., double(maximum_entry_sub_steps)));
    }


    bool
    AutomaticDiscretisation::contact_spacing_halving_for_energy(
      const double balance,
      const double activation_work)
    {
      if (!std::isfinite(balance) || !std::isfinite(activation_work) ||
          std::abs(balance) <= energy_balance_target)
        return false;
      const double rest = balance - activation_work;
      return rest * balance > 0 && std::abs(rest) >= 0.5 * std::abs(balance);
    }


    AutomaticDiscretisation::EnergyRefinement
    AutomaticDiscretisation::next_refinement_for_energy(
      const EnergyRefinement &current,
      const double            balance,
      const double            activation_work,
      const bool              spacing_refinable,
      const bool              sub_steps_refinable)
    {
      EnergyRefinement next = current;
      const bool       spacing_left =
        spacing_refinable && current.contact_spacing_halvings == 0;
      const double step = step_refinement_for_energy(balance, activation_work);
      if (current.step == 1 && step > 1)
        {
          next.step = step;
          if (sub_steps_refinable)
            next.entry_sub_steps =
              entry_sub_steps_for_energy(balance, activation_work);
        }
      // Only after a finer step: the rest it leaves is then the damping of
      // what the nodes entering contact excite, which denser nodes reduce;
      // a rest that dominates from the first run has another cause.
      else if (spacing_left && current.step > 1 &&
               contact_spacing_halving_for_energy(balance, activation_work))
        next.contact_spacing_halvings = 1;
      return next;
    }


    namespace
    {
      std::string
      number(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }
    } // namespace


    std::string
    AutomaticDiscretisation::contact_element_size_rule()
    {
      return "a / " + number(elements_per_contact_radius) + ", a / " +
             number(plastic_elements_per_contact_radius) +
             " if a body is expected to yield";
    }


    std::string
    AutomaticDiscretisation::uniform_zone_rule()
    {
      return number(uniform_zone_per_contact_radius) + " a";
    }


    std::string
    AutomaticDiscretisation::contact_surface_rule()
    {
      return number(surface_per_contact_radius) + " a, at most R/2";
    }


    std::string
    AutomaticDiscretisation::contact_surface_refinements_rule()
    {
      return number(plastic_contact_surface_refinements) +
             " if a body is expected to yield (contact nodes every a / " +
             number(plastic_elements_per_contact_radius *
                    (1u << plastic_contact_surface_refinements)) +
             ") and the contact element size is auto, else 0; one more if "
             "a run whose step was refined for its energy balance still "
             "misses " +
             number(energy_balance_target) +
             ", mostly by the rest of the error (the integrator's damping)";
    }


    std::string
    AutomaticDiscretisation::steps_rule()
    {
      return number(steps_per_expected_contact_time) +
             " per expected contact time, raised if the contact activation "
             "loses more than the energy balance allows (" +
             number(energy_balance_target) +
             "); the entry counts per Hertz contact time";
    }


    namespace
    {
      bool
      is_auto(const std::string &text)
      {
        return Utilities::trim(text) == "auto";
      }

      bool
      is_number(const std::string &text)
      {
        std::istringstream in(Utilities::trim(text));
        double             x;
        in >> x;
        return !in.fail() && in.eof() && std::isfinite(x);
      }

      class NumberOrAuto : public Patterns::PatternBase
      {
      public:
        bool
        match(const std::string &text) const override
        {
          return is_auto(text) || is_number(text);
        }

        std::string
        description(const Patterns::PatternBase::OutputStyle) const override
        {
          return "[auto or a floating point number]";
        }

        std::unique_ptr<Patterns::PatternBase>
        clone() const override
        {
          return std::make_unique<NumberOrAuto>();
        }
      };
    } // namespace


    std::unique_ptr<Patterns::PatternBase>
    number_or_auto_pattern()
    {
      return std::make_unique<NumberOrAuto>();
    }


    double
    number_or_auto(const ParameterHandler &prm,
                   const std::string      &entry,
                   const std::string      &path,
                   const double            automatic,
                   bool                   &was_automatic)
    {
      const std::string text = prm.get(entry);
      was_automatic          = is_auto(text);
      if (was_automatic)
        return automatic;
      AssertThrow(is_number(text),
                  ExcMessage(path + " must be 'auto' or a number, got '" +
                             text + "'."));
      return std::stod(Utilities::trim(text));
    }


    std::string
    DiscretisationChoice::describe() const
    {
      std::ostringstream s;
      s << "  " << expected.describe() << "\n";
      for (const auto &e : entries)
        s << "  " << e.path << " = " << as_written(e.value)
          << (e.unit == "1" ? "" : " " + e.unit)
          << (e.automatic ? "  (auto: " + e.rule + ")" :
                            "  (set by the scenario)")
          << "\n";
      return s.str();
    }


    nlohmann::json
    DiscretisationChoice::to_json() const
    {
      nlohmann::json j = {{"expected_contact", expected.to_json()}};
      for (const auto &e : entries)
        {
          j["entries"][e.path] = {{"value", e.value},
                                  {"unit", e.unit},
                                  {"origin",
                                   e.automatic ? "auto" : "scenario"}};
          if (e.automatic)
            j["entries"][e.path]["rule"] = e.rule;
        }
      return j;
    }
  } // namespace discretisation
} // namespace impact_fem
