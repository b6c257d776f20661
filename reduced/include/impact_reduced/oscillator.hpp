#pragma once
/// @file
/// Free decay of a damped oscillator with power-law stiffness (Olshanskiy):
///
///     m x'' + k x' + c1 x + c2 |x|^(v+1) sign(x) = 0,   x(0) = -a0,  x'(0) = 0.
///
/// The successive amplitudes a_i = |x(t_i)| at the extremes x'(t_i) = 0, i = 1..N, by four
/// methods: a tight-tolerance numerical integration (the reference), the implicit
/// recurrence of the averaged half-cycle frequency, and the explicit Lambert-W recurrence
/// with the exact W0 or with the source's elementary approximation of W. The mathematics is
/// in doc/theory/reduced-models.md, section 2. Units are SI throughout.
///
/// Every function validates its input and throws InvalidInput (see invalid_input.hpp) whose
/// `parameter()` is one of "mass", "viscous", "c1", "c2", "power", "a0", "count" (the names
/// of the `impact-reduced oscillator` options); no function returns NaN or Inf.

#include <string>
#include <vector>

namespace impact::reduced {

/// The oscillator and its initial deflection.
struct PowerLawOscillator {
  double mass;                ///< m  [kg], finite, > 0                          ("mass")
  double viscous_damping;     ///< k  [N s/m], finite, >= 0, underdamped (below)  ("viscous")
  double linear_stiffness;    ///< c1 [N/m], finite, > 0                          ("c1")
  double nonlinear_stiffness; ///< c2 [N/m^(v+1)], finite, any sign: > 0 hardening,
                              ///< < 0 softening, 0 linear                        ("c2")
  double power;               ///< v  [-], finite, >= 0                           ("power")
  double initial_amplitude;   ///< a0 [m], finite, > 0; x(0) = -a0                ("a0")
};

/// One extreme of the free decay: x'(time) = 0, amplitude = |x(time)|.
struct OscillatorExtreme {
  int index;        ///< i = 1, 2, ... (i = 0 would be the start, x = -a0)
  double time;      ///< t_i [s]
  double amplitude; ///< a_i [m], > 0 (or 0 after underflow of a very long decay)
};

/// How the amplitudes are computed.
enum class AmplitudeMethod {
  numeric,        ///< free_decay_extremes (reference)
  implicit,       ///< a_i = a_{i-1} exp(-k pi / (2 m omega_i)), omega_i of (a_{i-1} + a_i)/2
  lambert,        ///< explicit Lambert recurrence, exact principal branch W0
  lambert_approx, ///< the same with W(z) ~ z - z^2 + 27 z^3 / (2 (16 z + 9))
};

/// Largest `count` accepted by the functions below.
constexpr int max_extreme_count = 10000;

/// Checks every parameter; throws InvalidInput naming the first one that is invalid:
/// - mass > 0, viscous >= 0, c1 > 0, power >= 0, a0 > 0, all finite; c2 finite;
/// - underdamped linear part: w_*^2 = c1/m - (k/(2m))^2 > 0 ("viscous");
/// - for v = 0 the equation is linear with stiffness c1 + c2, which must be > 0 ("c2")
///   and underdamped: (c1 + c2)/m - (k/(2m))^2 > 0 ("viscous");
/// - softening (c2 < 0, v > 0): a0 below the barrier (c1/|c2|)^(1/v), where the restoring
///   force vanishes and beyond which the motion escapes ("a0").
void validate_oscillator(const PowerLawOscillator& oscillator);

/// w_* [rad/s] = sqrt(c1/m - (k/(2m))^2), the damped frequency of the linear part.
/// Relative accuracy ~1e-16. Validates as validate_oscillator.
double damped_linear_frequency(const PowerLawOscillator& oscillator);

/// alpha(v) = (2/pi) Gamma((v+3)/2) Gamma(1/2) / Gamma((v+4)/2), the averaging coefficient
/// of the power-law force over a half-cycle; alpha(0) = 1, alpha(1) = 8/(3 pi), alpha(2) = 3/4.
/// power: finite, >= 0 ("power"). Relative accuracy a few 1e-16 (Boost tgamma_ratio).
double averaging_coefficient(double power);

/// The source's elementary approximation of the principal Lambert W:
/// W(z) ~ z - z^2 + 27 z^3 / (2 (16 z + 9)). Relative error below 0.22 % on [-0.2, 0.3]
/// (exact at z = 0, error O(z^4)); it degrades quickly outside (about 28 % at z = -1/e).
/// z: finite, in [-0.2, 0.3] ("z"); the domain is enforced because outside it the
/// formula is not an approximation of W worth having.
double lambert_w0_elementary(double z);

/// Reference: numerical integration of the equation of motion (Boost.Odeint, Cash-Karp 5(4)
/// with step control at relative tolerance 1e-13 on the state scaled by the last amplitude
/// and the linear frequency sqrt(c1/m)); each extreme is located by event location: the step
/// over which x' changes sign is repeated from its start with the step length that a
/// bracketing root finder (TOMS 748) drives to x' = 0 to machine precision. The zero
/// crossings x = 0, where the force is not smooth, are located the same way and never stepped
/// over. The integration restarts from each extreme in scaled variables, so that the relative
/// accuracy does not degrade as the amplitudes decay.
/// count: number of extremes, in [1, max_extreme_count] ("count").
/// Accuracy: relative error of a_i and t_i about 1e-12 per extreme, accumulating about
/// linearly with i (measured in the tests: 1e-10 after 200 extremes of an exactly solvable
/// linear decay, 3e-11 after 50 extremes of undamped nonlinear cases against quadrature).
/// Throws std::runtime_error if an extreme is not found within 10^6 steps (cannot happen
/// for inputs that pass validate_oscillator).
std::vector<OscillatorExtreme> free_decay_extremes(const PowerLawOscillator& oscillator, int count);

/// Amplitudes a_1..a_count [m] by `method`. count in [1, max_extreme_count] ("count").
/// - numeric: the amplitudes of free_decay_extremes.
/// - implicit: the implicit recurrence of the spec, each step solved for a_i/a_{i-1} in
///   (0, 1] by a bracketing root finder (TOMS 748) to machine precision. An approximation
///   of the equation of motion whose error grows with i: over the 10 extremes of the
///   published cases at most 4.3 % (quadratic) and 7.1 % (cubic) from the numeric
///   amplitudes. Softening needs the averaged frequency real at the first step,
///   w_*^2 + alpha c2 a0^v / m > 0 ("a0").
/// - lambert: the explicit recurrence of the spec, hardening y_i = ln(A a_{i-1}^v) -
///   k pi v/(2 m w_*), a_i = [-W0(-exp(y_i))/A]^(1/v); softening a_i = [W0(exp(z_i))/A]^(1/v)
///   with z_i formed as y_i. Evaluated in the algebraically identical form
///   a_i = a_{i-1} exp(-k pi/(2 m w_*)) (W(s)/s)^(1/v), s = -+exp(y_i), which neither
///   underflows nor cancels. A further approximation, valid for alpha |c2| a0^v / m << w_*^2
///   (beyond, it can even give growing amplitudes): over the 10 extremes of the published
///   cases at most 3.3 % (quadratic) and 5.4 % (cubic) from the numeric amplitudes, and
///   within 0.54 units of the last printed digit of the published formula column.
///   Hardening needs -exp(y_i) >= -1/e, the real domain of W0 ("a0").
/// - lambert_approx: as lambert with lambert_w0_elementary in place of W0; needs the
///   argument -+exp(y_i) in [-0.2, 0.3] ("a0"). Reproduces the published formula columns
///   digit for digit.
/// Cost per extreme (measured): numeric 0.1-0.2 ms, implicit 0.3 us, lambert 0.1 us.
/// Special cases, exact for all three approximations: c2 = 0 or v = 0 (linear, stiffness
/// c1 + c2): a_i = a_{i-1} exp(-k pi / (2 m omega)), omega^2 = (c1 + c2)/m - (k/(2m))^2;
/// k = 0: a_i = a0.
std::vector<double> free_decay_amplitudes(const PowerLawOscillator& oscillator, int count,
                                          AmplitudeMethod method);

/// The method of a name "numeric", "implicit", "lambert", "lambert-approx"; throws
/// InvalidInput ("method") for any other name.
AmplitudeMethod amplitude_method_from_name(const std::string& name);

} // namespace impact::reduced
