#pragma once
// Gauss-Jacobi quadrature for integrals with an end-point power singularity,
//     integral_0^1 t^(-exponent) h(t) dt  ~  sum_i weight_i h(node_i),
// exact for polynomials h of degree < 2 points. Internal to the library: the Hunt-Crossley
// time integrals have exactly this form for the power law (see hunt_crossley.cpp).

#include <vector>

namespace impact::reduced::detail {

struct QuadratureRule {
  std::vector<double> nodes;   // in (0, 1)
  std::vector<double> weights; // for the weight t^(-exponent) on (0, 1)
};

/// The `points`-point rule for the weight t^(-exponent), 0 <= exponent < 1, by the
/// Golub-Welsch eigenvalue method (Eigen). Rules are cached per thread, so a given
/// exponent costs the eigenvalue solve (about 20 us) once.
const QuadratureRule& gauss_jacobi_rule(int points, double exponent);

} // namespace impact::reduced::detail
