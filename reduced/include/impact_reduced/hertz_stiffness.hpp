#pragma once
/// @file
/// Hertz contact stiffness of two elastic spheres (or a sphere and a flat, elastic or rigid),
/// and the mass of a solid sphere.

#include <limits>

namespace impact::reduced {

/// An elastic body at the contact: Young's modulus [Pa], Poisson's ratio [-] and the
/// radius of curvature at the contact point [m] (infinity for a plate or half-space).
/// A rigid body has an infinite modulus: make it with rigid_body().
struct ElasticBody {
  double youngs_modulus;
  double poisson_ratio;
  double radius = std::numeric_limits<double>::infinity();
};

/// A rigid body (no compliance: (1 - nu^2)/E = 0), a flat unless `radius` is given. Its
/// modulus is +infinity, the only infinite modulus hertz_stiffness accepts; its Poisson ratio
/// (0) has no effect.
inline ElasticBody rigid_body(double radius = std::numeric_limits<double>::infinity()) {
  return {std::numeric_limits<double>::infinity(), 0.0, radius};
}

/// Hertz stiffness c [N/m^1.5] of two spheres, F = c x^(3/2):
///     1/c = (3/4) ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) sqrt(1/R1 + 1/R2).
/// Ranges: E > 0 (infinity for a rigid body, rigid_body(); not both), -1 < nu < 0.5, R > 0
/// (infinity allowed for one of the two, not both). Accuracy: a few ulps. Throws InvalidInput
/// naming the offending field ("first.radius"...), also when c overflows (is not finite).
double hertz_stiffness(const ElasticBody& first, const ElasticBody& second);

/// Mass (4/3) pi R^3 rho [kg] of a solid sphere of radius R > 0 [m] and density rho > 0
/// [kg/m^3]. Throws InvalidInput naming "radius", "density", or "mass" when the product
/// overflows or underflows to 0.
double solid_sphere_mass(double radius, double density);

} // namespace impact::reduced
