// The thin-plate model of the validity map (report_parts.hpp): Zener's impact of a sphere on
// an infinite Kirchhoff plate (reduced/thin_plate.hpp) with the run's own materials and
// plate thickness, and a given Hunt–Crossley damping b.

#include "report_parts.hpp"

#include "impact_postprocess/scenario_materials.hpp"

#include <impact_reduced/thin_plate.hpp>

#include <cmath>
#include <sstream>

namespace impact::postprocess::detail {

ThinPlatePrediction thin_plate_prediction(const FemRun& run, double damping) {
  ThinPlatePrediction prediction;
  const ScenarioMaterials materials = scenario_materials({run});
  const auto youngs_modulus = material_constant(run, "Plate", "Young's modulus");
  const auto poisson_ratio = material_constant(run, "Plate", "Poisson's ratio");
  const auto density = material_constant(run, "Plate", "Density");
  const auto thickness = text_number(run, "Scenario/Plate thickness");
  if (!materials.hertz_from_runs || !youngs_modulus || !poisson_ratio || !density || !thickness) {
    prediction.missing = "the run does not record the plate's material (Plate/<Model>/Young's "
                         "modulus, Poisson's ratio, Density), its thickness (Scenario/Plate "
                         "thickness) or the sphere's (Sphere/..., Scenario/Sphere radius)";
    return prediction;
  }
  try {
    const reduced::KirchhoffPlate plate{*youngs_modulus, *poisson_ratio, *density, *thickness};
    const double impedance = reduced::plate_point_impedance(plate);
    const reduced::ThinPlateImpact model(materials.hertz_stiffness, 1.5, damping, run.mass,
                                         impedance);
    const auto result = model.impact(run.impact_velocity);
    prediction.quantities = ImpactQuantities{result.restitution, result.contact_time,
                                             result.force_max, result.time_force_max,
                                             result.approach_max};
    std::ostringstream text;
    text.precision(4);
    text << "c = " << materials.hertz_stiffness << " N/m^1.5, n = 1.5, Z = " << impedance
         << " N s/m, lambda = " << result.zener_lambda << " at " << run.impact_velocity << " m/s";
    prediction.parameters = text.str();
  } catch (const std::exception& error) {
    prediction.missing = std::string("the thin-plate model cannot be evaluated: ") + error.what();
  }
  return prediction;
}

} // namespace impact::postprocess::detail
