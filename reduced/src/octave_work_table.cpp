#include "octave_work_table.hpp"

#include "impact_reduced/elastic_plastic_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace impact::reduced::detail {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double half_log_two = 0.34657359027997265471; // ln(2) / 2: dx/dt = x ln(2) / 2

// Chebyshev sum of coefficients c_0 .. c_(n-1) at t in [-1, 1] (Clenshaw).
double chebyshev_sum(const double* coefficients, std::size_t n, double t) {
  double next = 0, current = 0;
  for (std::size_t m = n; m-- > 1;) {
    const double previous = 2 * t * current - next + coefficients[m];
    next = current;
    current = previous;
  }
  return t * current - next + coefficients[0];
}

// cos(pi k / 64), k = 0 .. 127: the cosines of every Chebyshev-Lobatto transform used here
// (n = 16, 32, 64 points: cos(pi k / n) is entry k 64 / n).
const std::array<double, 128>& lobatto_cosines() {
  static const std::array<double, 128> table = [] {
    std::array<double, 128> values{};
    for (std::size_t k = 0; k < values.size(); ++k)
      values[k] = std::cos(pi * static_cast<double>(k) / 64.0);
    return values;
  }();
  return table;
}

// sum_m c_m (T_m(a) - T_m(b)) for a - b = gap >= 0 given: D_m = T_m(a) - T_m(b) satisfies
// D_(m+1) = 2 a D_m + 2 gap T_m(b) - D_(m-1), D_0 = 0, D_1 = gap, so that every term is
// formed from the gap and no difference of two close sums is taken.
double chebyshev_difference(const double* coefficients, std::size_t n, double a, double b,
                            double gap) {
  if (n < 2 || gap == 0) return 0.0;
  double previous_difference = 0, difference = gap; // D_0, D_1
  double previous_value = 1, value = b;             // T_0(b), T_1(b)
  double sum = coefficients[1] * difference;
  for (std::size_t m = 1; m + 1 < n; ++m) {
    const double next_difference = 2 * a * difference + 2 * gap * value - previous_difference;
    const double next_value = 2 * b * value - previous_value;
    previous_difference = difference;
    difference = next_difference;
    previous_value = value;
    value = next_value;
    sum += coefficients[m + 1] * difference;
  }
  return sum;
}

constexpr double two_over_log_two = 2.8853900817779268147; // dt/d(ln x) = 2 / ln 2

// An octave's series at t in one pass: W - W(lower), G = dW/dt and G' = dG/dt, from the
// forward recurrences T_(k+1) = 2 t T_k - T_(k-1) and U_(k+1) = 2 t U_k - U_(k-1)
// (T_k' = k U_(k-1)), stable on [-1, 1]; the three sums share them. With `Curvature` also
// G'' = sum c_k k U_(k-1)', U_(k+1)' = 2 U_k + 2 t U_k' - U_(k-1)'.
struct OctavePoint {
  double work;
  double density;
  double density_slope;
  double density_curvature; // 0 unless asked for
};

template <bool Curvature, class Piece>
OctavePoint evaluate_octave(const Piece& piece, double t) {
  const std::size_t n = piece.size; // density: c_0 .. c_(n-1); integral: C_0 .. C_n
  double work = piece.integral[0] + piece.integral[1] * t;
  double density = piece.density[0] + piece.density[1] * t;
  double density_slope = piece.density[1];
  double density_curvature = 0;
  double previous = 1, current = t;         // T_(k-1), T_k for k = 1
  double previous_u = 1, current_u = 2 * t; // U_(k-2), U_(k-1) for k = 2
  double previous_du = 0, current_du = 2;   // their derivatives
  for (std::size_t k = 2; k <= n; ++k) {
    const double next = 2 * t * current - previous; // T_k
    previous = current;
    current = next;
    work += piece.integral[k] * next;
    if (k < n) {
      density += piece.density[k] * next;
      density_slope += piece.density[k] * static_cast<double>(k) * current_u; // k U_(k-1)
      if (Curvature) density_curvature += piece.density[k] * static_cast<double>(k) * current_du;
    }
    if (Curvature) {
      const double next_du = 2 * current_u + 2 * t * current_du - previous_du; // U_k'
      previous_du = current_du;
      current_du = next_du;
    }
    const double next_u = 2 * t * current_u - previous_u; // U_k
    previous_u = current_u;
    current_u = next_u;
  }
  return {work, density, density_slope, density_curvature};
}

