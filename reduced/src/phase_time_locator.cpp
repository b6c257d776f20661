// Locating ascending times on a PhaseTimeMap (phase_time_map.hpp): Newton's method on each
// piece's series, or, on a piece holding more points than its nodes, the Chebyshev series in
// time of sigma and the companions. The series are evaluated for several points or nodes
// at once: Clenshaw's recurrence is a chain of dependent operations, and chains of
// independent points run side by side at little more than the cost of one.

#include "phase_time_map.hpp"

#include "chebyshev_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::reduced::detail {

namespace {

constexpr int m = PhaseTimeMap::nodes;

// sum_{j <= m} t_j T_j(x) and sum_{j < m} d_j T_j(x) at N points by Clenshaw's recurrence.
template <int N>
void time_and_density(const double* t, const double* d, const double (&x)[N], double (&time)[N],
                      double (&density)[N]) {
  double t_next[N], t_after[N] = {}, d_next[N] = {}, d_after[N] = {};
  for (int i = 0; i < N; ++i) t_next[i] = t[m];
  for (int j = m - 1; j >= 1; --j)
    for (int i = 0; i < N; ++i) {
      const double t_current = t[j] + 2 * x[i] * t_next[i] - t_after[i];
      const double d_current = d[j] + 2 * x[i] * d_next[i] - d_after[i];
      t_after[i] = t_next[i];
      t_next[i] = t_current;
      d_after[i] = d_next[i];
      d_next[i] = d_current;
    }
  for (int i = 0; i < N; ++i) {
    time[i] = t[0] + x[i] * t_next[i] - t_after[i];
    density[i] = d[0] + x[i] * d_next[i] - d_after[i];
  }
}

// The quantities c_0, sigma c_1, sigma^(p-1) c_2 (sigma > 0).
PhaseSample quantities(double sigma, double sigma_power, const double (&companions)[3]) {
  static_assert(phase_companions == 3);
  return {{companions[0], sigma * companions[1], sigma_power / sigma * companions[2]}};
}

} // namespace

// The quantities at panel variables x, the companions and sigma^p by Clenshaw's recurrence.
template <int N>
void PhaseTimeMap::panel_samples(const Panel& panel, const double (&x)[N],
                                 PhaseSample (&samples)[N]) const {
  constexpr int n = phase_companions + 1;
  const double* series[n];
  for (int c = 0; c < phase_companions; ++c) series[c] = panel.companions[c];
  series[phase_companions] = panel.sigma_power;
  double next[N][n] = {}, after[N][n] = {};
  for (int j = m - 1; j >= 1; --j)
    for (int i = 0; i < N; ++i)
      for (int c = 0; c < n; ++c) {
        const double current = series[c][j] + 2 * x[i] * next[i][c] - after[i][c];
        after[i][c] = next[i][c];
        next[i][c] = current;
      }
  for (int i = 0; i < N; ++i) {
    double companions[phase_companions];
    for (int c = 0; c < phase_companions; ++c)
      companions[c] = series[c][0] + x[i] * next[i][c] - after[i][c];
    samples[i] = quantities(panel.lower + panel.half_width * (x[i] + 1.0),
                            series[phase_companions][0] + x[i] * next[i][phase_companions] -
                                after[i][phase_companions],
                            companions);
  }
}

// The quantities on the first piece, the companions polynomials in tau by Horner's rule.
PhaseSample PhaseTimeMap::first_piece_sample(double s, double tau) const {
  constexpr int K = first_nodes;
  double sum[phase_companions];
  for (int c = 0; c < phase_companions; ++c) sum[c] = first_companions_[c][K - 1];
  for (int k = K - 2; k >= 0; --k)
    for (int c = 0; c < phase_companions; ++c) sum[c] = sum[c] * tau + first_companions_[c][k];
  return quantities(first_upper_ * s, first_upper_power_ * tau, sum);
}

