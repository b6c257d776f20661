#pragma once
/// @file
/// A sphere hitting an infinite thin (Kirchhoff) plate: Zener's model.
///
/// C. Zener, "The intrinsic inelasticity of large plates", Phys. Rev. 59 (1941) 669; the
/// equations re-derived in "Approximation Solution for the Zener Impact Theory", Mathematics
/// 9(18) (2021) 2222, doi:10.3390/math9182222. (Of that article only the abstract could be
/// read here; lambda below is derived from the model equations in Zener's normalisation, see
/// README.md, "Sphere on a thin plate".)
///
/// Model. An infinite Kirchhoff plate loaded at a point moves there with the velocity
/// w' = F / Z, its point impedance Z = 8 sqrt(D rho h) a real constant (the flexural waves
/// carry the energy F^2 / Z away and never return). The plate point is a dashpot in series
/// with the contact. Sphere of mass m, velocity v (towards the plate positive), approach
/// (indentation) x = z_sphere - w:
///
///     m v' = -F,   x' = v - F / Z,   F = c x^n (1 + b x')  (F >= 0, x >= 0),
///     x(0) = 0, v(0) = V > 0, w(0) = 0.
///
/// With Hunt–Crossley damping (b > 0) the force depends on x', which depends on F; the
/// relation is linear in F and solved explicitly:
///
///     F = c x^n (1 + b v - b F / Z)   =>   F = c x^n (1 + b v) / (1 + b c x^n / Z).
///
/// Scaled by Zener's units t0 = (m V^(1-n) / c)^(1/(n+1)), x0 = V t0 (so that the rigid
/// elastic impact reads sigma'' = -sigma^n), with sigma = x / x0, u = v / V, tau = t / t0:
///
///     u' = -phi,  sigma' = u - lambda phi,  phi = sigma^n (1 + beta u) / (1 + beta lambda sigma^n),
///     lambda = m / (Z t0) = m^(n/(n+1)) c^(1/(n+1)) V^((n-1)/(n+1)) / Z,   beta = b V.
///
/// For b = 0 this is sigma'' + sigma^n + lambda (sigma^n)' = 0, sigma(0) = 0, sigma'(0) = 1:
/// with n = 3/2 Zener's equation, and lambda his inelasticity parameter. The impact depends
/// on (n, lambda, beta) only.
///
/// End of contact and repeated contacts. During contact F > 0, so v falls; 1 + b v cannot
/// reach 0 (u' is proportional to (1 + beta u): it would take infinite time), so F vanishes
/// only when x returns to 0, and there x' = v: x returns to 0 from above only with v <= 0.
/// After it the plate point is at rest (w' = F / Z = 0) and the sphere moves away at
/// v <= 0, so x = v (t - t_sep) <= 0 for ever: without gravity this model has exactly one
/// contact (number_of_contacts is always 1; tests/reduced/test_thin_plate.cpp checks it
/// with an independent integration that keeps integrating after the separation).
/// The plate point does not move back: it keeps the deflection w = m V (1 + e) / Z.
///
/// Valid while the flexural waves do not return from the plate's edges during the contact
/// and the contact radius is small against h (Zener's conditions).

#include "impact_reduced/impact_figures.hpp"

#include <cstddef>
#include <vector>

