#pragma once
// The work W(x) = W(x_0) + integral_(x_0)^x F of a loading force that is analytic above a start
// approach x_0 > 0, tabulated octave by octave ([x_0 2^k, x_0 2^(k+1)]) as a Chebyshev series
// in the logarithm of the approach, and its inverse. The fitted elastic-plastic loading curves
// (Jackson-Green, Ghaednia) are built from powers and exponentials of powers of x: entire
// functions of s = ln x, so that on an octave (s spans ln 2) the series of F(x) x converges
// far faster than a Gauss rule in x on the same piece. The table is built on demand, one
// octave at a time (a few tens of force evaluations each), and then gives W in one Clenshaw
// sum and its inverse in a few Newton steps, instead of one composite quadrature per call.
//
// Accuracy: the series are truncated where their coefficients fall below 1e-17 of the
// octave's work (checked when an octave is built; an octave that does not converge within
// the largest degree throws, rather than returning a less accurate work). Measured against
// composite 30-point Gauss-Legendre in x (tests/reduced/test_octave_work_table.cpp).
//
// The inverse starts Newton's method from Chebyshev series of t(W) on eight equal parts of
// each octave's work (9 points each, built with the octave), so that one Newton step usually
// ends it: a step below 1e-9 in t
// leaves an error of about (G'/2G) 1e-18, far below the rounding of t.
//
// F at a given work (force_at_work, the integrand of the damped impact's time integrals) is
// a Chebyshev series of F(W) on each of those parts, interpolating at 17 points the values
// that the Newton path gives there, where its last two coefficients are below 1e-15 of the
// first, as for the octave's own series (checked when the octave is built; a part that fails
// it keeps the Newton path). On the fits the coefficients fall by 10 (the first part of the
// first octave) to 30 per degree down to the rounding of the values, about 1e-16, by degree
// 10 to 15. One sum of 17 terms then replaces the inverse's guess, one or two evaluations of
// the octave's three series and an exp2 (a quarter of the instructions of a damped
// impact's response on the fits, callgrind); F stays within 3e-15 of the fit's at the
// inverse (tests/reduced/test_octave_work_table.cpp). Building an octave costs 64 more
// Newton solves for it (about twice the instructions).
//
// Thread safety: const member functions may be called concurrently (the octaves are built
// under a mutex, never move once built, and are published through atomic pointers, so that
// reading a built octave takes no lock).

#include <array>
#include <atomic>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>

namespace impact::reduced::detail {

class OctaveWorkTable {
public:
  using Force = std::function<double(double)>;
  /// x_0 > 0 [m], W(x_0) [J].
  OctaveWorkTable(double start_approach, double start_work);
  /// W(x) [J] for x >= x_0; `force` F(x) for x > x_0.
  double work(double approach, const Force& force) const;
  /// The x >= x_0 with W(x) = work (work >= W(x_0)).
  double approach(double work, const Force& force) const;
  /// F at that x from the octave's series of F(x) x (within a few 1e-16 of `force`'s value
  /// relative to the octave's largest, measured in tests/reduced/test_octave_work_table.cpp):
  /// for the time integrals, which need F only where W is given.
  double force_at_work(double work, const Force& force) const;
  /// {F, dF/dx} there from the series of F x and its derivative (dF/dx within 1.5e-13
  /// relative: the derivative of the interpolant), for the force peak's search: G and G' from
  /// the Newton iteration's last evaluation (which also sums G''), carried over its last step
  /// d <= 1e-9 to first order (errors of order d^2), not from a second evaluation.
  std::pair<double, double> force_and_slope_at_work(double work, const Force& force) const;
  /// {F, dF/dx} at x >= x_0 from the octave's series of G = F x ln(2) / 2 (the work's
  /// density) and its derivative: one sum of at most 65 terms (17 on the fits) instead of
  /// the force's own evaluation, for an integrator that evaluates the law many times. F within
  /// 2.2e-15 and dF/dx within 2.4e-13 of `force`'s and its slope, relative (measured on the
  /// Jackson-Green and Ghaednia fits, tests/reduced/test_octave_work_table.cpp).
  std::pair<double, double> force_and_slope(double approach, const Force& force) const;
  /// W(x_max) - W(x_max - d) [J] for x_max - d >= x_0, d >= 0, without cancellation for
  /// small d: on each octave the difference of the series is summed term by term,
  /// T_m(a) - T_m(b) by its own recurrence from a - b (formed from d, not from a and b).
  double work_below(double approach_max, double distance, const Force& force) const;
  /// The same for a law that is Hertz's c x^(3/2) below x_0 (c = `hertz_stiffness`
  /// [N/m^1.5]) and this table above: any x_max >= 0 and 0 <= d <= x_max, the part of d
  /// below x_0 by Hertz's closed form (hertz_work_below).
  double work_below_over_hertz(double hertz_stiffness, double approach_max, double distance,
                               const Force& force) const;

  static constexpr std::size_t max_degree = 65;   // coefficients of the longest series
  static constexpr std::size_t inverse_parts = 8; // pieces of the inverse's guess
  static constexpr std::size_t inverse_size = 9;  // coefficients of each piece
  static constexpr std::size_t force_size = 17;   // coefficients of F(W) on each piece
  // Octaves x_0 2^k, k < max_octaves: beyond, x_0 2^k overflows for any x_0 >= 1e-300.
  static constexpr std::size_t max_octaves = 2100;

private:
  struct Octave {
    double lower;                                // x_0 2^k
    double work_start;                           // W(lower)
    double work_end;                             // W(2 lower)
    std::size_t size;                            // number of coefficients in use
    std::array<double, max_degree> density;      // Chebyshev coefficients of dW/dt
    std::array<double, max_degree + 1> integral; // of W - W(lower), zero at t = -1
    // t on part k of the work as a series in its own normalised work in [-1, 1]
    std::array<std::array<double, inverse_size>, inverse_parts> inverse;
    // F on part k as a series in the same normalised work, where it converged (else unused)
    std::array<std::array<double, force_size>, inverse_parts> force;
    std::array<bool, inverse_parts> force_converged;
  };
  // The octave that holds x (built with those below it).
  const Octave& octave_of(double approach, const Force& force) const;
  const Octave& octave(std::size_t index, const Force& force) const;
  // The octave that holds W = work (built up to it), t there and the series' G(t).
  struct Located {
    const Octave* piece;
    double t;
    double density;
  };
  Located locate_work(double work, const Force& force) const;
  // The octave that holds W = work, the part of its work and the normalised work in it.
  struct Part {
    const Octave* piece;
    std::size_t index;
    double normalised;
  };
  Part locate_part(double work, const Force& force) const;
  // Builds octaves up to `index` (under the mutex).
  void build_up_to(std::size_t index, const Force& force) const;
  Octave build(double lower, double work_start, const Force& force) const;
  // The series of t and of F on the parts of an octave whose work series is built.
  static void build_parts(Octave& octave);

  double start_approach_;
  double start_work_;
  mutable std::mutex mutex_;
  mutable std::deque<Octave> octaves_; // deque: references stay valid while it grows
  // octaves_[k] once built, else null; built_ counts them (release after the pointer).
  std::unique_ptr<std::atomic<const Octave*>[]> published_;
  mutable std::atomic<std::size_t> built_{0};
};

} // namespace impact::reduced::detail
