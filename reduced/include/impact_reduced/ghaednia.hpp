#pragma once
/// @file
/// The elastic-plastic sphere-on-flat loading law with linear strain hardening of
/// H. Ghaednia, M.R.W. Brake, M. Berryhill, R.L. Jackson, "Strain hardening from
/// elastic-perfectly plastic to perfectly elastic flattening single asperity contact",
/// J. Tribol. 141(3):031402 (2019), as an ElasticPlasticContact for impacts.
///
/// The paper itself could not be read here. The formulas below were read in three public
/// implementations, all from the same group (tmd-lab), which agree with each other:
///   - tmd-lab/microslip-rough-contact ROUTINES/FRIC_MODELS/PLASTIC/GHAEDNIA_ET_AL_FLATTENING.m
///     (sphere on flat, written after the paper's equations and citing their numbers,
///     quoted below as (Eq. n)); TESTS/verification_normal_plasticity.m re-draws the
///     paper's Figures 8-12 with it (Delta/R from 0 to 0.05, E_t/E_s from 0.005 to 0.1);
///   - the same repository's ROUTINES/FRIC_MODELS/PLASTIC/SPHERE_PLASTIC_PRE.m and
///     SPHERE_PLASTIC_PRE2.m (two equal spheres: each sphere against the plane of symmetry,
///     with twice the pair's effective radius and modulus and half the interference, which
///     maps onto the formulas below term by term);
///   - tmd-lab/tmdsimpy tmdsimpy/jax/nlforces/roughcontact/_asperity_functions.py
///     (_normal_pl_asperity_loading, the same sphere-on-sphere form in Python).
///
/// Symbols: x (the paper's Delta) the interference (approach) [m], R the effective radius,
/// E* the contact modulus (1/E* = (1-nu_s^2)/E_s + (1-nu_f^2)/E_f, the paper's E, Eq. 3),
/// E_s, nu_s the Young's modulus and Poisson ratio of the yielding sphere, Y its yield
/// strength (S_y), E_t >= 0 its tangent (linear hardening) modulus, r = E_t / E_s.
/// E_s is needed besides E*: the hardening enters only through E_t / E_s and E_s / Y.
///
///   C = 1.295 exp(0.736 nu_s)                                      (Eq. 6)
///   delta_c = (pi C Y / (2 E*))^2 R,  omega* = x / delta_c         (Eq. 5)
///   P_c = (4/3) (R / E*)^2 (C pi Y / 2)^3  (= Hertz's load at delta_c)   (Eq. 29)
///   Hertz (Eqs. 1, 31):  F_e = (4/3) E* sqrt(R) x^(3/2),  a_e = sqrt(R x).
/// For x <= 1.9 delta_c the contact is Hertz's: F = F_e, a = a_e. For x > 1.9 delta_c:
///   a_p = sqrt(R x) (omega* / 1.9)^(B/2),  B = 0.14 exp(23 Y / E*)  (Eqs. 23, 24; the
///         Jackson-Green 2005 contact radius of the elastic-perfectly plastic sphere)
///   Upsilon = -2 sqrt(E_s / Y) r^(1 - (x - delta_c) / R)
///             / ((4 - 3 exp(-2 sqrt(E_s / Y) r)) (1 - r))            (Eq. 26, corrected)
///   a = a_e + (a_p - a_e) exp(Upsilon)                              (Eq. 25)
///   H_G / Y = 2.84 - 0.92 (1 - cos(pi a / R))                       (Eq. 28)
///   F_p = P_c [exp(-omega*^(5/12) / 4) omega*^(3/2)
///              + (4 H_G / (C Y)) (1 - exp(-omega*^(5/9) / 25)) omega*]   (Eq. 27)
///   F = F_p + (F_e - F_p) (1 - exp(-3.3 r))                         (Eq. 30)
/// F_p is the Jackson-Green (2005) load fit evaluated with the hardened contact radius a.
///
/// Discrepancies between readings, and the choices made here:
///   - Eq. 26 as published (transcribed in a comment of GHAEDNIA_ET_AL_FLATTENING.m) reads
///     Upsilon = +sqrt(E_s/Y) r^(1 - x/R) / (0.5 (4 - 3 exp(-2 sqrt(E_s/Y) r)) (1 - r)):
///     positive, and with x instead of x - delta_c in the exponent. That file says the
///     published equation is wrong (the authors were to add a note to the journal) and uses
///     the form above, "from their implementation"; SPHERE_PLASTIC_PRE.m/PRE2.m and
///     tmdsimpy use the same corrected form. The published sign would make exp(Upsilon) > 1
///     and the contact radius grow without bound; the corrected form is implemented. (The
///     square root in the exponential of the denominator is flagged as uncertain in the
///     sphere-on-sphere files; the flat file says it was checked against a draft.)
///   - Eq. 31 (the elastic force) carries a factor pi in the paper according to all three
///     implementations, which drop it as inconsistent with Hertz; F_e here is Hertz's load.
///   - H_G / Y of Eq. 28 is not the hardness of the Jackson-Green law in sphere_flat_fits.hpp
///     (2.84 (1 - exp(-0.82 (a/R)^(-0.7))), read in JG.m); the two differ by less than
///     0.3 % for a/R <= 0.1 and 2 % for a/R <= 0.3. Eq. 28 is used, as in all three readings.
///   - Unloading: none of the three reads an unloading law from this paper (its subject is
///     loading); SPHERE_PLASTIC_PRE.m and tmdsimpy pair it with Brake's (2015) unloading,
///     SPHERE_PLASTIC_PRE2.m with the radius-preserving one after Etsion-Kligerman-Kadin.
///     The latter is implemented, with the contact radius a of Eq. 25 (as PRE2 does), like
///     JacksonGreenContact:
///       R_u = 4 E* a_m^3 / (3 P_m),  x_r = x_max - 3 P_m / (4 E* a_m)
///     (P_m = F(x_max), a_m = a(x_max)); for x_max <= 1.9 delta_c: Hertz on R, x_r = 0.
///
/// The limits in the hardening (measured in tests/reduced/test_ghaednia.cpp):
///   - E_t = 0 (elastic-perfectly plastic): Upsilon = 0 (the limit E_t -> 0+; the power of
///     r is r^p with p = 1 - (x - delta_c)/R > 0 for x < R + delta_c), so a = a_p and F = F_p:
///     the Jackson-Green 2005 loading with Eq. 28's hardness. It stays within 1.2 % of
///     JacksonGreenContact for omega* <= 100 (steel; the largest difference near a/R = 0.26,
///     from the two hardness fits).
///   - E_t -> E_s (perfectly elastic material): Upsilon -> -infinity, a -> a_e, but the
///     weight of Eq. 30 stays 1 - exp(-3.3) = 0.963, so F -> F_e - exp(-3.3) (F_e - F_p(a_e)):
///     the fit does not reach Hertz; it stays below it by 3.7 % of the plastic deficit
///     (F/F_e = 0.98 at omega* = 100 for steel). E_t >= E_s is refused (1 - r in Eq. 26).
///   - The two branches do not join at x = 1.9 delta_c, where a_p = a_e, so a = a_e and F_p
///     does not depend on E_t: F jumps by exp(-3.3 r) (F_p - F_e). At E_t = 0 the jump is
///     +0.43 % for steel (nu = 0.3, Y/E* = 8.7e-3) and -0.19 % for an aluminium sphere
///     (nu = 0.33, Y/E* = 8.6e-3; the sign follows C(nu) through the fit), shrinking by
///     exp(-3.3 r) as E_t grows (+0.016 % / -0.007 % as E_t -> E_s); the slope drops by
///     5.4 % / 6.0 % at E_t = 0. 1.9 delta_c is the breakpoint. Where the jump is upward,
///     the radius-preserving unloading just above it has x_r < 0 (the impact is elastic).
///
/// Range: the implementations' verification re-draws the paper's figures for
/// Delta/R <= 0.05 and 0.005 <= E_t/E_s <= 0.1; the paper's own statement of the range of
/// validity could not be read. The formulas are evaluated as written for any x >= 0, but
/// they mean nothing once a approaches R: Eq. 26's exponent changes sign at
/// x = R + delta_c, and with E_t = 0 the force decreases from x = 1.44 R on (steel,
/// a = 2.25 R there). F increases up to x = R for every E_t tested.
///
/// Accuracy: F, a and dF/dx within 1e-15 relative of the formulas (against mpmath and a
/// long-double re-writing); the loading work (Hertz in closed form, then a Chebyshev series
/// in ln x per octave) within 5e-16 relative of 50-digit tanh-sinh.
/// All in SI units.

