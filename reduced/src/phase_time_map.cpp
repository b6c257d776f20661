#include "phase_time_map.hpp"

#include "chebyshev_points.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impact::reduced::detail {

namespace {

constexpr int m = PhaseTimeMap::nodes;

} // namespace

PhaseTimeMap::PhaseTimeMap(const Density& density, double power, double tolerance) : power_(power) {
  double middle[phase_companions], end[phase_companions];
  density_tolerance_ = tolerance * density(0.5, std::pow(0.5, power), middle);
  density(1.0, 1.0, end);
  for (int c = 0; c < phase_companions; ++c)
    companion_tolerance_[c] = tolerance * std::max(std::fabs(middle[c]), std::fabs(end[c]));
  evaluations_ = 2;
  // The first piece as wide as its polynomial converges (G's nearest singularity lies
  // O(1) away in sigma^p, so about half the phase).
  double first = 0.5;
  for (;;) {
    const Convergence convergence = build_first_piece(density, first);
    if (convergence.density && (convergence.companions || first <= 1.0 / 64)) break;
    if (first <= 1.0 / 1024) break;
    first *= 0.5;
  }
  // Depth-first bisection keeps the panels in ascending order, so each starts at the time
  // accumulated by those before it.
  std::function<void(double, double, int)> cover = [&](double lower, double upper, int depth) {
    Panel panel;
    const Convergence convergence = build_panel(density, lower, upper, panel);
    if ((convergence.density && (convergence.companions || depth >= companion_depth)) ||
        depth >= 60) {
      panels_.push_back(panel);
      duration_ += panel.half_width * [&] {
        double at_right = 0;
        for (int j = 0; j <= m; ++j) at_right += panel.time[j];
        return at_right;
      }();
      return;
    }
    const double middle_sigma = 0.5 * (lower + upper);
    cover(lower, middle_sigma, depth + 1);
    cover(middle_sigma, upper, depth + 1);
  };
  const int count = std::max(1, static_cast<int>(std::ceil((1.0 - first) / 0.125)));
  for (int i = 0; i < count; ++i)
    cover(first + (1.0 - first) * i / count, first + (1.0 - first) * (i + 1) / count, 0);
}

namespace {

// The monomial coefficients in tau in [0, 1] of sum_j chebyshev[j] T_j(2 tau - 1), by
// T_(j+1) = 2 (2 tau - 1) T_j - T_(j-1). The coefficients decay much faster than those of
// T_j grow, so the sum stays exact.
template <int K>
void monomials(const double* chebyshev, double* monomial) {
  double previous[K] = {1.0}, current[K] = {-1.0, 2.0};
  for (int k = 0; k < K; ++k) monomial[k] = 0;
  monomial[0] += chebyshev[0] * previous[0];
  for (int k = 0; k < 2; ++k) monomial[k] += chebyshev[1] * current[k];
  for (int j = 2; j < K; ++j) {
    double next[K] = {};
    for (int k = 0; k < K; ++k)
      next[k] = -2.0 * current[k] - previous[k] + (k > 0 ? 4.0 * current[k - 1] : 0.0);
    for (int k = 0; k < K; ++k) {
      previous[k] = current[k];
      current[k] = next[k];
      monomial[k] += chebyshev[j] * current[k];
    }
  }
}

void check_density(double value) {
  if (!(std::isfinite(value) && value > 0))
    throw std::runtime_error(
        "internal error: the time density of an impact phase is not "
        "finite and positive");
}

} // namespace

PhaseTimeMap::Convergence PhaseTimeMap::build_first_piece(const Density& density, double upper) {
  constexpr int K = first_nodes;
  const auto& cosine = cosine_table<K>();
  // G and the companions at the Chebyshev points of tau in [0, 1], then their Chebyshev
  // coefficients there.
  const double upper_power = std::pow(upper, power_);
  double values[K], companion_values[phase_companions][K];
  for (int k = 0; k < K; ++k) {
    const double tau = 0.5 * (1.0 + cosine[1][k]);
    double companions[phase_companions];
    values[k] = density(upper * std::pow(tau, 1.0 / power_), upper_power * tau, companions);
    check_density(values[k]);
    for (int c = 0; c < phase_companions; ++c) companion_values[c][k] = companions[c];
  }
  evaluations_ += K;
  double chebyshev[K], companion_chebyshev[phase_companions][K];
  Convergence convergence;
  convergence.density = chebyshev_coefficients<K>(values, density_tolerance_, chebyshev);
  for (int c = 0; c < phase_companions; ++c)
    convergence.companions = chebyshev_coefficients<K>(companion_values[c], companion_tolerance_[c],
                                                       companion_chebyshev[c]) &&
                             convergence.companions;
  if (!convergence.density) return convergence;
  double monomial[K];
  monomials<K>(chebyshev, monomial);
  first_upper_ = upper;
  first_upper_power_ = upper_power;
  double at_end = 0;
  for (int k = 0; k < K; ++k) {
    first_density_[k] = monomial[k];
    first_time_[k] = monomial[k] / (k * power_ + 1.0);
    at_end += first_time_[k];
  }
  for (int c = 0; c < phase_companions; ++c)
    monomials<K>(companion_chebyshev[c], first_companions_[c]);
  duration_ = upper * at_end;
  return convergence;
}

PhaseTimeMap::Convergence PhaseTimeMap::build_panel(const Density& density, double lower,
                                                    double upper, Panel& panel) {
  const auto& cosine = cosine_table<m>();
  panel.lower = lower;
  panel.half_width = 0.5 * (upper - lower);
  panel.start_time = duration_;
  // sigma^p at the nodes, for the density and as a series of its own (analytic on the
  // panel, sigma > 0: used, not judged).
  double powers[m];
  for (int k = 0; k < m; ++k)
    powers[k] = std::pow(lower + panel.half_width * (1.0 + cosine[1][k]), power_);
  chebyshev_coefficients<m>(powers, 0.0, panel.sigma_power);
  double values[m], companion_values[phase_companions][m];
  for (int k = 0; k < m; ++k) {
    // Node k at x = cos(pi (k + 1/2) / m), from the right end to the left.
    double companions[phase_companions];
    values[k] = density(lower + panel.half_width * (1.0 + cosine[1][k]), powers[k], companions);
    check_density(values[k]);
    for (int c = 0; c < phase_companions; ++c) companion_values[c][k] = companions[c];
  }
  evaluations_ += m;
  Convergence convergence;
  convergence.density = chebyshev_coefficients<m>(values, density_tolerance_, panel.density);
  for (int c = 0; c < phase_companions; ++c)
    convergence.companions = chebyshev_coefficients<m>(companion_values[c], companion_tolerance_[c],
                                                       panel.companions[c]) &&
                             convergence.companions;
  // Term-by-term integral from x = -1: int T_0 = T_1, int T_1 = T_2 / 4,
  // int T_j = T_(j+1) / (2 (j+1)) - T_(j-1) / (2 (j-1)).
  const double* c = panel.density;
  auto coefficient = [&](int j) { return j < m ? c[j] : 0.0; };
  panel.time[1] = c[0] - 0.5 * coefficient(2);
  for (int j = 2; j <= m; ++j)
    panel.time[j] = (coefficient(j - 1) - coefficient(j + 1)) / (2.0 * j);
  double at_left = 0;
  for (int j = 1; j <= m; ++j) at_left += (j % 2 == 0 ? 1.0 : -1.0) * panel.time[j];
  panel.time[0] = -at_left;
  return convergence;
}

// The companions at panel variable x by Clenshaw's recurrence, the chains interleaved.

} // namespace impact::reduced::detail
