#pragma once
/// @file
/// What the runs' scenario says about yielding: the elastic-plastic contact of Thornton's law
/// (the no-fit "thornton-material" model of the calibration and the LIGGGHTS export), read
/// from the parameters impact-fem stores as text attributes of each run file.

#include "impact_postprocess/run/fem_run.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The elastic-plastic contact of the scenario for Thornton's law: the elastic constants of
/// the two bodies and the limiting contact pressure.
struct PlasticContact {
  double sphere_youngs_modulus;               ///< Pa
  double sphere_poisson_ratio;                ///< -
  std::optional<double> plate_youngs_modulus; ///< Pa; none: a rigid plate (or E* not split)
  std::optional<double> plate_poisson_ratio;  ///< -; none: a rigid plate (or E* not split)
  double contact_modulus;                     ///< E* [Pa] of the two bodies
  double yield_pressure;                      ///< p_y [Pa]
  double yield_strength;                      ///< Y [Pa] of the body that yields first
  double yield_poisson_ratio;                 ///< nu of that body (Jackson–Green's C(nu))
  bool elastic_plastic = false;               ///< that body's material model is elastic-plastic
  std::string yield_basis;                    ///< where p_y comes from, in words
};

/// A body with a yield strength whose elastic constants are not recorded; what() names the
/// run and the parameter.
class PlasticContactError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The plastic contact of the runs' scenario, or none when no body records a yield strength.
/// Read from the first run's parameters: a body's yield strength Y is "<Body>/Yield strength"
/// when > 0 (one per body: an elastic-plastic body's initial flow stress, else the strength
/// impact-fem checks the stresses against; result files written before it was one per body
/// give an elastic-plastic body's in "<Body>/Elastic-plastic/Yield strength"); its
/// elastic constants "<Body>/<Model>/Young's modulus" and "Poisson's ratio";
/// "Plate/Material model = rigid" is a rigid plate. The limiting pressure is Johnson's
/// p_y = 1.6 Y (Contact Mechanics, 1985, sec. 4.2; the p_y of Thornton 1997) of the body that
/// yields first, the lower Y. Hardening does not enter Thornton's law. Throws
/// PlasticContactError naming the run and the parameter when a body's elastic constants are
/// missing.
std::optional<PlasticContact> scenario_plastic_contact(const std::vector<FemRun>& runs);

/// How the hardening the run records enters the elastic–perfectly-plastic laws (Thornton,
/// Jackson–Green): it does not; the sentence names the hardening of each elastic-plastic
/// body ("<Body>/Elastic-plastic/Hardening law" linear with "Hardening modulus" > 0, or
/// johnson-cook with "Johnson-Cook B" or "Johnson-Cook C" > 0) that the laws leave out.
std::string hardening_note(const FemRun& run);

/// The hardening of each elastic-plastic body of the run that those laws leave out, in words
/// ("the Plate's Johnson-Cook B = 2.75e+08 Pa, C = 0.022"); "" when the run records none.
std::string hardening_left_out(const FemRun& run);

} // namespace impact::postprocess
