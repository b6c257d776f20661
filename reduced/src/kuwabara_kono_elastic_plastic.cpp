#include "impact_reduced/kuwabara_kono_elastic_plastic.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <algorithm>
#include <cmath>

namespace impact::reduced {

double kuwabara_kono_elastic_plastic_force(const ElasticPlasticContact& spring,
                                           double dissipative_constant, double approach,
                                           double approach_rate, double approach_max) {
  if (approach_rate >= 0 || approach_max <= 0)
    return spring.loading_force(approach) +
           dissipative_constant * spring.loading_stiffness(approach) * approach_rate;
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
    if (rate >= 0)
      return spring.loading_force(x) + dissipative_constant * spring.loading_stiffness(x) * rate;
    const double stretch = x - branch.residual_approach;
    return branch.stiffness * std::sqrt(std::abs(stretch)) *
           (stretch + 1.5 * dissipative_constant * rate);
  };
}

// x_max from the compression on the loading branch (identical in both integrations).
double approach_max_of(double mass, double velocity, const ElasticPlasticContact& spring,
                       double dissipative_constant, double relative_tolerance) {
  const ContactForceLaw loading = [&spring, dissipative_constant](double x, double rate) {
    return spring.loading_force(x) + dissipative_constant * spring.loading_stiffness(x) * rate;
  };
  return integrate_impact(mass, velocity, loading, relative_tolerance, ContactEnd::zero_force)
      .approach_max;
}

} // namespace

OdeImpactResult kuwabara_kono_elastic_plastic_impact(double mass, double velocity,
                                                     const ElasticPlasticContact& spring,
                                                     double dissipative_constant,
                                                     double relative_tolerance) {
  validate(mass, velocity, dissipative_constant);
  const double approach_max =
      approach_max_of(mass, velocity, spring, dissipative_constant, relative_tolerance);
  return integrate_impact(mass, velocity, switched_law(spring, dissipative_constant, approach_max),
                          relative_tolerance, ContactEnd::zero_force);
}

std::vector<ImpactSample> kuwabara_kono_elastic_plastic_history(double mass, double velocity,
                                                                const ElasticPlasticContact& spring,
                                                                double dissipative_constant,
                                                                std::size_t points,
                                                                double relative_tolerance) {
  validate(mass, velocity, dissipative_constant);
  const double approach_max =
      approach_max_of(mass, velocity, spring, dissipative_constant, relative_tolerance);
  return integrate_impact_history(mass, velocity,
                                  switched_law(spring, dissipative_constant, approach_max), points,
                                  relative_tolerance, ContactEnd::zero_force);
}

} // namespace impact::reduced