// Newton in t on an octave's series of W - W(lower) (increasing: its slope G > 0) for the
// value `target`, from `guess`, safeguarded by bisection on [low, high]. It stops once a step
// is within a few ulps of t, a Newton step is below 1e-9 (its error is then of order
// (G' / 2G) 1e-18: the series grow like exp(t), so G' / G is of order 1), or the residual is 0.
// Returns t and G there (after a Newton step d, G + G' d: its error is of order d^2), and with
// `Curvature` G' there (G' + G'' d).
struct Solved {
  double t;
  double density;
  double density_slope; // with Curvature only
};

template <bool Curvature = false, class Piece>
Solved solve_octave(const Piece& piece, double target, double guess) {
  double low = -1, high = 1;
  double t = std::clamp(guess, -1.0, 1.0);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const OctavePoint point = evaluate_octave<Curvature>(piece, t);
    const double residual = point.work - target;
    if (residual == 0) return {t, point.density, point.density_slope};
    (residual < 0 ? low : high) = t;
    double next = t - residual / point.density;
    const bool newton = next > low && next < high;
    if (!newton) next = 0.5 * (low + high);
    const bool done = std::abs(next - t) <= 4 * std::numeric_limits<double>::epsilon() ||
                      high - low <= 4 * std::numeric_limits<double>::epsilon() ||
                      (newton && std::abs(next - t) <= 1e-9);
    if (done)
      return {next, point.density + point.density_slope * (next - t),
              point.density_slope + point.density_curvature * (next - t)};
    t = next;
  }
  const OctavePoint point = evaluate_octave<Curvature>(piece, t);
  return {t, point.density, point.density_slope};
}

// The Chebyshev coefficients c_0 .. c_m of the interpolant of the values at the m + 1
// Chebyshev-Lobatto points cos(pi j / m), m in {8, 16, 32, 64}.
void lobatto_series(const double* values, std::size_t m, double* coefficients) {
  const auto& cosines = lobatto_cosines();
  const std::size_t stride = 64 / m;
  for (std::size_t k = 0; k <= m; ++k) {
    double sum = 0;
    for (std::size_t j = 0; j <= m; ++j) {
      const double term = values[j] * cosines[(k * j % (2 * m)) * stride];
      sum += j == 0 || j == m ? 0.5 * term : term;
    }
    coefficients[k] = 2 * sum / static_cast<double>(m);
  }
  coefficients[0] *= 0.5;
  coefficients[m] *= 0.5;
}

} // namespace

OctaveWorkTable::OctaveWorkTable(double start_approach, double start_work)
    : start_approach_(start_approach),
      start_work_(start_work),
      published_(new std::atomic<const Octave*>[max_octaves]) {
  for (std::size_t k = 0; k < max_octaves; ++k) published_[k].store(nullptr);
}

