#pragma once
/// @file
/// The impact of a body on a fixed obstacle under a rate-independent elastic-plastic contact
/// law: a loading curve F_L(x) while the approach grows, and from the maximum approach x_max
/// a Hertzian unloading branch on an enlarged radius,
///     F_U(x) = k_u (x - x_r)^(3/2)  for x_r <= x <= x_max,   F_U(x_max) = F_L(x_max),
/// which leaves the permanent (residual) approach x_r. The bodies separate when F_U returns
/// to 0 at x = x_r (the contact cannot pull), or at x = 0 if x_r < 0 (a branch that would still
/// push at x = 0). A branch that would return more energy than the loading absorbed (possible
/// only with fitted loading curves, see sphere_flat_fits.hpp) gives an elastic rebound, e = 1,
/// never e > 1. Thornton (1997) and the Jackson-Green loading
/// with the radius-preserving unloading are such laws (thornton.hpp, sphere_flat_fits.hpp).
///
/// Model: m x'' = -F(x), x(0) = 0, x'(0) = V > 0. With no rate dependence the impact follows
/// from energy: x_max from W_L(x_max) = m V^2 / 2 (W_L the loading work), the rebound speed
/// from the energy stored in the unloading branch, (2/5) F_max (x_max - x_r) = m V_out^2 / 2,
/// and the times from t = integral dx / |x'| over each phase: the loading piece from x = 0 by
/// Hertz's incomplete Beta function where the law is a power law there (loading_power_law;
/// else tanh-sinh), the pieces above it by adaptive Gauss-Kronrod in sigma, x = x_max
/// exp(-sigma^2), which removes the inverse-square-root singularity at x_max, with the work
/// near x_max from the law's loading_work_below (closed forms, the fits' series differenced
/// term by term, or local Gauss-Legendre) so that it does not cancel.
///
/// Accuracy (measured in tests/reduced/test_thornton.cpp, test_sphere_flat_fits.cpp and
/// test_ghaednia.cpp against Thornton's closed forms and an independent long-double
/// Runge-Kutta-Fehlberg 7(8) integration, tests/reduced/plastic_impact_reference.hpp):
/// restitution, x_max, F_max, x_r within 1e-13 relative; compression and contact time
/// within 1e-12.

#include "impact_reduced/elastic_force.hpp"
#include "impact_reduced/impact_ode.hpp"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace impact::reduced {

/// The unloading branch from one maximum approach: F = stiffness (x - residual_approach)^1.5.
struct HertzianUnloading {
  double stiffness;         ///< k_u = (4/3) E* sqrt(R_u) [N/m^1.5], R_u the unloading radius
  double residual_approach; ///< x_r [m], the permanent approach after the impact
};

namespace detail {
/// (2/5) c (x^(5/2) - (x - d)^(5/2)), the work of the Hertz force c x^(3/2) between x - d and
/// x (0 <= d <= x), without cancellation for small d.
double hertz_work_below(double stiffness, double approach, double distance);
} // namespace detail

