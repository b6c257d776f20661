#pragma once
/// @file
/// Hertz contact stiffness of two elastic spheres.

#include <limits>

namespace impact::reduced {

/// An elastic body at the contact: Young's modulus [Pa], Poisson's ratio [-] and the
/// radius of curvature at the contact point [m] (infinity for a plate or half-space).
struct ElasticBody {
  double youngs_modulus;
  double poisson_ratio;
  double radius = std::numeric_limits<double>::infinity();
};

/// Hertz stiffness c [N/m^1.5] of two spheres, F = c x^(3/2):
///     1/c = (3/4) ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) sqrt(1/R1 + 1/R2).
/// Ranges: E > 0, -1 < nu < 0.5, R > 0 (infinity allowed for one of the two, not both).
/// Accuracy: a few ulps. Throws InvalidInput naming the offending field ("first.radius"...).
double hertz_stiffness(const ElasticBody& first, const ElasticBody& second);

} // namespace impact::reduced