// t(x) = start_time + half_width T(x), increasing in x on [-1, 1]: Newton's method kept
// inside a shrinking bracket, bisection where a step would leave it, for N times at once
// (x holds the guesses). From a guess within 1e-8 of the root one step reaches the root to
// rounding (quadratic convergence, and t''/t' is of order one in x on a panel).
template <int N>
void PhaseTimeMap::solve_in_panel(const Panel& panel, const double (&times)[N],
                                  double (&x)[N]) const {
  double target[N], low[N], high[N];
  bool solved[N];
  for (int i = 0; i < N; ++i) {
    target[i] = (times[i] - panel.start_time) / panel.half_width;
    low[i] = -1;
    high[i] = 1;
    x[i] = std::clamp(x[i], -1.0, 1.0);
    solved[i] = false;
  }
  for (int iteration = 0; iteration < 100; ++iteration) {
    double value[N], slope[N];
    time_and_density<N>(panel.time, panel.density, x, value, slope);
    bool all_solved = true;
    for (int i = 0; i < N; ++i) {
      if (solved[i]) continue;
      const double residual = value[i] - target[i];
      if (residual == 0) {
        solved[i] = true;
        continue;
      }
      (residual > 0 ? high : low)[i] = x[i];
      double next = x[i] - residual / slope[i];
      const bool newton = next >= low[i] && next <= high[i];
      if (!newton) next = 0.5 * (low[i] + high[i]);
      const double step = next - x[i];
      x[i] = next;
      solved[i] = (newton && std::fabs(step) < 1e-8) ||
                  high[i] - low[i] < 4 * std::numeric_limits<double>::epsilon();
      all_solved = all_solved && solved[i];
    }
    if (all_solved) break;
  }
}

double PhaseTimeMap::panel_end_time(long panel) const {
  return static_cast<std::size_t>(panel) + 1 < panels_.size() ? panels_[panel + 1].start_time
                                                              : duration_;
}

bool PhaseTimeMap::fit_series(const double (&values)[series_count][nodes],
                              const double (&tolerances)[series_count], SampleSeries& series) {
  bool converged = true;
  double coefficients[series_count][nodes];
  series.length = 1;
  for (int c = 0; c < series_count; ++c) {
    converged =
        chebyshev_coefficients<nodes>(values[c], tolerances[c], coefficients[c]) && converged;
    double dropped = 0;
    int length = nodes;
    while (length > 1 && dropped + std::fabs(coefficients[c][length - 1]) <= tolerances[c])
      dropped += std::fabs(coefficients[c][--length]);
    series.length = std::max(series.length, length);
  }
  // The power form by T_(j+1) = 2 y T_j - T_(j-1), each T_j's coefficients in turn.
  const int length = series.length;
  double previous[nodes] = {1.0}, current[nodes] = {0.0, 1.0};
  for (int j = 0; j < length; ++j)
    for (int c = 0; c < series_count; ++c)
      series.coefficients[j][c] = j == 0 ? coefficients[c][0] : j == 1 ? coefficients[c][1] : 0.0;
  for (int j = 2; j < length; ++j) {
    double next[nodes];
    for (int k = 0; k <= j; ++k)
      next[k] = (k > 0 ? 2.0 * current[k - 1] : 0.0) - (k < j - 1 ? previous[k] : 0.0);
    for (int k = 0; k <= j; ++k) {
      previous[k] = current[k];
      current[k] = next[k];
      if (current[k] != 0)
        for (int c = 0; c < series_count; ++c)
          series.coefficients[k][c] += coefficients[c][j] * current[k];
    }
  }
  return converged;
}

// The series at `batch` points y at once, by Horner's rule.
void PhaseTimeMap::evaluate_series(const SampleSeries& series, const double (&y)[batch],
                                   double (&values)[batch][series_count]) {
  double sum[series_count][batch];
  for (int c = 0; c < series_count; ++c)
    for (int i = 0; i < batch; ++i) sum[c][i] = series.coefficients[series.length - 1][c];
  for (int j = series.length - 2; j >= 0; --j)
    for (int c = 0; c < series_count; ++c)
      for (int i = 0; i < batch; ++i) sum[c][i] = sum[c][i] * y[i] + series.coefficients[j][c];
  for (int i = 0; i < batch; ++i)
    for (int c = 0; c < series_count; ++c) values[i][c] = sum[c][i];
}

// sigma and the companions as functions of t on the panel: their values at the Chebyshev
// points of the panel's time range, by Newton's method on the panel's series (all nodes at
// once, from the node's own y: t is nearly linear in x), and their series; false if those
// of sigma do not decay to 1e-14 of the panel's half width (its values carry rounding
// errors of a few 1e-16 of it, which is the floor of the coefficients; the state then lies
// within 1e-14 of a half panel from the exact one, a time error below 1e-14 of the panel's
// duration) or a companion's not to its tolerance (the inverse is then not used).
bool PhaseTimeMap::build_inverse(const Panel& panel, double end_time, SampleSeries& inverse) const {
  const auto& cosine = cosine_table<m>();
  double times[m], x[m];
  for (int k = 0; k < m; ++k) {
    x[k] = cosine[1][k];
    times[k] = panel.start_time + 0.5 * (end_time - panel.start_time) * (1 + x[k]);
  }
  solve_in_panel<m>(panel, times, x);
  PhaseSample samples[m];
  panel_samples<m>(panel, x, samples);
  double values[series_count][nodes];
  for (int k = 0; k < m; ++k)
    for (int c = 0; c < series_count; ++c) values[c][k] = samples[k].quantities[c];
  // sigma <= 1: a quantity's error is at most its companion's.
  return fit_series(values, companion_tolerance_, inverse);
}