#include "impact_reduced/elastic_plastic_impact.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"

#include <memory>
#include <utility>
#include <vector>

namespace impact::reduced {

namespace detail {
class OctaveWorkTable;
}

/// Ghaednia et al. (2019) loading with the radius-preserving Hertzian unloading.
class GhaedniaContact final : public ElasticPlasticContact {
public:
  /// `contact`: R, E*, Y and nu of the yielding sphere; `youngs_modulus` E_s of the sphere
  /// (>= E* (1 - nu^2), the rigid-flat value); `tangent_modulus` E_t, 0 <= E_t < E_s.
  /// Throws InvalidInput naming "radius", "contact_modulus", "yield_strength",
  /// "poisson_ratio", "youngs_modulus" or "tangent_modulus".
  GhaedniaContact(const SphereFlatContact& contact, double youngs_modulus, double tangent_modulus);

  /// F(x) [N], x >= 0 (InvalidInput naming "approach" otherwise); likewise below.
  double loading_force(double approach) const override;
  /// Hertz's work up to 1.9 delta_c; above it a Chebyshev series in ln x per octave, built on
  /// first use and shared by copies of the law (as JacksonGreenContact's).
  double loading_work(double approach) const override;
  /// The inverse of loading_work: Hertz's in closed form, then Newton on the octave's series.
  double loading_approach(double work) const override;
  /// As JacksonGreenContact's: one sum of a series of F(W) above the transition.
  double loading_force_at_work(double work) const override;
  /// Likewise F and dF/dx from the series.
  std::pair<double, double> loading_force_and_stiffness_at_work(double work) const override;
  /// W(x_max) - W(x_max - d) without cancellation for small d (as JacksonGreenContact's).
  double loading_work_below(double approach_max, double distance) const override;
  /// dF/dx [N/m], analytic; the fit's (right) slope at x = 1.9 delta_c.
  double loading_stiffness(double approach) const override;
  /// Both from one evaluation of the fit (the same values as the two calls).
  std::pair<double, double> loading_force_and_stiffness(double approach) const override;
  /// As JacksonGreenContact's: the octave's series of F x and its derivative above the
  /// transition (F within 2.2e-15, dF/dx within 2.4e-13 of the fit's, relative, measured;
  /// 57 ns against the fit's 175 ns).
  std::pair<double, double> loading_force_and_stiffness_from_table(double approach) const override;
  std::vector<double> loading_breakpoints() const override { return {transition_}; }
  /// Hertz's up to 1.9 delta_c.
  std::optional<PowerLawCoefficients> loading_power_law() const override {
    return PowerLawCoefficients{hertz_coefficient_, 1.5};
  }
  /// The radius-preserving Hertzian unloading from x_max > 0 ("approach_max").
  HertzianUnloading unloading(double approach_max) const override;

