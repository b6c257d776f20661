#include "impact_reduced/hertz_stiffness.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace impact::reduced {

namespace {
constexpr double pi = 3.14159265358979323846;

void validate(const ElasticBody& body, const std::string& name) {
  if (body.youngs_modulus != std::numeric_limits<double>::infinity()) // rigid_body()
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
  if (!(compliance > 0))
    throw InvalidInput("youngs_modulus",
                       "two rigid bodies have no Hertz contact (both moduli "
                       "are infinite)");
  const double stiffness = 1.0 / (0.75 * compliance * std::sqrt(curvature));
  if (!std::isfinite(stiffness))
    throw InvalidInput("youngs_modulus",
                       "the Hertz stiffness of these bodies overflows (is not "
                       "a finite number)");
  return stiffness;
}

double solid_sphere_mass(double radius, double density) {
  require_positive("radius", radius);
  require_positive("density", density);
  const double mass = 4.0 / 3.0 * pi * radius * radius * radius * density;
  if (!std::isfinite(mass) || !(mass > 0)) {
    std::ostringstream message;
    message.precision(17);
    message << "mass: the sphere of radius " << radius << " m and density " << density
            << " kg/m^3 has a mass " << mass << " kg outside the finite positive numbers";
    throw InvalidInput("mass", message.str());
  }
  return mass;
}

} // namespace impact::reduced