// Chebyshev-Lobatto interpolation of G(t) = F(x(t)) dx/dt, x = lower 2^((t + 1) / 2), at
// 17, 33, then 65 points (nested: each doubling reuses the values), until the last two
// coefficients are below 1e-15 of the first (they fall by about 30 per degree on the fits,
// so the neglected tail is below the rounding of the sum); the work is G's exact
// antiderivative.
OctaveWorkTable::Octave OctaveWorkTable::build(double lower, double work_start,
                                               const Force& force) const {
  Octave result{};
  result.lower = lower;
  result.work_start = work_start;
  std::vector<double> values; // G at t_j = cos(pi j / n), j = 0 .. n
  auto density = [&](double t) {
    const double x = lower * std::exp2(0.5 * (t + 1));
    return force(x) * x * half_log_two;
  };
  const auto& cosines = lobatto_cosines();
  for (std::size_t n = 16; n + 1 <= max_degree; n *= 2) {
    const std::size_t stride = 64 / n;
    std::vector<double> refined(n + 1);
    for (std::size_t j = 0; j <= n; ++j)
      refined[j] = j % 2 == 0 && !values.empty() ? values[j / 2] : density(cosines[j * stride]);
    values = std::move(refined);
    // c_m = (2/n) sum'' G_j cos(pi m j / n), the end terms halved, and c_0, c_n halved.
    for (std::size_t m = 0; m <= n; ++m) {
      double sum = 0;
      for (std::size_t j = 0; j <= n; ++j) {
        const double term = values[j] * cosines[(m * j % (2 * n)) * stride];
        sum += j == 0 || j == n ? 0.5 * term : term;
      }
      result.density[m] = 2 * sum / static_cast<double>(n);
    }
    result.density[0] *= 0.5;
    result.density[n] *= 0.5;
    result.size = n + 1;
    const double scale = std::abs(result.density[0]);
    if (std::abs(result.density[n]) <= 1e-15 * scale &&
        std::abs(result.density[n - 1]) <= 1e-15 * scale)
      break;
    if (2 * n + 1 > max_degree)
      throw std::runtime_error("the loading work's series does not converge on an octave");
  }
  // Antiderivative: C_m = (c_(m-1) - c_(m+1)) / (2 m), C_0 such that it vanishes at t = -1.
  const std::size_t n = result.size;
  for (std::size_t m = 1; m <= n; ++m) {
    const double above = m + 1 < n ? result.density[m + 1] : 0.0;
    result.integral[m] =
        ((m == 1 ? 2 * result.density[0] : result.density[m - 1]) - above) / (2.0 * m);
  }
  double at_minus_one = 0;
  for (std::size_t m = 1; m <= n; ++m)
    at_minus_one += (m % 2 == 0 ? 1.0 : -1.0) * result.integral[m];
  result.integral[0] = -at_minus_one;
  result.work_end = work_start + chebyshev_sum(result.integral.data(), n + 1, 1.0);
  build_parts(result);
  return result;
}

// On each of eight equal parts of the octave's work: t at the 9 Chebyshev-Lobatto points of
// the part's normalised work (by Newton from the linear guess) and their series (the
// inverse's guess); then t at the 8 points between them (by Newton from that guess: one or
// two evaluations each) and the series of F from all 17.
void OctaveWorkTable::build_parts(Octave& result) {
  const auto& cosines = lobatto_cosines();
  const double span = result.work_end - result.work_start;
  constexpr std::size_t fine = force_size - 1, fine_stride = 64 / fine;
  static_assert(fine == 2 * (inverse_size - 1), "the inverse's points are every other one");
  for (std::size_t part = 0; part < inverse_parts; ++part) {
    const auto target = [&](std::size_t j) {     // W - W(lower) at fine point j
      const double w = cosines[j * fine_stride]; // in the part, [-1, 1]
      return span * (static_cast<double>(part) + 0.5 * (w + 1)) /
             static_cast<double>(inverse_parts);
    };
    std::array<double, force_size> forces{};
    // As force_at_work's Newton path: G(t) = F(x) x ln(2) / 2.
    const auto force_at = [&](const Solved& solved) {
      return solved.density / (result.lower * std::exp2(0.5 * (solved.t + 1)) * half_log_two);
    };
    std::array<double, inverse_size> times{};
    for (std::size_t j = 0; j < inverse_size; ++j) {
      const double work = target(2 * j);
      const auto solved = solve_octave(result, work, 2 * work / span - 1);
      times[j] = solved.t;
      forces[2 * j] = force_at(solved);
    }
    auto& inverse = result.inverse[part];
    lobatto_series(times.data(), inverse_size - 1, inverse.data());
    for (std::size_t j = 1; j < fine; j += 2)
      forces[j] = force_at(
          solve_octave(result, target(j),
                       chebyshev_sum(inverse.data(), inverse_size, cosines[j * fine_stride])));
    auto& force = result.force[part];
    lobatto_series(forces.data(), fine, force.data());
    const double scale = std::abs(force[0]);
    result.force_converged[part] =
        std::abs(force[fine]) <= 1e-15 * scale && std::abs(force[fine - 1]) <= 1e-15 * scale;
  }
}

