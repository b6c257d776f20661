#pragma once
/// @file
/// Hunt-Crossley impact of a body on a fixed obstacle in closed form (Lambert W).
///
/// Model: m x'' = -f(x) (1 + b x'), x(0) = 0, x'(0) = V > 0, contact until x returns to 0.
/// x [m] is the approach (indentation), b [s/m] the damping constant, beta = b V the
/// dimensionless impact parameter. Everything is evaluated from the first integral
///     ln(1 + b v) - b v = ln(1 + beta) - beta + (b^2/m) P(x),
/// solved with Lambert W through a formulation that stays exact at the branch point
/// (x -> x_max, beta -> 0) and continuous at b = 0 (Hertz). Times are integrals over the
/// approach rate, so there is no ODE and no step size: for the power law by Gauss-Jacobi
/// (beta <= 1) or tanh-sinh; for a custom law the piece from the singular end by tanh-sinh
/// (by the power law's Gauss-Jacobi rule if the law is one there, initial_power_law), the
/// pieces between its breakpoints by adaptive Gauss-Kronrod in ln u (estimate 1e-12), and
/// the compression split at the force peak, so that the peak's time and the compression time
/// share one integral.

#include "impact_reduced/elastic_force.hpp"
#include "impact_reduced/impact_figures.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace impact::reduced {

/// Coefficient of restitution k(beta) = (1 + W0(-(1 + beta) exp(-(1 + beta)))) / beta,
/// a function of beta = b V alone, whatever the elastic law. beta >= 0 (k(0) = 1),
/// relative error <= 4e-15 for beta in [0, 1e4] and finite beyond. Throws InvalidInput for
/// beta < 0 or non-finite beta.
double restitution_from_impact_parameter(double beta);

/// The inverse of restitution_from_impact_parameter: beta such that k(beta) = restitution,
/// for restitution in (0, 1] (1 gives 0). Relative error <= 1e-13 for restitution in
/// [1e-6, 1 - 1e-12]. Throws InvalidInput outside (0, 1].
double impact_parameter_from_restitution(double restitution);

/// Damping constant b = beta / V [s/m] that gives `restitution` (0, 1] at impact velocity
/// `velocity` > 0 [m/s]. Same accuracy as impact_parameter_from_restitution.
double damping_from_restitution(double restitution, double velocity);

/// The two phases of the contact: approach growing (x' > 0) or shrinking (x' < 0).
enum class ImpactPhase { compression, restitution };

/// A point of the impact: time since first contact [s], approach x [m], approach rate
/// x' [m/s] (positive while compressing), contact force F [N].
struct ImpactState {
  double time;
  double approach;
  double approach_rate;
  double force;
};

/// All derived quantities of one impact, SI units.
struct ImpactResponse {
  double approach_max;     ///< x_max [m]
  double force_max;        ///< peak contact force [N]
  double time_force_max;   ///< time of the peak force [s]
  double compression_time; ///< time of x_max [s]
  double contact_time;     ///< time at which x returns to 0 [s]
  double rebound_velocity; ///< approach rate at separation [m/s], negative (moving away)
  double restitution;      ///< -rebound_velocity / V [-]
  double energy_loss;      ///< kinetic energy lost, m V^2 (1 - k^2) / 2 [J]
  /// The figures by which impacts are compared (impact_figures.hpp).
  ImpactFigures figures() const {
    return {restitution, contact_time, force_max, time_force_max, approach_max};
  }
};

/// One Hunt-Crossley impact. Construction validates the parameters and precomputes the
/// closed forms; the time quantities are integrated on demand (a few microseconds).
///
/// Accuracy (relative, power law, against 50-digit references; see tests/reduced):
/// restitution and rebound velocity 4e-15 (beta <= 1e4); approach_max, force_max,
/// time_force_max 1e-13 and compression_time, contact_time 1e-12 (beta <= 1e3);
/// approach_rate(x) 1e-12 on both branches, also within 1e-10 x_max of x_max (the power law
/// evaluates the energy balance in quadruple precision there). A custom elastic law is as
/// accurate as its callables (its times to 1e-12 or better: tests/reduced/
/// test_hunt_crossley_elastic_plastic.cpp finds 1.5e-15), except approach_rate close to x_max,
/// where the cancellation in P(x_max) - P(x) limits it to about 1e-16 x_max / (x_max - x).
class HuntCrossleyImpact {
public:
  /// Power law f = c x^n: mass m > 0 [kg], stiffness c > 0 [N/m^n], exponent n > 0,
  /// damping b >= 0 [s/m], velocity V > 0 [m/s]. Throws InvalidInput naming the parameter.
  HuntCrossleyImpact(double mass, double stiffness, double exponent, double damping,
                     double velocity);
  /// Any elastic law f(x) (see ElasticForce).
  HuntCrossleyImpact(double mass, std::shared_ptr<const ElasticForce> elastic_force, double damping,
                     double velocity);