  /// The contact radius a(x) [m] of Eq. 25 (a_e up to 1.9 delta_c).
  double contact_radius(double approach) const;
  /// Upsilon(x) of the corrected Eq. 26 (0 for E_t = 0).
  double upsilon(double approach) const;
  /// delta_c [m].
  double critical_interference() const { return critical_interference_; }
  /// P_c [N].
  double critical_load() const { return critical_load_; }
  /// 1.9 delta_c [m], where the fit replaces Hertz.
  double transition_approach() const { return transition_; }
  /// The weight of Hertz in Eq. 30, 1 - exp(-3.3 E_t / E_s).
  double elastic_weight() const { return elastic_weight_; }

private:
  struct FitPoint;
  FitPoint fit(double approach) const;
  double fit_force(double approach) const;                        // Eq. 30 above the transition
  double fit_slope(double approach, const FitPoint& point) const; // its dF/dx

  SphereFlatContact contact_;
  double c_;                     // C(nu)
  double b_;                     // B(Y / E*)
  double critical_interference_; // delta_c
  double critical_load_;         // P_c
  double hertz_coefficient_;     // (4/3) E* sqrt(R)
  double modulus_ratio_;         // r = E_t / E_s
  double log_modulus_ratio_;     // ln r (unused for r = 0)
  double upsilon_scale_;         // 2 sqrt(E_s/Y) / ((4 - 3 exp(-2 sqrt(E_s/Y) r)) (1 - r))
  double elastic_weight_;        // 1 - exp(-3.3 r)
  double transition_;            // 1.9 delta_c
  double transition_work_;       // Hertz work up to the transition
  std::shared_ptr<const detail::OctaveWorkTable> work_table_; // the work above the transition
};

} // namespace impact::reduced