void OctaveWorkTable::build_up_to(std::size_t index, const Force& force) const {
  if (index >= max_octaves)
    throw std::runtime_error("the loading curve never absorbs the impact energy");
  std::lock_guard<std::mutex> lock(mutex_);
  while (octaves_.size() <= index) {
    const double lower = octaves_.empty() ? start_approach_ : 2 * octaves_.back().lower;
    const double work = octaves_.empty() ? start_work_ : octaves_.back().work_end;
    octaves_.push_back(build(lower, work, force));
    published_[octaves_.size() - 1].store(&octaves_.back(), std::memory_order_release);
    built_.store(octaves_.size(), std::memory_order_release);
  }
}

const OctaveWorkTable::Octave& OctaveWorkTable::octave(std::size_t index,
                                                       const Force& force) const {
  if (index < max_octaves)
    if (const Octave* built = published_[index].load(std::memory_order_acquire)) return *built;
  build_up_to(index, force);
  return *published_[index].load(std::memory_order_acquire);
}

const OctaveWorkTable::Octave& OctaveWorkTable::octave_of(double approach,
                                                          const Force& force) const {
  int exponent = 0;
  std::frexp(approach / start_approach_, &exponent); // ratio in [2^(e-1), 2^e)
  return octave(static_cast<std::size_t>(std::max(exponent - 1, 0)), force);
}

double OctaveWorkTable::work(double approach, const Force& force) const {
  if (!(approach > start_approach_)) return start_work_;
  const Octave& piece = octave_of(approach, force);
  const double t = std::clamp(2 * std::log2(approach / piece.lower) - 1, -1.0, 1.0);
  return piece.work_start + chebyshev_sum(piece.integral.data(), piece.size + 1, t);
}

OctaveWorkTable::Part OctaveWorkTable::locate_part(double work, const Force& force) const {
  // The octave whose works bracket the target: built up to it, then a binary search.
  std::size_t count = built_.load(std::memory_order_acquire);
  while (count == 0 || published_[count - 1].load(std::memory_order_acquire)->work_end < work) {
    build_up_to(count, force);
    count = built_.load(std::memory_order_acquire);
  }
  std::size_t first = 0, last = count - 1; // the first octave with work_end >= work
  while (first < last) {
    const std::size_t middle = first + (last - first) / 2;
    if (published_[middle].load(std::memory_order_acquire)->work_end < work)
      first = middle + 1;
    else
      last = middle;
  }
  const Octave& piece = *published_[first].load(std::memory_order_acquire);
  // The part of the work that holds the target, and the normalised work in it.
  const double scaled =
      std::clamp((work - piece.work_start) / (piece.work_end - piece.work_start), 0.0, 1.0) *
      inverse_parts;
  const std::size_t part = std::min(static_cast<std::size_t>(scaled), inverse_parts - 1);
  return {&piece, part, 2 * (scaled - static_cast<double>(part)) - 1};
}

OctaveWorkTable::Located OctaveWorkTable::locate_work(double work, const Force& force) const {
  const Part found = locate_part(work, force);
  const Octave& piece = *found.piece;
  const Solved solved = solve_octave(piece, work - piece.work_start,
                                     chebyshev_sum(piece.inverse[found.index].data(), inverse_size,
                                                   found.normalised));
  return {&piece, solved.t, solved.density};
}

double OctaveWorkTable::approach(double work, const Force& force) const {
  if (!(work > start_work_)) return start_approach_;
  const Located found = locate_work(work, force);
  return found.piece->lower * std::exp2(0.5 * (found.t + 1));
}

double OctaveWorkTable::force_at_work(double work, const Force& force) const {
  if (!(work > start_work_)) return force(start_approach_);
  const Part part = locate_part(work, force);
  if (part.piece->force_converged[part.index])
    return chebyshev_sum(part.piece->force[part.index].data(), force_size, part.normalised);
  const Located found = locate_work(work, force);
  const double approach = found.piece->lower * std::exp2(0.5 * (found.t + 1));
  // G(t) = F(x) x ln(2) / 2.
  return found.density / (approach * half_log_two);
}