  double mass() const { return mass_; }
  double damping() const { return damping_; }
  double velocity() const { return velocity_; }
  /// beta = b V [-].
  double impact_parameter() const { return damping_ * velocity_; }

  double approach_max() const { return approach_max_; }
  double restitution() const { return restitution_; }
  /// Approach rate at separation [m/s], = -restitution V.
  double rebound_velocity() const { return -restitution_ * velocity_; }
  /// m V^2 (1 - k^2) / 2 [J].
  double energy_loss() const;

  /// Approach rate v(x) [m/s] at approach x in [0, x_max] in the given phase (positive
  /// while compressing, negative while restoring). Throws InvalidInput for x outside.
  double approach_rate(double approach, ImpactPhase phase) const;
  /// Contact force F = f(x) (1 + b v) [N] at a state.
  double force(double approach, double approach_rate) const;

  /// The state of maximum contact force (during compression; at x_max when b = 0).
  ImpactState force_peak() const;
  /// Time from first contact to x_max [s].
  double compression_time() const;
  /// Time from first contact to separation [s].
  double contact_time() const;
  /// Time from x_max to separation [s] (contact_time() - compression_time(), integrated on
  /// its own).
  double restitution_time() const;
  /// Time from first contact [s] at which the approach is x in [0, x_max] in the given
  /// phase: the inverse of the history's approach, integrated from the nearer singular end
  /// of the phase (same accuracy as compression_time). Throws InvalidInput for x outside.
  double time_at_approach(double approach, ImpactPhase phase) const;
  /// force_peak() and compression_time() at once, with the same values: one peak search, and
  /// for a custom law with damping the compression integral continued from the peak (as
  /// compression_time() integrates it) instead of integrated again from first contact.
  std::pair<ImpactState, double> force_peak_and_compression_time() const;
  /// Everything at once (one peak search, two integrals).
  ImpactResponse response() const;

  /// The time history at `points` >= 2 instants equally spaced over [0, contact_time],
  /// both ends included. Throws InvalidInput for points < 2.
  ///
  /// Power law: linear in `points`. Each phase's time is accumulated piece by piece from
  /// its singular end (first contact, separation) in sigma = (d / D)^(1/(n+1)), d the
  /// distance from that end, where dt/dsigma is bounded: a polynomial in sigma^(n+1) on
  /// the first half, Chebyshev panels on the rest, built from a fixed number of density
  /// evaluations (about 80 per phase, whatever `points`), the state interpolated on the same
  /// pieces. On a piece holding more than 16 instants the state is a series in time, built
  /// once for the piece and evaluated for four instants at a time; elsewhere each instant is
  /// located by Newton's method on the piece's series. Cost (bench-reduced, README; beta =
  /// 0.1): 14 us for both phases' series, 57 us for 1000 points, 0.27 ms for 10000.
  /// Accuracy, stated (tests/reduced/test_hunt_crossley_history.cpp; measured worst in
  /// brackets): each state lies on the exact trajectory (50-digit references) at a time
  /// within 1e-13 t_c of its own [2.1e-15], and approach, rate and force are within 1e-12 of
  /// x_max, V and F_max [9.5e-15], for beta in [1e-6, 1e3], n in {1, 1.5, 2.5}; against
  /// state_at within 1e-12 [2.3e-14] for beta in {0} U [1e-12, 1e3], n in [0.5, 4].
  /// Other elastic laws: each instant by Newton's method on the adaptive quadrature, from
  /// the previous one.
  std::vector<ImpactState> history(std::size_t points) const;

  /// The state at one instant `time` in [0, contact_time()] [s], the time inverted by
  /// Newton's method on the adaptive (tanh-sinh) quadrature from the nearer singular end of
  /// its phase: independent of history()'s series, and about 1e-13 t_c accurate in time, at
  /// tens of microseconds per call. Throws InvalidInput for a time outside.
  ImpactState state_at(double time) const;

