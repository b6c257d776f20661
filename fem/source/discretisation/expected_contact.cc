#include <impact_fem/discretisation/expected_contact.h>

#include <impact_reduced/elastic_plastic_impact.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>
#include <impact_reduced/contact_formulas.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace impact_fem
{
  namespace discretisation
  {
    namespace reduced = impact::reduced;

    ExpectedContact
    ExpectedContact::of_impact(const HertzImpact               &hertz,
                               const std::vector<YieldingBody> &yielding_bodies)
    {
      const auto pressure = [](const YieldingBody &body) {
        return reduced::yield_pressure(reduced::YieldCriterion::jackson_green,
                                       body.yield_strength,
                                       body.poissons_ratio);
      };
      const YieldingBody *first = nullptr;
      for (const auto &body : yielding_bodies)
        if (!first || pressure(body) < pressure(*first))
          first = &body;
      ExpectedContact expected;
      if (!first)
        {
          expected.law            = "Hertz";
          expected.approach_max   = hertz.approach_max();
          expected.contact_radius = hertz.contact_radius_max();
          expected.contact_time   = hertz.contact_time();
          return expected;
        }
      const reduced::SphereFlatContact contact{hertz.radius,
                                               hertz.effective_modulus,
                                               first->yield_strength,
                                               first->poissons_ratio};
      const auto                       response =
        reduced::elastic_plastic_impact(hertz.mass,
                                        hertz.velocity,
                                        reduced::JacksonGreenContact(contact));
      expected.law           = "Jackson-Green";
      expected.yielding_body = first->name;
      expected.approach_max  = response.approach_max;
      expected.contact_radius =
        reduced::jackson_green_contact_radius(response.approach_max, contact);
      expected.contact_time = response.contact_time;
      expected.velocity_ratio =
        hertz.velocity / reduced::yield_velocity(pressure(*first),
                                                 hertz.effective_modulus,
                                                 hertz.radius,
                                                 hertz.mass);
      return expected;
    }


    ExpectedContact
    ExpectedContact::of_static_force(const HertzImpact &hertz,
                                     const double       force)
    {
      // Hertz's F = k x^(3/2) inverted.
      return of_indentation(hertz,
                            std::pow(force / hertz.stiffness(), 2. / 3.));
    }


    ExpectedContact
    ExpectedContact::of_indentation(const HertzImpact &hertz,
                                    const double       approach_max)
    {
      ExpectedContact expected;
      expected.law            = "Hertz";
      expected.approach_max   = approach_max;
      expected.contact_radius = std::sqrt(hertz.radius * approach_max);
      return expected;
    }


    std::string
    ExpectedContact::describe() const
    {
      std::ostringstream s;
      s << std::setprecision(4) << "expected contact (" << law;
      if (!yielding_body.empty())
        s << ", the " << yielding_body
          << " yielding first, V/V_y = " << velocity_ratio;
      s << "): radius " << contact_radius * 1e3 << " mm, approach "
        << approach_max * 1e6 << " um";
      if (contact_time > 0)
        s << ", contact time " << contact_time * 1e6 << " us";
      return s.str();
    }


    nlohmann::json
    ExpectedContact::to_json() const
    {
      nlohmann::json j = {{"law", law},
                          {"approach_max", approach_max},
                          {"contact_radius", contact_radius},
                          {"contact_time", contact_time}};
      if (!yielding_body.empty())
        {
          j["yielding_body"]  = yielding_body;
          j["velocity_ratio"] = velocity_ratio;
        }
      return j;
    }
  } // namespace discretisation
} // namespace impact_fem
