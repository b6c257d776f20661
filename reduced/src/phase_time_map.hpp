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

#include <cstddef>
#include <functional>
#include <vector>

namespace impact::reduced::detail {

class PhaseTimeMap {
public:
  /// Builds the map of t(sigma) = integral_0^sigma density over [0, 1]; `power` is p > 0.
  /// `tolerance` bounds the trailing Chebyshev coefficients of the density on each piece
  /// relative to the density at sigma = 1/2: the time then carries a relative error of
  /// about `tolerance`. Throws std::runtime_error if the density is not finite and positive.
  PhaseTimeMap(const std::function<double(double)>& density, double power, double tolerance);

  /// t(1) [units of the density times sigma].
  double duration() const { return duration_; }
  /// Density evaluations made to build the map.
  std::size_t evaluations() const { return evaluations_; }

  /// sigma^p at the sigma in [0, 1] with t(sigma) = time, for ascending times in
  /// [0, duration]: one pass over the pieces, Newton's method on each piece's series
  /// (safeguarded by bisection) from a quadratic extrapolation of the previous points, or,
  /// on a panel holding more than 2 `nodes` points, the Chebyshev series of the inverse.
  std::vector<double> locate(const std::vector<double>& ascending_times) const;

  /// Chebyshev points per panel, and interpolation points of the first piece.
  static constexpr int nodes = 16;
  static constexpr int first_nodes = 12;

private:
  struct Panel {
    double lower;      // sigma at the panel's left end
    double half_width; // of the panel in sigma
    double start_time; // t(lower)
    double density[nodes];  // Chebyshev coefficients of dt/dsigma on the panel (x in [-1, 1])
    double time[nodes + 1]; // Chebyshev coefficients of t - start_time on the panel
  };
  bool build_first_piece(const std::function<double(double)>& density, double upper,
                         double tolerance);
  bool build_panel(const std::function<double(double)>& density, double lower, double upper,
                   double tolerance, Panel& panel);
  double solve_in_panel(const Panel& panel, double time, double guess) const;
  double panel_end_time(long panel) const;
  bool build_inverse(const Panel& panel, double end_time, double* inverse) const;
  double solve_in_first_piece(double time, double guess, double& tau) const;

  double power_;
  // The first piece [0, first_upper_]: density = sum first_density_[k] tau^k,
  // t = sigma sum first_time_[k] tau^k, tau = (sigma / first_upper_)^p.
  double first_upper_ = 0;
  double first_density_[first_nodes] = {};
  double first_time_[first_nodes] = {};
  std::vector<Panel> panels_;
  double duration_ = 0;
  std::size_t evaluations_ = 0;
};

} // namespace impact::reduced::detail