  /// The states at `times` [s], ascending within [0, contact_time()]: each as state_at, but
  /// each phase's instants inverted in one pass (its quadrature carried on from the previous
  /// instant), so that n instants cost n short integrals instead of n whole ones. Agrees
  /// with state_at within 1e-11 of x_max, V and F_max (worst measured 1.1e-12,
  /// tests/reduced/test_hunt_crossley_history.cpp). Throws InvalidInput naming "times" for a
  /// time outside or out of order.
  std::vector<ImpactState> states_at(const std::vector<double>& times) const;

private:
  HuntCrossleyImpact(double mass, std::shared_ptr<const ElasticForce> custom_force, double damping,
                     double velocity, std::optional<PowerLawForce> power_law);

  // Each phase is parametrised by a distance u >= 0 from its singular end (first contact,
  // separation), so that the quantities are exact where the force vanishes. Compression:
  // u = V - v. Restitution: u = v - v_out for beta <= 1; for larger beta, where 1 + b v_out
  // underflows, u = psi_out - psi with psi = -log(1 + b v) (the spec's w = -exp(-psi)).
  // Energy per unit mass P(x)/m [m^2/s^2]:
  double compression_energy(double distance_from_impact_velocity) const;
  double restitution_energy(double distance_from_separation) const;
  // The approach rate [m/s] at a restitution distance, and the extent of that phase in u.
  double restitution_rate(double distance_from_separation) const;
  double restitution_span() const;
  // dt/du on each phase.
  double compression_time_density(double distance_from_impact_velocity) const;
  double restitution_time_density(double distance_from_separation) const;
  double compression_time_until(double distance_from_impact_velocity) const;
  // The distance u of the force peak (b > 0), and whether the compression time of this law
  // is integrated in two parts split there (custom laws with b > 0).
  double peak_distance() const;
  bool splits_compression_at_peak() const { return !power_law_ && damping_ > 0; }
  double compression_time_from(double distance_from_impact_velocity) const;
  double restitution_time_from(double distance_from_rebound_velocity) const;
  // Power-law fast path: dt/du = K u^-alpha g(u) with g smooth, integrated by Gauss-Jacobi.
  bool uses_singular_rule() const;
  double singular_rule_time(ImpactPhase phase, double distance,
                            const PowerLawCoefficients& law) const;
  // A custom law that is a power law below its first breakpoint (initial_power_law): the
  // same rule on the first piece of each phase, for beta <= 1.
  bool uses_initial_rule() const;
  ImpactState compression_state(double time, double distance) const;
  ImpactState restitution_state(double time, double distance) const;
  // The power law's linear-time history (see history()). Each phase is measured by a
  // distance d from its singular end: u as above for beta <= 1; for beta > 1 the log-rate
  // distance in both phases (compression: d = psi_in - psi, psi_in = log(1 + beta)), where
  // 1 + b v never vanishes. E(d) / d [energy per mass per unit d], v(d), 1 + b v(d):
  double phase_extent(ImpactPhase phase) const;
  double phase_energy_ratio(ImpactPhase phase, double distance) const;
  double phase_rate(ImpactPhase phase, double distance) const;
  double phase_force_factor(ImpactPhase phase, double distance) const;
  std::vector<ImpactState> power_law_history(std::size_t points) const;
  std::vector<ImpactState> quadrature_history(std::size_t points) const;

  // The law: the power law is held by value (the fast path, no allocation), any other law
  // through the caller's pointer.
  const ElasticForce& elastic_force() const {
    return power_law_ ? static_cast<const ElasticForce&>(*power_law_) : *custom_force_;
  }

  double mass_;
  std::optional<PowerLawForce> power_law_;
  std::shared_ptr<const ElasticForce> custom_force_;
  double damping_;
  double velocity_;
  double excess_ratio_;                  // (beta - ln(1 + beta)) / beta^2, 1/2 at beta = 0
  bool restitution_in_log_rate_ = false; // beta > 1: restitution parametrised by psi
  double log_rate_span_ = 0;             // psi_out = -log(1 + b v_out)
  double log_rate_in_ = 0;               // psi_in = log(1 + beta) (set for beta > 1)
  double separation_force_factor_ = 0;   // 1 + b v_out = exp(-psi_out)
  double approach_max_;
  double restitution_;
  // A custom law's breakpoints (ElasticForce::breakpoints) below x_max as phase distances:
  // the time integrals split there, where the density jumps or kinks.
  std::vector<double> compression_breaks_;
  std::vector<double> restitution_breaks_;
  std::optional<PowerLawCoefficients> initial_power_law_; // custom laws only
};

} // namespace impact::reduced
