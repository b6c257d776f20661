#pragma once
/// @file
/// The dissipative constant A [s] of the viscoelastic-sphere law (Kuwabara–Kono /
/// Brilliantov, F = c x^(3/2) + (3/2) A c x^(1/2) x') from the material, without fitting.
///
/// A Kelvin–Voigt body with Young's modulus Y, Poisson's ratio nu and retardation times
/// tau_d (deviatoric) and tau_v (volumetric),
///     sigma = E1 (eps_d + tau_d eps_d') + E2 (tr eps + tau_v tr eps') 1   (eps_d: deviatoric strain),
///     E1 = Y / (1 + nu) (= 2G),  E2 = Y / (3 (1 - 2 nu)) (= K),
/// has the viscosities eta1 = tau_d E1 (shear) and eta2 = tau_v E2 (bulk). In the quasi-static
/// theory of the viscoelastic sphere (N. V. Brilliantov, F. Spahn, J.-M. Hertzsch,
/// T. Pöschel, Phys. Rev. E 53 (1996) 5382; also quoted by T. Schwager, T. Pöschel,
/// Phys. Rev. E 57 (1998) 650):
///     A = (1/3) (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1) (1 - nu^2)(1 - 2 nu) / (Y nu^2),
/// which in the retardation times reads
///     A = (1 - nu) [tau_v (1 + nu) - tau_d (1 - 2 nu)]^2 / (3 nu^2 [tau_v (1 + nu) + 2 tau_d (1 - 2 nu)]).
/// Y drops out. With tau_d = tau_v = tau the viscous stress is tau times the elastic one and
/// A = tau exactly (the force is F_el + tau dF_el/dt).
///
/// Two bodies: each surface moves by its compliance k_i = (1 - nu_i^2) / Y_i times the same
/// pressure integral, so to first order in the dissipation the contact has the compliance-
/// weighted mean A = (k1 A1 + k2 A2) / (k1 + k2); exact when A1 = A2.
///
/// The theory assumes the quasi-static regime (contact time much longer than the time waves
/// take to cross the contact zone) and tau small against the contact time; it has no wave
/// radiation into the bodies, so an FEM plate that radiates energy loses more than this A says.

namespace impact::reduced {

/// A Kelvin–Voigt body at the contact.
struct KelvinVoigtBody {
  double youngs_modulus;              ///< Y [Pa], > 0
  double poisson_ratio;               ///< nu, in (0, 0.5)
  double deviatoric_retardation_time; ///< tau_d [s], >= 0
  double volumetric_retardation_time; ///< tau_v [s], >= 0
};

/// A [s] of one body (formula above). Ranges: nu in (0, 0.5) (the formula has nu^2 in its
/// denominator), tau_d, tau_v >= 0 and finite. Accuracy: a few ulps. Throws InvalidInput
/// ("poisson_ratio", "deviatoric_retardation_time", "volumetric_retardation_time").
double kuwabara_kono_dissipative_constant(double poisson_ratio, double deviatoric_retardation_time,
                                          double volumetric_retardation_time);

/// A [s] of the contact of two bodies (compliance-weighted mean, above). Also validates
/// youngs_modulus > 0; the parameter names are prefixed "first." and "second.".
double kuwabara_kono_dissipative_constant(const KelvinVoigtBody& first,
                                          const KelvinVoigtBody& second);

} // namespace impact::reduced
