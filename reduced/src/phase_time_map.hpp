#pragma once
// The time along one phase of an impact as a function of a phase variable, and its inverse,
// for a whole time history in linear time. Internal to the library (hunt_crossley.cpp).
//
// The caller supplies the time density dt/dsigma on sigma in [0, 1] in the form
//     density(sigma) = G(sigma^p),   G analytic on [0, 1], finite and positive,
// (the end-point singularity of the time integral already removed by the choice of sigma;
// what is left is a power series in sigma^p, p = n + 1 for the Hunt-Crossley phases).
// The map accumulates the time from sigma = 0, piece by piece:
//   - on [0, sigma_0] G is interpolated by a polynomial in tau = (sigma / sigma_0)^p, and
//     sum g_k tau^k integrates term by term in sigma: t = sigma sum g_k tau^k / (k p + 1),
//     exact for the power series (no singular term is left to resolve near sigma = 0);
//   - on the rest the density is smooth in sigma: panels on which it is interpolated at
//     Chebyshev points of the first kind and the interpolant integrated term by term
//     (Clenshaw & Curtis 1960; Trefethen, Approximation Theory and Approximation Practice,
//     SIAM 2013, ch. 3 and 19). A panel whose last coefficients exceed the tolerance is
//     halved.
// Each piece's time is then a short series that is inverted by Newton's method without
// further calls of the density.
//
// Beside the density the caller supplies `companions`: values c_k that are analytic
// functions of sigma^p, computed with the density at the same nodes, of which the caller
// wants the quantities q_0 = c_0, q_1 = sigma c_1 and q_2 = sigma^(p-1) c_2 (here the state of
// the impact: the approach rate, the approach and the force, c_2 = force / sigma^n). They are interpolated on the same pieces (a piece is accepted only when their
// trailing coefficients are small too), sigma^p too (on the panels; it is exact on the first
// piece), so that locating a time also gives the quantities by a few short series: no power,
// logarithm or root per located time (one power on the first piece).

#include <cstddef>
#include <functional>
#include <vector>

namespace impact::reduced::detail {

/// The number of companion values interpolated with the density.
inline constexpr int phase_companions = 3;

/// A located time: the quantities c_0, sigma c_1, sigma^(p-1) c_2 there.
struct PhaseSample {
  double quantities[phase_companions];
};

class PhaseTimeMap {
public:
  /// density(sigma, sigma^p, companions) returns dt/dsigma and writes the companions at sigma.
  using Density = std::function<double(double sigma, double sigma_power, double* companions)>;

  /// Builds the map of t(sigma) = integral_0^sigma density over [0, 1]; `power` is p > 0.
  /// `tolerance` bounds the trailing Chebyshev coefficients of the density (and of each
  /// companion) on each piece relative to its value at sigma = 1/2 (a companion's scale is
  /// at least its largest value there and at the nodes of the first piece): the time and the
  /// companions then carry a relative error of about `tolerance`. Throws std::runtime_error
  /// if the density is not finite and positive.
  PhaseTimeMap(const Density& density, double power, double tolerance);

  /// t(1) [units of the density times sigma].
  double duration() const { return duration_; }
  /// Density evaluations made to build the map.
  std::size_t evaluations() const { return evaluations_; }

  /// One pass over ascending times in (0, duration] (below).
  class Locator;

