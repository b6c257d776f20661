#pragma once
// Interpolation at the K Chebyshev points of the first kind, x_k = cos(pi (k + 1/2) / K),
// k = 0 .. K-1 (descending from the right end of [-1, 1]): the discrete cosine transform
// that turns values there into Chebyshev coefficients (Trefethen, Approximation Theory and
// Approximation Practice, SIAM 2013, ch. 3). Internal to the library (phase_time_map*.cpp).

#include <array>
#include <cmath>

namespace impact::reduced::detail {

template <int K>
using CosineTable = std::array<std::array<double, K>, K>;

/// cos(pi j (k + 1/2) / K): row 1 holds the points, row j the transform. Computed once.
template <int K>
const CosineTable<K>& cosine_table() {
  static const CosineTable<K> table = [] {
    CosineTable<K> values{};
    const double pi = std::acos(-1.0);
    for (int j = 0; j < K; ++j)
      for (int k = 0; k < K; ++k) values[j][k] = std::cos(pi * j * (k + 0.5) / K);
    return values;
  }();
  return table;
}

/// The Chebyshev coefficients of the values at the K points, and whether the last three
/// are within `tolerance`.
template <int K>
bool chebyshev_coefficients(const double* values, double tolerance, double* coefficients) {
  const CosineTable<K>& cosine = cosine_table<K>();
  for (int j = 0; j < K; ++j) {
    double sum = 0;
    for (int k = 0; k < K; ++k) sum += values[k] * cosine[j][k];
    coefficients[j] = (j == 0 ? 1.0 : 2.0) * sum / K;
  }
  const double tail = std::fabs(coefficients[K - 1]) + std::fabs(coefficients[K - 2]) +
                      std::fabs(coefficients[K - 3]);
  return tail <= tolerance;
}

} // namespace impact::reduced::detail