std::pair<double, double> OctaveWorkTable::force_and_slope(double approach,
                                                           const Force& force) const {
  const Octave& piece = octave_of(std::max(approach, start_approach_), force);
  const double t = std::clamp(2 * std::log2(approach / piece.lower) - 1, -1.0, 1.0);
  // G and G' by the forward recurrences of evaluate_octave, without the work's sum.
  const std::size_t n = piece.size;
  double density = piece.density[0] + piece.density[1] * t;
  double density_slope = piece.density[1];
  double previous = 1, current = t;         // T_(k-1), T_k for k = 1
  double previous_u = 1, current_u = 2 * t; // U_(k-2), U_(k-1) for k = 2
  for (std::size_t k = 2; k < n; ++k) {
    const double next = 2 * t * current - previous; // T_k
    previous = current;
    current = next;
    density += piece.density[k] * next;
    density_slope += piece.density[k] * static_cast<double>(k) * current_u; // k U_(k-1)
    const double next_u = 2 * t * current_u - previous_u;                   // U_k
    previous_u = current_u;
    current_u = next_u;
  }
  // G = F x h and dG/dt = (F' x + F) x h^2, h = ln(2) / 2.
  const double force_value = density / (approach * half_log_two);
  const double slope =
      (density_slope / (approach * half_log_two * half_log_two) - force_value) / approach;
  return {force_value, slope};
}

std::pair<double, double> OctaveWorkTable::force_and_slope_at_work(double work,
                                                                   const Force& force) const {
  const Part found = locate_part(std::max(work, start_work_), force);
  const Octave& piece = *found.piece;
  // G and G' at the solution from the last evaluation of the Newton iteration, carried over
  // its last step d (<= 1e-9) to first order: errors of order d^2, as G's own.
  const Solved point = solve_octave<true>(piece, std::max(work, start_work_) - piece.work_start,
                                          chebyshev_sum(piece.inverse[found.index].data(),
                                                        inverse_size, found.normalised));
  const double approach = piece.lower * std::exp2(0.5 * (point.t + 1));
  // G = F x h and dG/dt = (F' x + F) x h^2, h = ln(2) / 2.
  const double force_value = point.density / (approach * half_log_two);
  const double slope =
      (point.density_slope / (approach * half_log_two * half_log_two) - force_value) / approach;
  return {force_value, slope};
}

double OctaveWorkTable::work_below(double approach_max, double distance, const Force& force) const {
  if (!(distance > 0)) return 0.0;
  const double approach = approach_max - distance;
  const Octave& top = octave_of(approach_max, force);
  const Octave& bottom = octave_of(std::max(approach, start_approach_), force);
  const auto position = [](const Octave& piece, double x) {
    return std::clamp(2 * std::log2(x / piece.lower) - 1, -1.0, 1.0);
  };
  const double top_t = position(top, approach_max);
  if (&top == &bottom) // t(x_max) - t(x) = (2 / ln 2) ln(x_max / x)
    return chebyshev_difference(top.integral.data(), top.size + 1, top_t, position(top, approach),
                                -two_over_log_two * std::log1p(-distance / approach_max));
  // From x to the end of its octave, the octaves between, and from the start of x_max's.
  const double bottom_end = 2 * bottom.lower;
  const double bottom_gap = distance - (approach_max - bottom_end); // 2 lower - x
  double work =
      chebyshev_difference(bottom.integral.data(), bottom.size + 1, 1.0, position(bottom, approach),
                           two_over_log_two * std::log1p(bottom_gap / approach));
  for (double lower = bottom_end; lower < top.lower; lower *= 2) {
    const Octave& piece = octave_of(lower, force);
    work += chebyshev_sum(piece.integral.data(), piece.size + 1, 1.0);
  }
  return work + chebyshev_difference(top.integral.data(), top.size + 1, top_t, -1.0,
                                     two_over_log_two *
                                         std::log1p((approach_max - top.lower) / top.lower));
}

double OctaveWorkTable::work_below_over_hertz(double hertz_stiffness, double approach_max,
                                              double distance, const Force& force) const {
  if (!(distance > 0)) return 0.0;
  if (approach_max <= start_approach_)
    return hertz_work_below(hertz_stiffness, approach_max, distance);
  const double above = approach_max - start_approach_; // the part of d above x_0
  if (distance <= above) return work_below(approach_max, distance, force);
  return work_below(approach_max, above, force) +
         hertz_work_below(hertz_stiffness, start_approach_, distance - above);
}

} // namespace impact::reduced::detail