  /// Chebyshev points per panel, and interpolation points of the first piece.
  static constexpr int nodes = 16;
  static constexpr int first_nodes = 12;

private:
  struct Panel {
    double lower;           // sigma at the panel's left end
    double half_width;      // of the panel in sigma
    double start_time;      // t(lower)
    double density[nodes];  // Chebyshev coefficients of dt/dsigma on the panel (x in [-1, 1])
    double time[nodes + 1]; // Chebyshev coefficients of t - start_time on the panel
    double companions[phase_companions][nodes]; // Chebyshev coefficients of each companion
    double sigma_power[nodes];                  // Chebyshev coefficients of sigma^p
  };
  // Whether the trailing coefficients of the density and of every companion are within
  // their tolerances. Where the density converges and a companion does not, the companion's
  // own values are the limit (the state near separation at large beta is computed from
  // distances of ~1e3 with rounding errors of ~1e-13): the piece is then still halved, but
  // not below 1/64 of the phase for the first piece and `companion_depth` halvings of a
  // panel (1/2^12 of the phase), where the companion's series stands at the noise of its
  // values.
  struct Convergence {
    bool density = false;
    bool companions = true;
  };
  static constexpr int companion_depth = 9;
  Convergence build_first_piece(const Density& density, double upper);
  Convergence build_panel(const Density& density, double lower, double upper, Panel& panel);
  template <int N>
  void panel_samples(const Panel& panel, const double (&x)[N], PhaseSample (&samples)[N]) const;
  PhaseSample first_piece_sample(double s, double tau) const;
  // The quantities (or, on the first piece, their ratios to u^(e_k), below) as series in one
  // variable y in [-1, 1], fitted as Chebyshev series, each cut after the last coefficient
  // that matters (those left out sum to at most the series' tolerance), and stored as
  // polynomials in y, coefficient by coefficient: Horner's rule for several points and the
  // series side by side is half the work and half the registers of Clenshaw's.
  // (The power form of sum c_j T_j(y) adds rounding errors of at most eps sum |c_j| (1 +
  // sqrt 2)^j on [-1, 1]: a few eps |c_0|, the coefficients of a converged series decaying
  // at least 7 times faster than (1 + sqrt 2)^j grows.)
  static constexpr int series_count = phase_companions;
  struct SampleSeries {
    double coefficients[nodes][series_count]; // of y^j
    int length = 0;
  };
  // From the values at the Chebyshev points of y; false if a series does not decay to its
  // tolerance.
  static bool fit_series(const double (&values)[series_count][nodes],
                         const double (&tolerances)[series_count], SampleSeries& series);
  static constexpr int batch = 4;
  static void evaluate_series(const SampleSeries& series, const double (&y)[batch],
                              double (&values)[batch][series_count]);
  // The first piece's inverse: with u = t / t(first end) and w = u^p, t = s Q(s^p) gives
  // s = u R(w), R analytic in w (Q(0) > 0), so that q_k / u^(e_k) (e = 0, 1, p - 1) is
  // analytic in w: Chebyshev series in w in [0, 1], and a located time costs one power and
  // three series instead of Newton's method. False if they do not converge (then not used).
  bool build_first_inverse(double first_end, SampleSeries& inverse) const;
  // A panel's quantities as Chebyshev series in its time range (they are analytic in t
  // there): a located time costs three series.
  bool build_inverse(const Panel& panel, double end_time, SampleSeries& inverse) const;
  template <int N>
  void solve_in_panel(const Panel& panel, const double (&times)[N], double (&x)[N]) const;
  double panel_end_time(long panel) const;
  double solve_in_first_piece(double time, double guess, double& tau) const;

  double power_;
  // The first piece [0, first_upper_]: density = sum first_density_[k] tau^k,
  // t = sigma sum first_time_[k] tau^k, tau = (sigma / first_upper_)^p.
  double first_upper_ = 0;
  double first_upper_power_ = 0; // first_upper_^p
  double first_density_[first_nodes] = {};
  double first_time_[first_nodes] = {};
  double first_companions_[phase_companions][first_nodes] = {};
  // Absolute tolerances of the density and of each companion.
  double density_tolerance_ = 0;
  double companion_tolerance_[phase_companions] = {};
  std::vector<Panel> panels_;
  double duration_ = 0;
  std::size_t evaluations_ = 0;
};

/// The quantities at the sigma in (0, 1] with t(sigma) = time, for ascending times: one pass
/// over the pieces, Newton's method on each piece's series (safeguarded by bisection) from a
/// quadratic extrapolation of the previous points, or, on a piece expected to hold more than
/// `nodes` points, the Chebyshev series in time of the quantities (built from Newton's
/// solutions at their nodes; not used where they do not converge), evaluated for up to
/// `batch` points at once.
class PhaseTimeMap::Locator {
public:
  static constexpr int batch = PhaseTimeMap::batch;
  explicit Locator(const PhaseTimeMap& map);
  /// The samples of `count` in [1, batch] ascending times, each after those of the earlier
  /// calls. `spacing` > 0 is the typical distance between successive times (it decides where
  /// series in time pay).
  void locate(const double* times, int count, double spacing, PhaseSample* samples);

private:
  long piece_of(double time) const;
  double piece_start(long piece) const;
  double piece_end(long piece) const;
  bool last_piece(long piece) const;
  void enter(long piece, double time, double spacing);
  PhaseSample newton_sample(double time);
  void inverse_samples(const double* times, int count, PhaseSample* samples) const;

  const PhaseTimeMap& map_;
  double first_end_; // t at the end of the first piece
  long piece_ = -2;  // -1 the first piece, 0, 1, ... the panels; -2 before the first time
  // The last (up to) three Newton solutions in the piece, to extrapolate from.
  double known_time_[3] = {}, known_x_[3] = {};
  int known_ = 0;
  SampleSeries inverse_;
  bool use_inverse_ = false;
};

} // namespace impact::reduced::detail
