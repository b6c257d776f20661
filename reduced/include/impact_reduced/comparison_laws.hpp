#pragma once
/// @file
/// Comparison contact laws: the dissipative force laws of the literature that Hunt–Crossley
/// is compared with. Each law is one entry of a registry, chosen by name: its force
/// F(x, x') for a damping parameter, and the mapping its authors give from a target
/// coefficient of restitution e (at impact velocity V) to that damping. The restitution that
/// the law then REALLY produces comes from integrate_impact (impact_ode.hpp); for most
/// mappings it differs from the target by several per cent at e < 0.8.
///
/// Elastic part: F_el = c x^n (Hertz-type, `stiffness` c in N/m^n, `exponent` n); the linear
/// Kelvin–Voigt law has n = 1 (c is then the spring constant k in N/m); Tsuji and
/// Kuwabara–Kono are Hertz laws, n = 3/2. The formulas and their sources are in each entry's
/// `formula` and `reference` and in reduced/src/law_*.cpp.
///
/// Laws (names for `impact-reduced law --model`): kelvin-voigt, lankarani-nikravesh, flores,
/// gonthier, hu-guo, zhiying-qishao, tsuji, tsuji-clamped, kuwabara-kono,
/// kuwabara-kono-no-tension (the same force, but the bodies separate when it returns to 0:
/// ContactEnd::zero_force).

#include "impact_reduced/impact_ode.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::reduced {

/// The impacting body and the elastic part of the contact.
struct ContactSetup {
  double mass;      ///< kg, > 0
  double stiffness; ///< c in N/m^n, > 0
  double exponent;  ///< n, > 0
};

/// One comparison law. Adding a law = one new entry (see reduced/src/law_catalogue.hpp).
struct ComparisonLaw {
  std::string name;                        ///< command-line name, e.g. "lankarani-nikravesh"
  std::string formula;                     ///< force and damping map, in plain text
  std::string reference;                   ///< where the damping map comes from
  std::string damping_name;                ///< symbol of the damping parameter, e.g. "b"
  std::string damping_unit;                ///< e.g. "s/m"
  std::optional<double> required_exponent; ///< the law is defined for this n only
  /// Damping parameter that the law's own formula assigns to restitution e in (0, 1] at
  /// impact velocity V (m/s). Arguments are validated by the caller (evaluate_comparison_law
  /// or comparison_law_damping).
  std::function<double(double restitution, double velocity, const ContactSetup& setup)>
      damping_for_restitution;
  /// The contact force law for a damping parameter (>= 0).
  std::function<ContactForceLaw(double damping, const ContactSetup& setup)> force_law;
  /// When its contact ends (integrate_impact's `end`).
  ContactEnd contact_end = ContactEnd::zero_approach;
};

/// All registered laws, in a fixed order.
const std::vector<ComparisonLaw>& comparison_laws();

/// The names of the registered laws, in the same order.
std::vector<std::string> comparison_law_names();

/// The law called `name`; throws InvalidInput("model") listing the known names otherwise.
const ComparisonLaw& comparison_law(const std::string& name);

/// Validated damping of `law` for restitution e in (0, 1] at velocity V > 0. Throws
/// InvalidInput naming "restitution", "velocity", "mass", "stiffness" or "exponent" (also when
/// the law requires another exponent).
double comparison_law_damping(const ComparisonLaw& law, const ContactSetup& setup,
                              double restitution, double velocity);

/// A law evaluated for a target restitution: the damping it assigns, the impact it then
/// produces, and how far that restitution is from the target.
struct ComparisonLawImpact {
  double damping;           ///< in the law's damping_unit
  OdeImpactResult impact;   ///< integrate_impact of the law with that damping
  double restitution_error; ///< (produced - target) / target
};

/// Evaluates `law` at target restitution e and impact velocity V (see
/// comparison_law_damping for the validation). The default tolerance 1e-12 gives the
/// produced restitution to ~1e-11 also for the laws with x^(1/2) and x^(1/4) factors, whose
/// integration error is larger than for Hunt–Crossley (about 30 x the tolerance). Throws InvalidInput("restitution") naming the
/// law and parameters if the law with that damping holds the body (ContactDoesNotEnd).
ComparisonLawImpact evaluate_comparison_law(const ComparisonLaw& law, const ContactSetup& setup,
                                            double restitution, double velocity,
                                            double relative_tolerance = 1e-12);

// ---- Helpers of individual laws, exposed for tests and reports ----

/// Damping ratio zeta of the linear oscillator with restitution e (over the half period):
/// e = exp(-zeta pi / sqrt(1 - zeta^2))  <=>  zeta = -ln e / sqrt(pi^2 + ln^2 e). e in (0, 1].
double linear_oscillator_damping_ratio(double restitution);

/// Tsuji-type damping factor alpha(e) = -sqrt(5) ln e / sqrt(ln^2 e + pi^2), so that
/// F = c x^(3/2) + alpha sqrt(m c) x^(1/4) x'. e in (0, 1]. Measured: the unclamped law then
/// produces e exactly (to 2e-12 at rtol 1e-13); with the no-tension clamp it does not.
double tsuji_alpha(double restitution);

/// First coefficient of the viscoelastic-sphere restitution series
/// e = 1 - gamma1 q + gamma2 q^2 - ..., with q = A (c/m)^(2/5) V^(1/5):
/// gamma1 = (6/5) (5/4)^(3/5) B(3/5, 3/2) = 1.7301733 (= (3/2) x 1.15344 of Schwager and
/// Pöschel 1998, whose dissipative constant carries the factor 3/2), gamma2 = (3/5) gamma1^2
/// (Ramírez et al. 1999).
double brilliantov_gamma1();

/// The two-term series e(V) ~ 1 - gamma1 q + (3/5) gamma1^2 q^2 for the Kuwabara–Kono /
/// Brilliantov law with dissipative constant A (s): shows the trend 1 - e ~ V^(1/5); valid
/// for small q (q < 0.1 to about 1e-3).
double brilliantov_restitution_series(double dissipative_constant, const ContactSetup& setup,
                                      double velocity);

} // namespace impact::reduced
