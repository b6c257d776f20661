#include "phase_time_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace impact::reduced::detail {

namespace {

constexpr int m = PhaseTimeMap::nodes;

// cos(pi j (k + 1/2) / m): the Chebyshev points of the first kind (j = 1) and the discrete
// cosine transform that turns values there into coefficients. Computed once.
const std::array<std::array<double, m>, m>& cosine_table() {
  static const auto table = [] {
    std::array<std::array<double, m>, m> values{};
    const double pi = std::acos(-1.0);
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) values[j][k] = std::cos(pi * j * (k + 0.5) / m);
    return values;
  }();
  return table;
}

// sum_{j <= m} t_j T_j(x) and sum_{j < m} d_j T_j(x) by Clenshaw's recurrence, the two
// recurrences interleaved (independent chains: about the cost of one).
void time_and_density(const double* t, const double* d, double x, double& time,
                      double& density) {
  double t_next = t[m], t_after = 0, d_next = 0, d_after = 0;
  for (int j = m - 1; j >= 1; --j) {
    const double t_current = t[j] + 2 * x * t_next - t_after;
    const double d_current = d[j] + 2 * x * d_next - d_after;
    t_after = t_next;
    t_next = t_current;
    d_after = d_next;
    d_next = d_current;
  }
  time = t[0] + x * t_next - t_after;
  density = d[0] + x * d_next - d_after;
}

} // namespace

PhaseTimeMap::PhaseTimeMap(const Density& density, double power, double tolerance)
  : power_(power) {
  double middle[phase_companions], end[phase_companions];
  density_tolerance_ = tolerance * density(0.5, middle);
  density(1.0, end);
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

// The Chebyshev coefficients of the values at the K points cos(pi (k + 1/2) / K), and
// whether the last three are within `tolerance`.
template <int K>
bool chebyshev_coefficients(const double* values,
                            const std::array<std::array<double, K>, K>& cosine,
                            double tolerance, double* coefficients) {
  for (int j = 0; j < K; ++j) {
    double sum = 0;
    for (int k = 0; k < K; ++k) sum += values[k] * cosine[j][k];
    coefficients[j] = (j == 0 ? 1.0 : 2.0) * sum / K;
  }
  const double tail = std::fabs(coefficients[K - 1]) + std::fabs(coefficients[K - 2]) +
                      std::fabs(coefficients[K - 3]);
  return tail <= tolerance;
}

template <int K>
std::array<std::array<double, K>, K> make_cosine_table() {
  std::array<std::array<double, K>, K> values{};
  const double pi = std::acos(-1.0);
  for (int j = 0; j < K; ++j)
    for (int k = 0; k < K; ++k) values[j][k] = std::cos(pi * j * (k + 0.5) / K);
  return values;
}

void check_density(double value) {
  if (!(std::isfinite(value) && value > 0))
    throw std::runtime_error("internal error: the time density of an impact phase is not "
                             "finite and positive");
}

} // namespace

PhaseTimeMap::Convergence PhaseTimeMap::build_first_piece(const Density& density,
                                                          double upper) {
  constexpr int K = first_nodes;
  static const auto cosine = make_cosine_table<K>();
  // G and the companions at the Chebyshev points of tau in [0, 1], then their Chebyshev
  // coefficients there.
  double values[K], companion_values[phase_companions][K];
  for (int k = 0; k < K; ++k) {
    const double tau = 0.5 * (1.0 + cosine[1][k]);
    double companions[phase_companions];
    values[k] = density(upper * std::pow(tau, 1.0 / power_), companions);
    check_density(values[k]);
    for (int c = 0; c < phase_companions; ++c) companion_values[c][k] = companions[c];
  }
  evaluations_ += K;
  double chebyshev[K], companion_chebyshev[phase_companions][K];
  Convergence convergence;
  convergence.density = chebyshev_coefficients<K>(values, cosine, density_tolerance_, chebyshev);
  for (int c = 0; c < phase_companions; ++c)
    convergence.companions = chebyshev_coefficients<K>(companion_values[c], cosine,
                                                       companion_tolerance_[c],
                                                       companion_chebyshev[c]) &&
                             convergence.companions;
  if (!convergence.density) return convergence;
  double monomial[K];
  monomials<K>(chebyshev, monomial);
  first_upper_ = upper;
  first_upper_power_ = std::pow(upper, power_);
  double at_end = 0;
  for (int k = 0; k < K; ++k) {
    first_density_[k] = monomial[k];
    first_time_[k] = monomial[k] / (k * power_ + 1.0);
    at_end += first_time_[k];
  }
  for (int c = 0; c < phase_companions; ++c) monomials<K>(companion_chebyshev[c], first_companions_[c]);
  duration_ = upper * at_end;
  return convergence;
}