/// An elastic-plastic contact law. Approach x in m, forces in N, work in J.
class ElasticPlasticContact {
public:
  virtual ~ElasticPlasticContact() = default;
  /// Loading force F_L(x) for x >= 0: increasing, F_L(0) = 0.
  virtual double loading_force(double approach) const = 0;
  /// Loading work W_L(x) = integral_0^x F_L [J].
  virtual double loading_work(double approach) const = 0;
  /// Loading stiffness dF_L/dx [N/m] for x > 0 (the right derivative at a breakpoint): the
  /// slope that locates the force peak of a damped impact and scales Kuwabara-Kono damping.
  virtual double loading_stiffness(double approach) const = 0;
  /// {loading_force(x), loading_stiffness(x)} at once, the same values (the Kuwabara-Kono
  /// law needs both at every evaluation; the fitted laws share their terms).
  virtual std::pair<double, double> loading_force_and_stiffness(double approach) const {
    return {loading_force(approach), loading_stiffness(approach)};
  }
  /// {F_L(x), dF_L/dx} for an integrator that evaluates them many times (Kuwabara-Kono,
  /// kuwabara_kono_elastic_plastic.hpp): loading_force_and_stiffness by default; laws that
  /// tabulate their loading work return the table's values, two to three times cheaper than
  /// their fit and within its rounding (the overrides say how close and how fast).
  virtual std::pair<double, double> loading_force_and_stiffness_from_table(double approach) const {
    return loading_force_and_stiffness(approach);
  }
  /// The approach x >= 0 with W_L(x) = work (work >= 0). The default brackets the root from
  /// the Hertz-like guess and solves by TOMS 748 to full double precision; laws with an
  /// inverse in closed form override it.
  virtual double loading_approach(double work) const;
  /// F_L at the approach where W_L = work: loading_force(loading_approach(work)) by default;
  /// laws that tabulate W_L return it from the table (the time integrals of
  /// hunt_crossley_elastic_plastic.hpp need only this pair).
  virtual double loading_force_at_work(double work) const {
    return loading_force(loading_approach(work));
  }
  /// {F_L, dF_L/dx} at the approach where W_L = work: loading_force_and_stiffness of
  /// loading_approach by default; laws that tabulate W_L return them from the table.
  virtual std::pair<double, double> loading_force_and_stiffness_at_work(double work) const {
    return loading_force_and_stiffness(loading_approach(work));
  }
  /// The loading work between x_max - d and x_max [J], integral of F_L, for 0 <= d <= x_max,
  /// without cancellation for small d (the time integrals need it where d << x_max). The
  /// default integrates F_L by 30-point Gauss-Legendre on [x_max - d, x_max] split at the
  /// breakpoints for d <= x_max / 2, and subtracts loading_work beyond; laws override it
  /// with their closed forms or tables.
  virtual double loading_work_below(double approach_max, double distance) const;
  /// If F_L is exactly a power law c x^n from x = 0 to its first breakpoint (Hertz's below
  /// yield): its coefficients, for the damped impact's time integrals. Default: none.
  virtual std::optional<PowerLawCoefficients> loading_power_law() const { return std::nullopt; }
  /// Approaches where F_L or its slope jumps (the quadratures split there). Default: none.
  virtual std::vector<double> loading_breakpoints() const { return {}; }
  /// The unloading branch from the maximum approach x_max > 0.
  virtual HertzianUnloading unloading(double approach_max) const = 0;
};

/// The figures of one impact. SI units.
struct ElasticPlasticImpactResponse {
  double approach_max;      ///< x_max [m]
  double force_max;         ///< F_L(x_max) [N], the peak force (at x_max: the law has no rate term)
  double residual_approach; ///< x_r [m], permanent approach (0 for an elastic impact)
  double compression_time;  ///< time of x_max [s]
  double contact_time;      ///< time of separation (force back to 0 at x_r) [s]
  double rebound_velocity;  ///< approach rate at separation [m/s], negative
  double restitution;       ///< -rebound_velocity / V [-]
  double dissipated_energy; ///< m V^2 (1 - e^2) / 2 [J], the plastic work
  /// The figures by which impacts are compared (impact_figures.hpp); the peak force is at
  /// x_max, so t(F_max) is the compression time.
  ImpactFigures figures() const {
    return {restitution, contact_time, force_max, compression_time, approach_max};
  }
};

/// The impact of mass m > 0 [kg] at velocity V > 0 [m/s] under `contact`. Throws
/// InvalidInput naming "mass" or "velocity"; std::runtime_error if the law never absorbs the
/// impact energy (bounded loading work).
ElasticPlasticImpactResponse elastic_plastic_impact(double mass, double velocity,
                                                    const ElasticPlasticContact& contact);

/// The force-approach loop of the same impact with its times: `points_per_phase` (>= 2)
/// states equally spaced in approach on the loading branch (x = 0 to x_max) and as many on
/// the unloading branch (x_max down to the separation approach, x_max not repeated). Times
/// and rates carry the accuracy of the response (1e-12). Throws InvalidInput naming
/// "points_per_phase", "mass" or "velocity". (Where the energy guard above applies, the
/// branch's last rate exceeds V slightly; the response reports e = 1.)
std::vector<ImpactSample> elastic_plastic_impact_loop(double mass, double velocity,
                                                      const ElasticPlasticContact& contact,
                                                      std::size_t points_per_phase);

/// The work of the loading curve between x_max - d and x_max, integral of F_L [J], evaluated
/// without cancellation for small d (0 <= d <= x_max; 0 for d <= 0): the law's
/// ElasticPlasticContact::loading_work_below. Used by the time integrals; exposed for tests.
double loading_work_below(const ElasticPlasticContact& contact, double approach_max,
                          double distance);

} // namespace impact::reduced