// t = sigma Q(tau), dt/dsigma = G(tau), tau = (sigma / sigma_0)^p, Newton's method in
// s = sigma / sigma_0 in [0, 1] as on a panel. Returns s and its tau.
double PhaseTimeMap::solve_in_first_piece(double time, double guess, double& tau) const {
  constexpr int K = first_nodes;
  auto horner = [](const double* c, double t) {
    double sum = c[K - 1];
    for (int k = K - 2; k >= 0; --k) sum = sum * t + c[k];
    return sum;
  };
  // tau = s^p after a step s -> s + step: one power at the start, then (1 + e)^p by its
  // binomial series for |e| = |step / s| < 1e-3 (five terms: error below e^6 < 1e-18).
  const double p = power_;
  auto rescale = [p](double tau_before, double e) {
    return tau_before * (1 + p * e *
                                 (1 + (p - 1) / 2 * e *
                                          (1 + (p - 2) / 3 * e *
                                                   (1 + (p - 3) / 4 * e * (1 + (p - 4) / 5 * e)))));
  };
  const double target = time / first_upper_;
  double low = 0, high = 1;
  double s = std::clamp(guess, 0.0, 1.0);
  tau = std::pow(s, p);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double residual = s * horner(first_time_, tau) - target;
    if (residual == 0) break;
    (residual > 0 ? high : low) = s;
    double next = s - residual / horner(first_density_, tau);
    const bool newton = next >= low && next <= high;
    if (!newton) next = 0.5 * (low + high);
    const double step = next - s;
    tau = s > 0 && std::fabs(step) < 1e-3 * s ? rescale(tau, step / s) : std::pow(next, p);
    s = next;
    if ((newton && std::fabs(step) < 1e-8 * s) ||
        high - low < 4 * std::numeric_limits<double>::epsilon() * high)
      break;
  }
  return s;
}

// The first piece's inverse (see the header): R and the companions at the Chebyshev points
// of w, each by Newton's method from the previous node's solution.
bool PhaseTimeMap::build_first_inverse(double first_end, SampleSeries& inverse) const {
  const auto& cosine = cosine_table<m>();
  double values[series_count][nodes];
  double guess = 0.5;
  for (int k = m - 1; k >= 0; --k) { // ascending w
    const double w = 0.5 * (1.0 + cosine[1][k]);
    const double u = std::pow(w, 1.0 / power_);
    double tau;
    const double s = solve_in_first_piece(u * first_end, guess, tau);
    guess = s;
    const PhaseSample sample = first_piece_sample(s, tau);
    values[0][k] = sample.quantities[0];
    values[1][k] = sample.quantities[1] / u;
    values[2][k] = sample.quantities[2] * u / w;
  }
  // u <= 1: a quantity's error is at most that of its ratio to u^(e_k).
  return fit_series(values, companion_tolerance_, inverse);
}

PhaseTimeMap::Locator::Locator(const PhaseTimeMap& map)
    : map_(map),
      first_end_(map.first_upper_ > 0 ? map.first_upper_ *
                                            [&] {
                                              double sum = 0;
                                              for (double c : map.first_time_) sum += c;
                                              return sum;
                                            }()
                                      : 0.0) {}

// Piece -1 is the first piece, 0, 1, ... the panels.
long PhaseTimeMap::Locator::piece_of(double time) const {
  long piece = piece_ >= -1 ? piece_ : (map_.first_upper_ > 0 ? -1 : 0);
  if (piece < 0 && time > first_end_ && !map_.panels_.empty()) piece = 0;
  while (piece >= 0 && static_cast<std::size_t>(piece) + 1 < map_.panels_.size() &&
         time > map_.panels_[piece + 1].start_time)
    ++piece;
  return piece;
}

double PhaseTimeMap::Locator::piece_start(long piece) const {
  return piece < 0 ? 0.0 : map_.panels_[piece].start_time;
}

