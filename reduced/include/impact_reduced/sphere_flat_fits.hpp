#pragma once
/// @file
/// Elastic-plastic sphere-on-flat contact laws fitted to finite-element results, in the
/// normalisation of their papers (the published-fit oracle of the FEM indentation test),
/// and the Jackson-Green law as an ElasticPlasticContact for impacts.
///
/// Symbols: omega the interference (approach) [m], R the effective radius, E* the contact
/// modulus (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, called E' by Jackson-Green and E by
/// Kogut-Etsion), Y the yield strength and nu the Poisson ratio of the yielding body.
///
/// Jackson & Green, "A finite element study of elasto-plastic hemispherical contact against
/// a rigid flat", J. Tribol. 127:343-354 (2005). Read in two implementations that agree:
/// tmd-lab/microslip-rough-contact ROUTINES/FRIC_MODELS/PLASTIC/SPHERE_PLASTIC_PRE.m (C,
/// delta_y, B, contact radius, P_c and the load fit; it uses Ghaednia et al.'s variant of H_G),
/// and a Jackson-Green rough-surface script JG.m found by the code search (same C, omega_c,
/// P_c, B, contact radius and load fit, with the H_G below):
///   C = 1.295 exp(0.736 nu),  omega_c = (pi C Y / (2 E*))^2 R,
///   P_c = (4/3) (R / E*)^2 (C pi Y / 2)^3   (= the Hertz load at omega_c),
///   omega* = omega / omega_c;  for omega* <= 1.9 the contact is Hertz's:
///     P / P_c = omega*^(3/2),  a = sqrt(R omega);
///   for omega* > 1.9:
///     P / P_c = exp(-omega*^(5/12) / 4) omega*^(3/2)
///               + (4 H_G / (C Y)) (1 - exp(-omega*^(5/9) / 25)) omega*,
///     H_G / Y = 2.84 (1 - exp(-0.82 (a/R)^(-0.7))),
///     a = sqrt(R omega) (omega* / 1.9)^(B/2),  B = 0.14 exp(23 Y / E*).
///   H_G / Y is read in JG.m only (one reading): flagged as such in the README.
///   The two branches do not join exactly at omega* = 1.9: the fit is about 0.5 % above
///   Hertz there (measured in tests/reduced/test_sphere_flat_fits.cpp), a jump of the force
///   that the impact integration treats as a breakpoint.
///
/// Kogut & Etsion, "Elastic-plastic contact analysis of a sphere and a rigid flat",
/// J. Appl. Mech. 69:657-662 (2002). Read in one implementation (KE.m, the Kogut-Etsion
/// counterpart of JG.m, found by the code search); the constants are those of that reading
/// only:
///   K = 0.454 + 0.41 nu,  H = 2.8 Y,  omega_c = (pi K H / (2 E*))^2 R,
///   P_c = (2/3) pi K H R omega_c   (= the Hertz load at omega_c),
///   P / P_c = omega*^(3/2)              for omega* <= 1,
///           = 1.03 omega*^1.425         for 1 < omega* <= 6,
///           = 1.40 omega*^1.263         for 6 < omega* <= 110,
///           = (3 / K) omega*            beyond (fully plastic, mean pressure H).
///
/// Unloading (for the impact): Hertzian on the radius that keeps the contact radius a_m of
/// the maximum, R_u = 4 E* a_m^3 / (3 P_m), residual interference
/// omega_r = omega_max - 3 P_m / (4 E* a_m), the same principle as Thornton's R_p. This is
/// the unloading that tmd-lab/microslip-rough-contact SPHERE_PLASTIC_PRE2.m attributes to
/// Etsion, Kligerman & Kadin (Int. J. Solids Struct. 42:3716, 2005). EKK's own empirical
/// fits of the unloading curve and of omega_r could not be read here and are NOT
/// implemented; Brake's (2015) unloading is available as read in one implementation
/// (JacksonGreenUnloading::brake). Where the loading fit lies above Hertz (just above
/// omega* = 1.9) this omega_r is negative: the surfaces then separate at omega = 0 with no
/// dent (residual 0), see residual_interference.
///
/// All functions: SI units; InvalidInput naming the parameter for non-positive radius,
/// modulus, strength, negative or non-finite interference, Poisson ratio outside (-1, 0.5).
/// Accuracy: a few ulps for the closed forms; the loading work of the Jackson-Green fit
/// (a Chebyshev series in ln x per octave, JacksonGreenContact::loading_work) to about 1e-15
/// relative.

#include "impact_reduced/elastic_plastic_impact.hpp"

#include <memory>

