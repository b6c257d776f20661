// The thin-plate model of the validity map (steps.hpp): Zener's impact of a sphere on
// an infinite Kirchhoff plate (reduced/thin_plate.hpp) with the run's own materials and
// plate thickness, and a given Hunt–Crossley damping b; with rigid = true the same contact on
// a rigid support (the massive-plate model of the map).

#include "steps.hpp"

#include "impact_postprocess/run/scenario_materials.hpp"

#include <impact_reduced/thin_plate.hpp>

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

namespace impact::postprocess::detail {

ThinPlatePrediction thin_plate_prediction(const FemRun& run, double damping, bool rigid) {
  ThinPlatePrediction prediction;
  const ScenarioMaterials materials = scenario_materials({run});
  const auto youngs_modulus =
      material_constant(run, fem_format::plate_body, fem_format::youngs_modulus);
  const auto poisson_ratio =
      material_constant(run, fem_format::plate_body, fem_format::poissons_ratio);
  const auto density = material_constant(run, fem_format::plate_body, fem_format::density);
  const auto thickness = text_number(run, fem_format::plate_thickness.path);
  if (!materials.hertz_from_runs || !youngs_modulus || !poisson_ratio || !density || !thickness) {
    prediction.missing = NoValue{NoValueReason::plate_not_recorded, ""};
    return prediction;
  }
  try {
    const reduced::KirchhoffPlate plate{*youngs_modulus, *poisson_ratio, *density, *thickness};
    const double impedance =
        rigid ? std::numeric_limits<double>::infinity() : reduced::plate_point_impedance(plate);
    const reduced::ThinPlateImpact model(materials.hertz_stiffness, 1.5, damping, run.mass,
                                         impedance);
    const auto result = model.impact(run.impact_velocity);
    prediction.quantities = result.figures();
    prediction.values = ThinPlateValues{materials.hertz_stiffness, impedance, result.zener_lambda,
                                        run.impact_velocity};
  } catch (const std::exception& error) {
    prediction.missing = NoValue{NoValueReason::thin_plate_failed, error.what()};
  }
  return prediction;
}

std::optional<double> thin_plate_damping(const FemRun& reference, bool rigid) {
  const auto restitution = [&](double b) {
    const auto prediction = thin_plate_prediction(reference, b, rigid);
    return prediction.quantities ? prediction.quantities->restitution
                                 : std::numeric_limits<double>::quiet_NaN();
  };
  const double target = reference.restitution;
  const double elastic = restitution(0.0);
  if (!std::isfinite(elastic)) return std::nullopt;
  // The plate alone loses more than the FEM: no damping reproduces it; b = 0 is the nearest.
  if (elastic <= target) return 0.0;
  // e falls with b on a massive plate (lambda << 1): bracket by doubling, then TOMS 748.
  double high = 1e-3 / reference.impact_velocity;
  while (restitution(high) > target) {
    high *= 2;
    if (high * reference.impact_velocity > 1e3) return std::nullopt;
  }
  std::uintmax_t iterations = 100;
  const auto root =
      boost::math::tools::toms748_solve([&](double b) { return restitution(b) - target; }, 0.0,
                                        high, elastic - target, restitution(high) - target,
                                        boost::math::tools::eps_tolerance<double>(40), iterations);
  return 0.5 * (root.first + root.second);
}

} // namespace impact::postprocess::detail