namespace impact::reduced {

/// An isotropic Kirchhoff plate: Young's modulus [Pa] > 0, Poisson's ratio [-] in (-1, 0.5),
/// density [kg/m^3] > 0, thickness [m] > 0.
struct KirchhoffPlate {
  double youngs_modulus;
  double poisson_ratio;
  double density;
  double thickness;
};

/// Flexural rigidity D = E h^3 / (12 (1 - nu^2)) [N m]. A few ulps. Throws InvalidInput
/// naming the field ("plate.thickness", ...) outside the ranges of KirchhoffPlate.
double flexural_rigidity(const KirchhoffPlate& plate);

/// Point impedance of the infinite plate Z = 8 sqrt(D rho h) [N s/m] (force over the
/// velocity of the loaded point, real and frequency-independent). A few ulps. Throws
/// InvalidInput like flexural_rigidity.
double plate_point_impedance(const KirchhoffPlate& plate);

/// The characteristic figures of one impact on the plate. SI units.
struct ThinPlateImpactResult {
  double restitution;             ///< -(sphere velocity after separation) / V [-], in [0, 1]
  double contact_time;            ///< s, from first touch to separation
  double force_max;               ///< N, peak contact force
  double time_force_max;          ///< s, its time
  double approach_max;            ///< m, peak approach (indentation) x
  double time_approach_max;       ///< s, its time
  double plate_energy_fraction;   ///< integral F^2 / Z dt over m V^2 / 2: radiated into the plate
  double damping_energy_fraction; ///< integral b c x^n x'^2 dt over m V^2 / 2: contact damping
  double plate_deflection;        ///< m, w of the plate point after the impact (it stays there)
  std::size_t number_of_contacts; ///< always 1 in this model (see the file comment)
  double
      zener_lambda; ///< lambda = m / (Z t0) [-] (Zener's parameter for n = 3/2)  /// The figures by which impacts are compared (impact_figures.hpp).
  ImpactFigures figures() const {
    return {restitution, contact_time, force_max, time_force_max, approach_max};
  }
};

/// One point of the time history. SI units.
struct ThinPlateSample {
  double time;             ///< s since first touch
  double approach;         ///< m, x = z_sphere - w
  double sphere_velocity;  ///< m/s, towards the plate positive
  double plate_deflection; ///< m, w of the loaded point (towards the plate's far side positive)
  double force;            ///< N, contact force
};

/// Impacts of one sphere–contact–plate system at any velocity.
///
/// Method: the scaled equations of the file comment, plus sphere displacement and the two
/// energy integrals, integrated by Boost.Odeint Cash–Karp 5(4) with exact event location
/// by TOMS 748 (the library's reference integrator, impact_ode.hpp): maximum approach
/// (x' = 0), separation (x = 0, or 1 + b v = 0, which cannot come first), force maximum
/// (dF/dt = 0, analytic).
///
/// Accuracy (measured, tests/reduced/test_thin_plate.cpp, against an independent
/// Dormand–Prince integration in long double at 1e-17 of the unscaled system in sphere
/// position and plate deflection; lambda in [0.01, 10], b V in {0, 0.1, 1}, n = 3/2):
///   - default relative_tolerance 1e-11: restitution within 6e-11 absolute (relative error
///     grows as e falls: 9e-8 at lambda = 10, where e = 6.8e-6), contact time 3e-9, peak
///     force 6e-11, peak approach 4e-11 relative;
///   - relative_tolerance 1e-14: restitution 1.8e-13 absolute (2.7e-10 relative at
///     lambda = 10), contact time 1.7e-11, peak force 1.5e-13, peak approach 1e-13 relative.
/// Energy balance 1 - e^2 = plate + damping fractions within 4e-10 (default tolerance,
/// lambda in [1e-3, 200]); the rigid limit (Z = infinity) within 2.5e-10 of the closed form
/// of HuntCrossleyImpact (n in {1, 1.5, 2.5}, b V up to 5). Times of the peaks: ~1e-9.
/// Cost: ~0.2-2 ms per impact (longer contacts at large lambda take more steps).
class ThinPlateImpact {
public:
  /// Contact law F = c x^n (1 + b x'): stiffness c [N/m^n] > 0, exponent n [-] > 0,
  /// damping b [s/m] >= 0; sphere mass m [kg] > 0; plate point impedance Z [N s/m] > 0,
  /// +infinity allowed (rigid plate: Hunt–Crossley on a fixed obstacle). Throws
  /// InvalidInput naming the parameter ("stiffness", "exponent", "damping", "mass",
  /// "impedance") outside these ranges or for NaN.
  ThinPlateImpact(double stiffness, double exponent, double damping, double mass, double impedance);

  /// The impact at `velocity` [m/s] > 0 (finite). `relative_tolerance` in [1e-14, 1e-3]:
  /// local error tolerance on the scaled state (results are within ~20 x of it). Throws
  /// InvalidInput for bad velocity or tolerance; std::runtime_error if the integration
  /// cannot meet the tolerance.
  ThinPlateImpactResult impact(double velocity, double relative_tolerance = 1e-11) const;

  /// The time history at `points` >= 2 instants equally spaced over [0, contact time], both
  /// ends included, each by re-stepping the accepted step that contains it (the accuracy of
  /// impact()). Throws InvalidInput like impact() and for points < 2.
  std::vector<ThinPlateSample> history(double velocity, std::size_t points,
                                       double relative_tolerance = 1e-11) const;

  /// lambda = m / (Z t0) [-] at `velocity` [m/s] > 0, t0 = (m V^(1-n) / c)^(1/(n+1)); 0 for
  /// a rigid plate. A few ulps.
  double zener_lambda(double velocity) const;

  double stiffness() const { return stiffness_; }
  double exponent() const { return exponent_; }
  double damping() const { return damping_; }
  double mass() const { return mass_; }
  double impedance() const { return impedance_; }

private:
  double stiffness_;
  double exponent_;
  double damping_;
  double mass_;
  double impedance_;
};

/// Zener's inelasticity parameter of a Hertz contact (n = 3/2) of an elastic sphere of
/// radius R [m] > 0, density rho_s [kg/m^3] > 0, Young's modulus E_s [Pa] > 0 and Poisson's
/// ratio nu_s in (-1, 0.5), on `plate`, at impact velocity V [m/s] > 0:
///
///     lambda = m^(3/5) c^(2/5) V^(1/5) / Z,   m = (4/3) pi R^3 rho_s,
///     c = (4/3) E* sqrt(R) (contact_formulas.hpp),   Z = plate_point_impedance(plate),
///
/// which in material terms is (with 1/E* = (1 - nu_s^2)/E_s + (1 - nu_p^2)/E_p)
///
///     lambda = (pi^(3/5) / sqrt(3)) (R/h)^2 (V / sqrt(E_p/rho_p))^(1/5) (rho_s/rho_p)^(3/5)
///              (E*/E_p)^(2/5) sqrt(1 - nu_p^2).
///
/// A few ulps (both forms agree to 1e-15 in the tests). Throws InvalidInput naming the
/// parameter ("sphere_radius", "sphere_density", "sphere_youngs_modulus",
/// "sphere_poisson_ratio", "plate.*", "velocity").
double zener_lambda(double sphere_radius, double sphere_density, double sphere_youngs_modulus,
                    double sphere_poisson_ratio, const KirchhoffPlate& plate, double velocity);

} // namespace impact::reduced
