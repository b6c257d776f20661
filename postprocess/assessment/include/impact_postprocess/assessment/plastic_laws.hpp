#pragma once
/// @file
/// The elastic-plastic laws against an elastic-plastic FEM campaign (plastic_laws.cpp).

#include "impact_postprocess/assessment/compared_models.hpp"
#include "impact_postprocess/assessment/fem_runs.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace impact::postprocess {

/// One elastic-plastic law against an elastic-plastic FEM campaign (plastic_laws.cpp): its
/// restitution and permanent approach over the tested range and at the runs, and its
/// force-approach loop at each run (reduced::elastic_plastic_impact, _loop).
struct PlasticLawCurve {
  std::string key; ///< the calibration's key ("thornton-material", "jackson-green", ...)
  std::string label;
  bool fitted = false; ///< a campaign fit (else nothing fitted)
  /// c [N/m^1.5] of the law's spring (NaN for a restitution fit, which has none).
  double stiffness = 0;
  /// The law's other values: its yield parameter ("x_y" [m], "Y" [Pa]), its damping, or a
  /// restitution fit's critical velocity "V_c" [m/s] and yield strain "eps_y" [1].
  std::vector<ModelParameter> parameters;
  std::size_t free_parameters = 0;            ///< of the campaign fit
  std::vector<double> velocity;               ///< m/s, the curve's grid
  std::vector<double> restitution;            ///< e on the grid
  std::vector<double> permanent_approach;     ///< x_p [m] on the grid (empty: a restitution fit)
  std::vector<double> run_restitution;        ///< e at each report run (NaN where it failed)
  std::vector<double> run_permanent_approach; ///< x_p [m] at each report run (likewise)
  std::vector<ImpactHistory> loops;           ///< per report run (empty where it failed)
  /// A damped elastic-plastic law (viscous and plastic loss): not a reference of the
  /// plastic family's slope.
  bool damped = false;
};

/// The elastic-plastic laws of an elastic-plastic campaign (none otherwise).
struct PlasticLaws {
  double yield_velocity;               ///< V_y [m/s], Johnson's p_y = 1.6 Y (Thornton's)
  double jackson_green_yield_velocity; ///< V_y [m/s] with p_y = C(nu) Y
  double mass;                         ///< kg, the runs' median: of V_y and the curves
  double yield_strength;               ///< Y [Pa] of the plate's material
  /// Where the material's constants come from (the models layer's words,
  /// SphereFlatScenario::basis).
  std::string material_basis;
  /// The runs' hardening that the elastic-plastic springs leave out (hardening_left_out of the
  /// first run; "" when the runs record none).
  std::string hardening_left_out;
  /// No-fit Thornton and Jackson–Green, Jackson–Green–Marghitu's restitution fit (e only,
  /// no loops), then the campaign fits; then the damped elastic-plastic laws
  /// (damped_plastic_models.hpp) from the material and fitted.
  std::vector<PlasticLawCurve> laws;
  std::vector<double> fem_permanent_approach; ///< m, per report run (NaN: not recorded)
};

} // namespace impact::postprocess
