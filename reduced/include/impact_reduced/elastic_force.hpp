#pragma once
/// @file
/// The elastic part f(x) of a Hunt-Crossley contact law F = f(x) (1 + b dx/dt).

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace impact::reduced {

/// An increasing elastic force f(x) [N] of the approach x [m], f(0) = 0, with its
/// potential P(x) = integral_0^x f [J]. The impact formulas work with P, so a law is
/// fully described by f, P and the slope f' (used only to locate the force maximum).
/// The coefficients of a power law f(x) = c x^n: stiffness c [N/m^n], exponent n > 0.
struct PowerLawCoefficients {
  double stiffness;
  double exponent;
};

class ElasticForce {
public:
  virtual ~ElasticForce() = default;
  /// f(x) [N] for x >= 0.
  virtual double force(double approach) const = 0;
  /// P(x) = integral_0^x f [J] for x >= 0.
  virtual double potential(double approach) const = 0;
  /// f'(x) [N/m] for x > 0.
  virtual double slope(double approach) const = 0;
  /// {force(x), slope(x)} at once, the same values (the force peak's search needs both).
  virtual std::pair<double, double> force_and_slope(double approach) const {
    return {force(approach), slope(approach)};
  }
  /// The approach x >= 0 with P(x) = potential (potential >= 0). The default solves
  /// P(x) = potential by bracketing and TOMS 748 to full double precision.
  virtual double approach_at_potential(double potential) const;
  /// f at the approach where P = potential: f(approach_at_potential(potential)) by default.
  /// The time integrals need only this pair; a law that tabulates P may return f from its
  /// table (to the table's accuracy) instead of evaluating f again.
  virtual double force_at_potential(double potential) const {
    return force(approach_at_potential(potential));
  }
  /// {f, f'} at the approach where P = potential (the force peak's search needs only these):
  /// force_and_slope(approach_at_potential(potential)) by default; a law that tabulates P may
  /// return them from its table.
  virtual std::pair<double, double> force_and_slope_at_potential(double potential) const {
    return force_and_slope(approach_at_potential(potential));
  }
  /// Approaches where f or its slope jumps: the time integrals split there. Default: none.
  virtual std::vector<double> breakpoints() const { return {}; }
  /// If f is exactly a power law c x^n from x = 0 to its first breakpoint: its coefficients
  /// (the time integrals then take the power law's Gauss-Jacobi rule on that piece). Default:
  /// none.
  virtual std::optional<PowerLawCoefficients> initial_power_law() const { return std::nullopt; }
};

/// The power law f(x) = c x^n (Hertz: n = 3/2), the fast path: P and its inverse are
/// closed forms. Ranges: c > 0 [N/m^n], n > 0. Throws InvalidInput otherwise.
class PowerLawForce final : public ElasticForce {
public:
  PowerLawForce(double stiffness, double exponent);
  double stiffness() const { return stiffness_; }
  double exponent() const { return exponent_; }
  double force(double approach) const override;
  double potential(double approach) const override;
  double slope(double approach) const override;
  double approach_at_potential(double potential) const override;

private:
  double stiffness_;
  double exponent_;
};

/// A user-supplied law: f, its potential P and its slope f' as callables. The caller
/// guarantees f(0) = 0, f increasing, and P' = f; results are then as accurate as the
/// callables (P near its maximum limits v(x) there, see HuntCrossleyImpact).
class CustomElasticForce final : public ElasticForce {
public:
  using Function = std::function<double(double)>;
  CustomElasticForce(Function force, Function potential, Function slope);
  double force(double approach) const override { return force_(approach); }
  double potential(double approach) const override { return potential_(approach); }
  double slope(double approach) const override { return slope_(approach); }

private:
  Function force_;
  Function potential_;
  Function slope_;
};

} // namespace impact::reduced
