#include "impact_reduced/elastic_force.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <stdexcept>

namespace impact::reduced {

double ElasticForce::approach_at_potential(double target) const {
  if (target <= 0) return 0.0;
  // Bracket: grow the upper end until P exceeds the target.
  double upper = 1e-9;
  int doublings = 0;
  while (potential(upper) < target) {
    upper *= 2;
    if (++doublings > 2000)
      throw std::runtime_error("the elastic potential never reaches the impact energy");
  }
  boost::uintmax_t iterations = 200;
  const auto [lower_end, upper_end] =
      boost::math::tools::toms748_solve([&](double x) { return potential(x) - target; }, 0.0, upper,
                                        -target, potential(upper) - target,
                                        boost::math::tools::eps_tolerance<double>(), iterations);
  return 0.5 * (lower_end + upper_end);
}

PowerLawForce::PowerLawForce(double stiffness, double exponent)
    : stiffness_(stiffness), exponent_(exponent) {
  require_positive("stiffness", stiffness);
  require_positive("exponent", exponent);
}

double PowerLawForce::force(double approach) const {
  return stiffness_ * std::pow(approach, exponent_);
}

double PowerLawForce::potential(double approach) const {
  return stiffness_ * std::pow(approach, exponent_ + 1) / (exponent_ + 1);
}

double PowerLawForce::slope(double approach) const {
  return exponent_ * stiffness_ * std::pow(approach, exponent_ - 1);
}

double PowerLawForce::approach_at_potential(double potential) const {
  return std::pow((exponent_ + 1) * potential / stiffness_, 1.0 / (exponent_ + 1));
}

CustomElasticForce::CustomElasticForce(Function force, Function potential, Function slope)
    : force_(std::move(force)), potential_(std::move(potential)), slope_(std::move(slope)) {
  if (!force_) throw InvalidInput("force", "force must be a callable f(x)");
  if (!potential_) throw InvalidInput("potential", "potential must be a callable P(x)");
  if (!slope_) throw InvalidInput("slope", "slope must be a callable f'(x)");
}

} // namespace impact::reduced
