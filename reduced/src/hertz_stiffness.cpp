#include "impact_reduced/hertz_stiffness.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <cmath>

namespace impact::reduced {

namespace {
void validate(const ElasticBody& body, const std::string& name) {
  require_positive((name + ".youngs_modulus").c_str(), body.youngs_modulus);
  require_open_interval((name + ".poisson_ratio").c_str(), body.poisson_ratio, -1.0, 0.5);
  if (!(body.radius > 0) || std::isnan(body.radius))
    throw InvalidInput(name + ".radius", name + ".radius must be > 0 (infinity for a plate)");
}
} // namespace

double hertz_stiffness(const ElasticBody& first, const ElasticBody& second) {
  validate(first, "first");
  validate(second, "second");
  const double curvature = 1.0 / first.radius + 1.0 / second.radius;
  if (!(curvature > 0))
    throw InvalidInput("radius", "at least one of the two radii must be finite");
  const double compliance =
      (1.0 - first.poisson_ratio * first.poisson_ratio) / first.youngs_modulus +
      (1.0 - second.poisson_ratio * second.poisson_ratio) / second.youngs_modulus;
  return 1.0 / (0.75 * compliance * std::sqrt(curvature));
}

} // namespace impact::reduced
