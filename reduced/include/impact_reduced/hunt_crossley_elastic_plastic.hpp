#pragma once
/// @file
/// Hunt-Crossley damping on an elastic-plastic spring, in closed form (Lambert W): the law
/// that carries both losses of a viscoelastic, yielding contact,
///     F = F_s(x) (1 + b x'),
/// with F_s the loading branch F_L of an elastic-plastic law (ElasticPlasticContact) while
/// the approach grows and its Hertzian unloading branch F_U(x) = k_u (x - x_r)^(3/2) from
/// the maximum approach x_max on. Below yield (F_U = F_L, x_r = 0) it is Hunt-Crossley's law;
/// with b = 0 it is the rate-independent impact of elastic_plastic_impact.hpp.
///
/// Model: m x'' = -F, x(0) = 0, x'(0) = V > 0; contact ends where the unloading branch
/// returns to zero force, x = x_s = max(x_r, 0).
///
/// Closed form. The seed paper's separation of variables holds for any spring whose work is
/// known: m v dv/dx = -F_s(x) (1 + b v) gives
///     (m / b^2) (b v - ln(1 + b v)) = W_L(x_max) - W_L(x)      while compressing,
///     (m / b^2) (b v - ln(1 + b v)) = W_U(x_max) - W_U(x)      while restoring,
/// with W_L = integral_0^x F_L and W_U = integral_(x_r)^x F_U = (2/5) k_u (x - x_r)^(5/2).
/// So each phase is the corresponding phase of a Hunt-Crossley impact on its own branch:
///   - compression: HuntCrossleyImpact on F_L at velocity V; x_max solves
///     W_L(x_max) = (m / b^2) (beta - ln(1 + beta)), beta = b V, and the force peaks before
///     x_max where m F_L'(x) v = b F_L(x)^2;
///   - restitution: the released energy E = W_U(x_max) - W_U(x_s) gives the rebound
///     velocity v_out = -(1/b) (1 + W0(-exp(-1 - b^2 E / m))), written without the branch
///     point as v_out = -u q(b u), u = sqrt(2 E / m) (q(p) = y / p with -y - ln(1 - y) =
///     p^2 / 2, the library's cancellation-free Lambert W near -1/e), and e = -v_out / V.
///     The phase is the restitution phase of a Hunt-Crossley impact on F_U in the shifted
///     approach x - x_r at the velocity that stores the same energy,
///     V_U = u q(-b u) (the lower branch W_-1).
/// The times are those phases' integrals in the approach rate (HuntCrossleyImpact's
/// quadratures: Gauss-Jacobi on the spring's Hertz piece, Gauss-Kronrod above it, the
/// compression split at the force peak), the history their inversion. There is no ODE and no
/// step size.
///
/// Edge cases: where the unloading branch would release more energy than the loading
/// absorbed (x_r < 0 on a fitted loading curve just above Hertz, E > W_L(x_max)), the spring
/// unloads along its loading branch (no dent), as elastic_plastic_impact returns e = 1 then;
/// where x_r < 0 otherwise, the surfaces part at x = 0 with the branch still pushing.
///
/// Accuracy: see HuntCrossleyElasticPlasticImpact.

#include "impact_reduced/elastic_plastic_impact.hpp"
#include "impact_reduced/hunt_crossley.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace impact::reduced {

/// The figures of one damped elastic-plastic impact. SI units.
struct HuntCrossleyElasticPlasticResponse {
  double approach_max;        ///< x_max [m]
  double force_max;           ///< peak contact force [N] (before x_max when b > 0)
  double time_force_max;      ///< time of the peak force [s]
  double compression_time;    ///< time of x_max [s]
  double contact_time;        ///< time of separation [s]
  double rebound_velocity;    ///< approach rate at separation [m/s], negative
  double restitution;         ///< -rebound_velocity / V [-]
  double separation_approach; ///< x_s [m]: the permanent approach, 0 for an elastic impact
  ImpactFigures figures() const {
    return {restitution, contact_time, force_max, time_force_max, approach_max};
  }
};

/// One impact of Hunt-Crossley damping on an elastic-plastic spring. Construction validates
/// the parameters and evaluates the closed forms (x_max, e); times are integrated on demand.
///
/// Accuracy (relative; tests/reduced/test_hunt_crossley_elastic_plastic.cpp): against 50-digit
/// references for the Hertz and Thornton springs (beta = b V in [0, 10], V/V_y in [0.5, 1e3])
/// and an independent long-double RKF 7(8) integration for Jackson-Green and Ghaednia
/// (E_t = 0.02 E_s; beta in [0, 1], V/V_y in {3, 30}): restitution, x_max and F_max within 1e-12, compression and contact time
/// within 1e-10 (worst measured 3.5e-15). On the Hertz spring every figure equals
/// HuntCrossleyImpact's (the same code) within 1e-14.
class HuntCrossleyElasticPlasticImpact {
public:
  /// mass m > 0 [kg], the spring (not null), damping b >= 0 [s/m], velocity V > 0 [m/s].
  /// Throws InvalidInput naming "mass", "spring", "damping" or "velocity".
  HuntCrossleyElasticPlasticImpact(double mass, std::shared_ptr<const ElasticPlasticContact> spring,
                                   double damping, double velocity);

  double mass() const { return loading_.mass(); }
  double damping() const { return loading_.damping(); }
  double velocity() const { return loading_.velocity(); }
  const ElasticPlasticContact& spring() const { return *spring_; }

  double approach_max() const { return loading_.approach_max(); }
  double restitution() const { return restitution_; }
  double rebound_velocity() const { return -restitution_ * velocity(); }
  /// x_s [m], where the bodies part (the permanent approach; 0 for an elastic impact).
  double separation_approach() const { return separation_approach_; }
  /// The unloading branch from x_max (the loading branch itself where the spring unloads
  /// elastically: stiffness 0 then).
  const HertzianUnloading& unloading() const { return unloading_; }

  /// Approach rate v(x) [m/s] in the given phase (positive while compressing), x in
  /// [0, x_max] while compressing and [x_s, x_max] while restoring. Throws InvalidInput.
  double approach_rate(double approach, ImpactPhase phase) const;
  /// Contact force [N] at approach x in the given phase and rate v: F_s(x) (1 + b v).
  double force(double approach, double approach_rate, ImpactPhase phase) const;

  /// The state of the maximum contact force (while compressing).
  ImpactState force_peak() const;
  double compression_time() const;
  double contact_time() const;
  HuntCrossleyElasticPlasticResponse response() const;

  /// `points` >= 2 states equally spaced in time over [0, contact_time], both ends included
  /// (each by Newton's method on the phase quadratures, as HuntCrossleyImpact::state_at).
  std::vector<ImpactState> history(std::size_t points) const;

private:
  // Restitution time from x_max to x_s [s].
  double restitution_time() const;

  std::shared_ptr<const ElasticPlasticContact> spring_;
  HuntCrossleyImpact loading_; // the compression phase on F_L
  HertzianUnloading unloading_{0.0, 0.0};
  std::optional<HuntCrossleyImpact> unloading_impact_; // restitution on F_U (x - x_r)
  double restitution_ = 1.0;
  double separation_approach_ = 0.0;
};

} // namespace impact::reduced