PhaseTimeMap::Convergence PhaseTimeMap::build_panel(const Density& density, double lower,
                                                    double upper, Panel& panel) {
  const auto& cosine = cosine_table();
  panel.lower = lower;
  panel.half_width = 0.5 * (upper - lower);
  panel.start_time = duration_;
  double values[m], companion_values[phase_companions][m];
  for (int k = 0; k < m; ++k) {
    // Node k at x = cos(pi (k + 1/2) / m), from the right end to the left.
    double companions[phase_companions];
    values[k] = density(lower + panel.half_width * (1.0 + cosine[1][k]), companions);
    check_density(values[k]);
    for (int c = 0; c < phase_companions; ++c) companion_values[c][k] = companions[c];
  }
  evaluations_ += m;
  Convergence convergence;
  convergence.density =
      chebyshev_coefficients<m>(values, cosine, density_tolerance_, panel.density);
  for (int c = 0; c < phase_companions; ++c)
    convergence.companions = chebyshev_coefficients<m>(companion_values[c], cosine,
                                                       companion_tolerance_[c],
                                                       panel.companions[c]) &&
                             convergence.companions;
  // sigma^p, analytic on the panel (sigma > 0): its series is used, not judged.
  double powers[m];
  for (int k = 0; k < m; ++k)
    powers[k] = std::pow(lower + panel.half_width * (1.0 + cosine[1][k]), power_);
  chebyshev_coefficients<m>(powers, cosine, 0.0, panel.sigma_power);
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
PhaseSample PhaseTimeMap::panel_sample(const Panel& panel, double x) const {
  constexpr int n = phase_companions + 1;
  const double* series[n];
  for (int c = 0; c < phase_companions; ++c) series[c] = panel.companions[c];
  series[phase_companions] = panel.sigma_power;
  double next[n] = {}, after[n] = {};
  for (int j = m - 1; j >= 1; --j)
    for (int c = 0; c < n; ++c) {
      const double current = series[c][j] + 2 * x * next[c] - after[c];
      after[c] = next[c];
      next[c] = current;
    }
  PhaseSample sample;
  sample.sigma = panel.lower + panel.half_width * (x + 1.0);
  sample.sigma_power = series[phase_companions][0] + x * next[phase_companions] -
                       after[phase_companions];
  for (int c = 0; c < phase_companions; ++c)
    sample.companions[c] = series[c][0] + x * next[c] - after[c];
  return sample;
}

// The companions on the first piece, polynomials in tau, by Horner's rule.
PhaseSample PhaseTimeMap::first_piece_sample(double s, double tau) const {
  constexpr int K = first_nodes;
  double sum[phase_companions];
  for (int c = 0; c < phase_companions; ++c) sum[c] = first_companions_[c][K - 1];
  for (int k = K - 2; k >= 0; --k)
    for (int c = 0; c < phase_companions; ++c) sum[c] = sum[c] * tau + first_companions_[c][k];
  PhaseSample sample;
  sample.sigma = first_upper_ * s;
  sample.sigma_power = first_upper_power_ * tau;
  for (int c = 0; c < phase_companions; ++c) sample.companions[c] = sum[c];
  return sample;
}

double PhaseTimeMap::solve_in_panel(const Panel& panel, double time, double guess) const {
  // t(x) = start_time + half_width T(x), increasing in x on [-1, 1]: Newton's method kept
  // inside a shrinking bracket, bisection where a step would leave it. From a guess within
  // 1e-8 of the root one step reaches the root to rounding (quadratic convergence, and
  // t''/t' is of order one in x on a panel).
  const double target = (time - panel.start_time) / panel.half_width;
  double low = -1, high = 1;
  double x = std::clamp(guess, -1.0, 1.0);
  for (int iteration = 0; iteration < 100; ++iteration) {
    double value, slope;
    time_and_density(panel.time, panel.density, x, value, slope);
    const double residual = value - target;
    if (residual == 0) break;
    (residual > 0 ? high : low) = x;
    double next = x - residual / slope;
    const bool newton = next >= low && next <= high;
    if (!newton) next = 0.5 * (low + high);
    const double step = next - x;
    x = next;
    if ((newton && std::fabs(step) < 1e-8) ||
        high - low < 4 * std::numeric_limits<double>::epsilon())
      break;
  }
  return x;
}

double PhaseTimeMap::panel_end_time(long panel) const {
  return static_cast<std::size_t>(panel) + 1 < panels_.size() ? panels_[panel + 1].start_time
                                                             : duration_;
}

bool PhaseTimeMap::fit_series(const double (&values)[series_count][nodes],
                              const double (&tolerances)[series_count], SampleSeries& series) {
  const auto& cosine = cosine_table();
  bool converged = true;
  series.length = 1;
  for (int c = 0; c < series_count; ++c) {
    double coefficients[nodes];
    converged = chebyshev_coefficients<nodes>(values[c], cosine, tolerances[c], coefficients) &&
                converged;
    double dropped = 0;
    int length = nodes;
    while (length > 1 && dropped + std::fabs(coefficients[length - 1]) <= tolerances[c])
      dropped += std::fabs(coefficients[--length]);
    series.length = std::max(series.length, length);
    for (int j = 0; j < nodes; ++j) series.coefficients[j][c] = coefficients[j];
  }
  for (int j = 0; j < nodes; ++j) series.coefficients[j][series_count] = 0;
  return converged;
}

void PhaseTimeMap::evaluate_series(const SampleSeries& series, double y,
                                   double (&values)[series_count]) {
  constexpr int width = series_count + 1;
  double next[width] = {}, after[width] = {};
  for (int j = series.length - 1; j >= 1; --j)
    for (int c = 0; c < width; ++c) {
      const double current = series.coefficients[j][c] + 2 * y * next[c] - after[c];
      after[c] = next[c];
      next[c] = current;
    }
  for (int c = 0; c < series_count; ++c)
    values[c] = series.coefficients[0][c] + y * next[c] - after[c];
}

// sigma and the companions as functions of t on the panel: their values at the Chebyshev
// points of the panel's time range, by Newton's method on the panel's series, and their
// series; false if those of sigma do not decay to 1e-14 of the panel's half width (its
// values carry rounding errors of a few 1e-16 of it, which is the floor of the
// coefficients; the state then lies within 1e-14 of a half panel from the exact one, a time
// error below 1e-14 of the panel's duration) or a companion's not to its tolerance (the
// inverse is then not used).
bool PhaseTimeMap::build_inverse(const Panel& panel, double end_time,
                                 SampleSeries& inverse) const {
  const auto& cosine = cosine_table();
  double values[series_count][nodes];
  // Newton's method from the quadratic extrapolation of the last three nodes' solutions
  // (from the node's own y, t being nearly linear in x, for the first two).
  double known_time[3], known_x[3];
  for (int k = 0; k < m; ++k) {
    const double y = cosine[1][k];
    const double time = panel.start_time + 0.5 * (end_time - panel.start_time) * (1 + y);
    double guess = y;
    if (k >= 3) {
      guess = 0;
      for (int a = 0; a < 3; ++a) {
        double weight = 1;
        for (int b = 0; b < 3; ++b)
          if (b != a) weight *= (time - known_time[b]) / (known_time[a] - known_time[b]);
        guess += weight * known_x[a];
      }
    }
    const double x = solve_in_panel(panel, time, guess);
    known_time[k % 3] = time;
    known_x[k % 3] = x;
    const PhaseSample sample = panel_sample(panel, x);
    values[0][k] = sample.sigma;
    values[1][k] = sample.sigma_power;
    for (int c = 0; c < phase_companions; ++c) values[c + 2][k] = sample.companions[c];
  }
  double tolerances[series_count] = {1e-14 * panel.half_width, 1e-14 * values[1][0]};
  for (int c = 0; c < phase_companions; ++c) tolerances[c + 2] = companion_tolerance_[c];
  return fit_series(values, tolerances, inverse);
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
    return tau_before *
           (1 + p * e *
                    (1 + (p - 1) / 2 * e *
                             (1 + (p - 2) / 3 * e * (1 + (p - 3) / 4 * e * (1 + (p - 4) / 5 * e)))));
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

bool PhaseTimeMap::build_first_inverse(double first_end, SampleSeries& inverse) const {
  const auto& cosine = cosine_table();
  double values[series_count][nodes];
  double guess = 0.5;
  for (int k = m - 1; k >= 0; --k) { // ascending w
    const double w = 0.5 * (1.0 + cosine[1][k]);
    const double u = std::pow(w, 1.0 / power_);
    double tau;
    const double s = solve_in_first_piece(u * first_end, guess, tau);
    guess = s;
    values[0][k] = s / u;
    values[1][k] = tau / w;
    const PhaseSample sample = first_piece_sample(s, tau);
    for (int c = 0; c < phase_companions; ++c) values[c + 2][k] = sample.companions[c];
  }
  double tolerances[series_count] = {1e-14 * std::fabs(values[0][0]),
                                     1e-14 * std::fabs(values[1][0])};
  for (int c = 0; c < phase_companions; ++c) tolerances[c + 2] = companion_tolerance_[c];
  return fit_series(values, tolerances, inverse);
}

PhaseSample PhaseTimeMap::first_inverse_sample(const SampleSeries& inverse, double u) const {
  const double w = std::pow(u, power_);
  double values[series_count];
  evaluate_series(inverse, 2 * w - 1, values);
  PhaseSample sample;
  sample.sigma = first_upper_ * u * values[0];
  sample.sigma_power = first_upper_power_ * w * values[1];
  for (int c = 0; c < phase_companions; ++c) sample.companions[c] = values[c + 2];
  return sample;
}

std::vector<PhaseSample> PhaseTimeMap::locate(const std::vector<double>& times) const {
  std::vector<PhaseSample> samples;
  samples.reserve(times.size());
  // Piece -1 is the first piece, 0, 1, ... the panels.
  const double first_end = first_upper_ > 0 ? first_upper_ *
      [&] { double sum = 0; for (double c : first_time_) sum += c; return sum; }() : 0.0;
  long piece = first_upper_ > 0 ? -1 : 0;
  // The last (up to) three solutions in the current piece predict the next one by
  // quadratic extrapolation in time (the solution is smooth in t within a piece): error
  // O(h^3), so that Newton's method needs one or two steps.
  double known_time[3], known_x[3];
  int known = 0;
  // A panel holding more points than nodes gets the Chebyshev series in time of sigma and of
  // the companions, so that each point costs five independent series instead of
  // Newton's method and the panel's series.
  SampleSeries inverse;
  bool use_inverse = false;
  SampleSeries first_inverse;
  bool use_first_inverse = false;
  if (piece < 0) {
    std::size_t count = 0;
    while (count < times.size() && times[count] <= first_end && count <= nodes) ++count;
    use_first_inverse = count > nodes && build_first_inverse(first_end, first_inverse);
  }
  for (std::size_t index = 0; index < times.size(); ++index) {
    const double time = times[index];
    const long before = piece;
    if (piece < 0 && time > first_end && !panels_.empty()) piece = 0;
    while (piece >= 0 && static_cast<std::size_t>(piece) + 1 < panels_.size() &&
           time > panels_[piece + 1].start_time)
      ++piece;
    if (piece != before) {
      known = 0;
      use_inverse = false;
      if (piece >= 0) {
        const double end = panel_end_time(piece);
        std::size_t count = 0;
        while (index + count < times.size() && times[index + count] <= end && count <= nodes)
          ++count;
        use_inverse = count > nodes && build_inverse(panels_[piece], end, inverse);
      }
    }
    if (piece < 0 && use_first_inverse) {
      samples.push_back(first_inverse_sample(first_inverse, std::min(time / first_end, 1.0)));
      continue;
    }
    if (use_inverse) {
      const Panel& panel = panels_[piece];
      const double y =
          2 * (time - panel.start_time) / (panel_end_time(piece) - panel.start_time) - 1;
      double values[series_count];
      evaluate_series(inverse, std::clamp(y, -1.0, 1.0), values);
      PhaseSample sample;
      sample.sigma = values[0];
      sample.sigma_power = values[1];
      for (int c = 0; c < phase_companions; ++c) sample.companions[c] = values[c + 2];
      samples.push_back(sample);
      continue;
    }
    double guess;
    if (known == 0) {
      guess = 0.0;
    } else if (known == 1) {
      guess = known_x[0];
    } else {
      guess = 0;
      for (int a = 0; a < known; ++a) {
        double weight = 1;
        for (int b = 0; b < known; ++b)
          if (b != a) weight *= (time - known_time[b]) / (known_time[a] - known_time[b]);
        guess += weight * known_x[a];
      }
    }
    double x;
    if (piece < 0) {
      if (known == 0) guess = time / first_end; // t is nearly linear in sigma
      double tau;
      x = solve_in_first_piece(time, guess, tau);
      samples.push_back(first_piece_sample(x, tau));
    } else {
      const Panel& panel = panels_[piece];
      if (known == 0)
        guess = -1 + 2 * (time - panel.start_time) / (panel_end_time(piece) - panel.start_time);
      x = solve_in_panel(panel, time, guess);
      samples.push_back(panel_sample(panel, x));
    }
    if (known == 3) {
      for (int a = 0; a < 2; ++a) {
        known_time[a] = known_time[a + 1];
        known_x[a] = known_x[a + 1];
      }
      --known;
    }
    known_time[known] = time;
    known_x[known] = x;
    ++known;
  }
  return samples;
}

} // namespace impact::reduced::detail
