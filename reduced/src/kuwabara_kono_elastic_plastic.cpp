#include "impact_reduced/kuwabara_kono_elastic_plastic.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "kuwabara_kono_stretch_root.hpp"
#include "switched_impact.hpp"

#include <algorithm>
#include <cmath>

namespace impact::reduced {

double kuwabara_kono_elastic_plastic_force(const ElasticPlasticContact& spring,
                                           double dissipative_constant, double approach,
                                           double approach_rate, double approach_max) {
  if (approach_rate >= 0 || approach_max <= 0) {
    const auto [force, stiffness] = spring.loading_force_and_stiffness(approach);
    return force + dissipative_constant * stiffness * approach_rate;
  }
  const HertzianUnloading branch = spring.unloading(approach_max);
  const double stretch = std::max(0.0, approach - branch.residual_approach);
  const double root = std::sqrt(stretch);
  return branch.stiffness * root * (stretch + 1.5 * dissipative_constant * approach_rate);
}

namespace {

void validate(double mass, double velocity, double dissipative_constant) {
  require_positive("mass", mass);
  require_positive("velocity", velocity);
  require_non_negative("dissipative_constant", dissipative_constant);
}

// The law with the unloading branch of x_max (computed once, not at every evaluation).
// Below x_r the branch is continued as k_u |s|^(1/2) (s + (3/2) A x'), s = x - x_r < 0, which
// is negative there: the force then changes sign once, at s = -(3/2) A x' > 0, so that the
// integrator's F = 0 event finds that crossing even when the window of tension is shorter
// than a step (a branch clipped at 0 below x_r would let a step jump over it, small A).
ContactForceLaw switched_law(const ElasticPlasticContact& spring, double dissipative_constant,
                             double approach_max) {
  const HertzianUnloading branch = spring.unloading(approach_max);
  return [&spring, dissipative_constant, branch](double x, double rate) {
    if (rate >= 0) {
      const auto [force, stiffness] = spring.loading_force_and_stiffness(x);
      return force + dissipative_constant * stiffness * rate;
    }
    const double stretch = x - branch.residual_approach;
    return branch.stiffness * std::sqrt(std::abs(stretch)) *
           (stretch + 1.5 * dissipative_constant * rate);
  };
}

// The loading branch's law (identical to the switched law while x' >= 0).
ContactForceLaw loading_law(const ElasticPlasticContact& spring, double dissipative_constant) {
  return [&spring, dissipative_constant](double x, double rate) {
    const auto [force, stiffness] = spring.loading_force_and_stiffness(x);
    return force + dissipative_constant * stiffness * rate;
  };
}

detail::LawAtMaximum unloading_law(const ElasticPlasticContact& spring,
                                   double dissipative_constant) {
  return [&spring, dissipative_constant](double approach_max) {
    return switched_law(spring, dissipative_constant, approach_max);
  };
}

} // namespace

// One integration: the compression on the loading branch gives x_max, where the law switches
// to the unloading branch of that x_max and the step that holds x_max is re-taken
// (switched_impact.hpp); the same impact as integrating the switched law from t = 0.
OdeImpactResult kuwabara_kono_elastic_plastic_impact(double mass, double velocity,
                                                     const ElasticPlasticContact& spring,
                                                     double dissipative_constant,
                                                     double relative_tolerance) {
  validate(mass, velocity, dissipative_constant);
  if (detail::has_hertz_start(spring))
    return detail::kuwabara_kono_stretch_root_impact(mass, velocity, spring, dissipative_constant,
                                                     relative_tolerance);
  return detail::integrate_switched_impact(mass, velocity,
                                           loading_law(spring, dissipative_constant),
                                           unloading_law(spring, dissipative_constant),
                                           relative_tolerance, ContactEnd::zero_force);
}

std::vector<ImpactSample> kuwabara_kono_elastic_plastic_history(double mass, double velocity,
                                                                const ElasticPlasticContact& spring,
                                                                double dissipative_constant,
                                                                std::size_t points,
                                                                double relative_tolerance) {
  validate(mass, velocity, dissipative_constant);
  if (detail::has_hertz_start(spring))
    return detail::kuwabara_kono_stretch_root_history(mass, velocity, spring, dissipative_constant,
                                                      points, relative_tolerance);
  return detail::integrate_switched_impact_history(mass, velocity,
                                                   loading_law(spring, dissipative_constant),
                                                   unloading_law(spring, dissipative_constant),
                                                   points, relative_tolerance,
                                                   ContactEnd::zero_force);
}

} // namespace impact::reduced
