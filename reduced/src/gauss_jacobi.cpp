#include "gauss_jacobi.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <map>
#include <utility>

namespace impact::reduced::detail {

namespace {

// Jacobi weight (1 - x)^a (1 + x)^b on (-1, 1), here with a = 0 and b = -exponent:
// the three-term recurrence of the orthonormal polynomials gives the symmetric
// tridiagonal Jacobi matrix whose eigenvalues are the nodes and whose eigenvectors'
// first components give the weights (Golub & Welsch 1969).
QuadratureRule make_rule(int points, double exponent) {
  const double a = 0.0;
  const double b = -exponent;
  Eigen::VectorXd diagonal(points);
  Eigen::VectorXd off_diagonal(points > 1 ? points - 1 : 1);
  for (int k = 0; k < points; ++k) {
    const double sum = 2.0 * k + a + b;
    diagonal[k] = (k == 0) ? (b - a) / (a + b + 2.0) : (b * b - a * a) / (sum * (sum + 2.0));
  }
  for (int k = 1; k < points; ++k) {
    const double sum = 2.0 * k + a + b;
    off_diagonal[k - 1] = std::sqrt(4.0 * k * (k + a) * (k + b) * (k + a + b) /
                                    (sum * sum * (sum + 1.0) * (sum - 1.0)));
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off_diagonal.head(points - 1),
                                Eigen::ComputeEigenvectors);
  // Total mass of the weight on (-1, 1): 2^(a+b+1) Gamma(a+1) Gamma(b+1) / Gamma(a+b+2).
  const double mass = std::pow(2.0, a + b + 1.0) * std::tgamma(a + 1.0) * std::tgamma(b + 1.0) /
                      std::tgamma(a + b + 2.0);
  // Map x in (-1, 1) to t = (1 + x) / 2 in (0, 1): (1 + x)^b dx = 2^(b+1) t^b dt.
  const double scale = std::pow(2.0, -(b + 1.0));
  QuadratureRule rule;
  for (int i = 0; i < points; ++i) {
    const double first = solver.eigenvectors()(0, i);
    rule.nodes.push_back(0.5 * (1.0 + solver.eigenvalues()[i]));
    rule.weights.push_back(mass * first * first * scale);
  }
  return rule;
}

} // namespace

const QuadratureRule& gauss_jacobi_rule(int points, double exponent) {
  thread_local std::map<std::pair<int, double>, QuadratureRule> cache;
  const auto key = std::make_pair(points, exponent);
  auto found = cache.find(key);
  if (found == cache.end()) {
    if (cache.size() > 64) cache.clear(); // calibrations sweep exponents: keep it bounded
    found = cache.emplace(key, make_rule(points, exponent)).first;
  }
  return found->second;
}

} // namespace impact::reduced::detail