double PhaseTimeMap::Locator::piece_end(long piece) const {
  return piece < 0 ? first_end_ : map_.panel_end_time(piece);
}

bool PhaseTimeMap::Locator::last_piece(long piece) const {
  return static_cast<std::size_t>(piece + 1) == map_.panels_.size();
}

// A piece expected to hold more than `nodes` points gets its series in time, so that each
// point costs five series instead of Newton's method and the piece's series.
void PhaseTimeMap::Locator::enter(long piece, double time, double spacing) {
  piece_ = piece;
  known_ = 0;
  const double end = piece_end(piece);
  use_inverse_ = spacing > 0 && std::floor((end - time) / spacing) + 1 > nodes &&
                 (piece < 0 ? map_.build_first_inverse(first_end_, inverse_)
                            : map_.build_inverse(map_.panels_[piece], end, inverse_));
}

// Newton's method from the quadratic extrapolation in time of the last (up to) three
// solutions in the piece (the solution is smooth in t within a piece): error O(h^3), so that
// one or two steps suffice.
PhaseSample PhaseTimeMap::Locator::newton_sample(double time) {
  double guess;
  if (known_ == 0) {
    guess = piece_ < 0
                ? time / first_end_ // t is nearly linear in sigma
                : -1 + 2 * (time - piece_start(piece_)) / (piece_end(piece_) - piece_start(piece_));
  } else if (known_ == 1) {
    guess = known_x_[0];
  } else {
    guess = 0;
    for (int a = 0; a < known_; ++a) {
      double weight = 1;
      for (int b = 0; b < known_; ++b)
        if (b != a) weight *= (time - known_time_[b]) / (known_time_[a] - known_time_[b]);
      guess += weight * known_x_[a];
    }
  }
  PhaseSample sample;
  double x;
  if (piece_ < 0) {
    double tau;
    x = map_.solve_in_first_piece(time, guess, tau);
    sample = map_.first_piece_sample(x, tau);
  } else {
    const Panel& panel = map_.panels_[piece_];
    const double times[1] = {time};
    double solution[1] = {guess};
    map_.solve_in_panel<1>(panel, times, solution);
    PhaseSample samples[1];
    map_.panel_samples<1>(panel, solution, samples);
    x = solution[0];
    sample = samples[0];
  }
  if (known_ == 3) {
    for (int a = 0; a < 2; ++a) {
      known_time_[a] = known_time_[a + 1];
      known_x_[a] = known_x_[a + 1];
    }
    --known_;
  }
  known_time_[known_] = time;
  known_x_[known_] = x;
  ++known_;
  return sample;
}

// On the first piece, with u = t / t(first end) and w = u^p, the series in w give q_k / u^(e_k)
// (one power per point); on a panel the series are in t.
void PhaseTimeMap::Locator::inverse_samples(const double* times, int count,
                                            PhaseSample* samples) const {
  double y[batch], u[batch], w[batch];
  for (int i = 0; i < batch; ++i) {
    const double time = times[std::min(i, count - 1)];
    if (piece_ < 0) {
      u[i] = std::min(time / first_end_, 1.0);
      w[i] = std::pow(u[i], map_.power_);
      y[i] = 2 * w[i] - 1;
    } else {
      const double start = piece_start(piece_);
      y[i] = std::clamp(2 * (time - start) / (piece_end(piece_) - start) - 1, -1.0, 1.0);
    }
  }
  double values[batch][series_count];
  evaluate_series(inverse_, y, values);
  for (int i = 0; i < count; ++i) {
    PhaseSample& sample = samples[i];
    for (int c = 0; c < phase_companions; ++c) sample.quantities[c] = values[i][c];
    if (piece_ < 0) {
      sample.quantities[1] *= u[i];
      sample.quantities[2] *= w[i] / u[i];
    }
  }
}

void PhaseTimeMap::Locator::locate(const double* times, int count, double spacing,
                                   PhaseSample* samples) {
  int first = 0;
  while (first < count) {
    const long piece = piece_of(times[first]);
    if (piece != piece_) enter(piece, times[first], spacing);
    // The points of this batch in the same piece.
    const double end = piece_end(piece);
    int after = first + 1;
    while (after < count && (last_piece(piece) || times[after] <= end)) ++after;
    if (use_inverse_) {
      inverse_samples(times + first, after - first, samples + first);
    } else {
      for (int i = first; i < after; ++i) samples[i] = newton_sample(times[i]);
    }
    first = after;
  }
}

} // namespace impact::reduced::detail