namespace impact::reduced {

namespace detail {
class OctaveWorkTable;
}

/// The contact: effective radius R [m], contact modulus E* [Pa], yield strength Y [Pa] and
/// Poisson ratio nu of the yielding body.
struct SphereFlatContact {
  double radius;
  double contact_modulus;
  double yield_strength;
  double poisson_ratio;
};

// ---- Jackson & Green (2005) ----

/// omega_c [m].
double jackson_green_critical_interference(const SphereFlatContact& contact);
/// P_c [N].
double jackson_green_critical_load(const SphereFlatContact& contact);
/// Contact radius a [m] at interference omega >= 0 [m].
double jackson_green_contact_radius(double interference, const SphereFlatContact& contact);
/// P / P_c at omega* = omega / omega_c >= 0 (depends on Y/E* and nu through H_G and B).
double jackson_green_load_ratio(double interference_ratio, const SphereFlatContact& contact);
/// P [N] at omega >= 0 [m].
double jackson_green_load(double interference, const SphereFlatContact& contact);

// ---- Kogut & Etsion (2002) ----

/// omega_c [m].
double kogut_etsion_critical_interference(const SphereFlatContact& contact);
/// P_c [N].
double kogut_etsion_critical_load(const SphereFlatContact& contact);
/// P / P_c at omega* >= 0 (depends on nu through K beyond omega* = 110).
double kogut_etsion_load_ratio(double interference_ratio, double poisson_ratio);

// ---- Unloading ----

/// The Hertzian unloading branch after Jackson-Green loading to (omega_max, P_m):
///   - contact_radius: keeps the contact radius a_m of the maximum (above);
///   - brake: the unloading of Brake (Int. J. Solids Struct., 2015) as read in
///     tmd-lab/microslip-rough-contact ROUTINES/FRIC_MODELS/PLASTIC/SPHERE_PLASTIC_PRE.m (one
///     reading; the paper could not be read here): omega_r = omega_max - P_m / ((4/3) E*
///     sqrt(R omega_max)) and R_u = P_m^2 / ((4/3 E*)^2 (omega_max - omega_r)^3), i.e. the
///     elastic recovery is omega_max P_m / P_Hertz(omega_max) and R_u = R P_Hertz / P_m.
enum class JacksonGreenUnloading { contact_radius, brake };

/// Residual interference [m] after loading along Jackson-Green to omega_max >= 0 and the
/// Hertzian unloading `rule`; max(0, omega_r) (contact_radius: omega_r = omega_max -
/// 3 P_m / (4 E* a_m)).
double jackson_green_residual_interference(
    double interference_max, const SphereFlatContact& contact,
    JacksonGreenUnloading rule = JacksonGreenUnloading::contact_radius);

/// Jackson-Green loading with a Hertzian unloading rule. The residual approach of
/// `unloading` is the (possibly negative) zero of the Hertzian branch; the impact separates
/// at max(0, x_r).
class JacksonGreenContact final : public ElasticPlasticContact {
public:
  explicit JacksonGreenContact(const SphereFlatContact& contact,
                               JacksonGreenUnloading rule = JacksonGreenUnloading::contact_radius);
  double loading_force(double approach) const override;
  /// Hertz's work below the transition; above it a Chebyshev series in ln x per octave
  /// (x_t 2^k to x_t 2^(k+1)), built on first use and shared by copies of the law: one sum
  /// per call, within 2e-16 of the fit's integral (measured against composite Gauss-Legendre,
  /// tests/reduced/test_octave_work_table.cpp).
  double loading_work(double approach) const override;
  double loading_stiffness(double approach) const override;
  /// Both from one evaluation of the fit's terms (the same values as the two calls).
  std::pair<double, double> loading_force_and_stiffness(double approach) const override;
  /// Hertz's below the transition; above it the octave's series of F x and its derivative
  /// (OctaveWorkTable::force_and_slope: F within 2.2e-15, dF/dx within 2.4e-13 of the fit's,
  /// relative, measured), 58 ns against the fit's 132 ns (measured).
  std::pair<double, double> loading_force_and_stiffness_from_table(double approach) const override;
  /// Hertz's inverse below the transition; above it Newton's method on the octave's series.
  double loading_approach(double work) const override;
  /// Hertz's in closed form; above the transition one Chebyshev sum, F(W) on an eighth of an
  /// octave's work (within 3e-15 of the fit's at the inverse, test_octave_work_table.cpp).
  double loading_force_at_work(double work) const override;
  /// Likewise F and dF/dx (the latter within 1.5e-13 of the fit's, measured; the peak's
  /// search only locates the root with it, F_max is the fit's force there).
  std::pair<double, double> loading_force_and_stiffness_at_work(double work) const override;
  /// Hertz's difference in closed form (expm1, log1p), the series' differences term by term
  /// above the transition: the loading work's accuracy also for d << x_max.
  double loading_work_below(double approach_max, double distance) const override;
  std::vector<double> loading_breakpoints() const override { return {transition_}; }
  /// Hertz's (4/3) E* sqrt(R) x^(3/2) up to the transition.
  std::optional<PowerLawCoefficients> loading_power_law() const override;
  HertzianUnloading unloading(double approach_max) const override;
  double critical_interference() const { return critical_interference_; }

private:
  SphereFlatContact contact_;
  JacksonGreenUnloading rule_;
  double critical_interference_;
  double transition_;                                         // 1.9 omega_c
  double transition_work_;                                    // Hertz work up to the transition
  double critical_load_;                                      // P_c
  double c_;                                                  // C(nu)
  double b_;                                                  // B(Y / E*)
  std::shared_ptr<const detail::OctaveWorkTable> work_table_; // the work above the transition
  double fit_force(double approach) const; // the fit's force above the transition
};

} // namespace impact::reduced
