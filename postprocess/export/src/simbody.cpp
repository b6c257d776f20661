// Simbody 3.7: the Hunt–Crossley law at n = 3/2 as HuntCrossleyForce body parameters, and
// the C++ header that sets them (mapping in simulator_export.hpp).

#include "impact_postprocess/export/simulator_export.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include "exporter.hpp"
#include "text.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <cmath>
#include <sstream>

namespace impact::postprocess {

SimbodyContact simbody_contact(double stiffness, double damping, double radius) {
  reduced::require_positive("stiffness", stiffness);
  reduced::require_non_negative("damping", damping);
  reduced::require_positive("radius", radius);
  return {3 * stiffness / std::sqrt(2 * radius), 2 * damping / 3};
}

namespace export_text {

std::string simbody_file(const ExportCampaign& campaign, const SimbodyContact& contact,
                         const std::vector<ImpactFigures>& model) {
  const HertzLawFit& law = campaign.hunt_crossley;
  std::ostringstream out;
  out << "// Simbody 3.7 HuntCrossleyForce parameters of the calibrated sphere-plate contact.\n"
      << "// Written by impact-export from " << campaign.calibration_file << ".\n"
      << "//\n"
      << "// Model: Hunt-Crossley F = c x^(3/2) (1 + b dx/dt), the campaign fit with n held at\n"
      << "// 3/2 (campaign.hunt_crossley_hertz_exponent): c = " << rounded(law.stiffness)
      << " N/m^1.5, b = " << rounded(law.damping) << " s/m,\n"
      << "// RMS force-history residual " << rounded(100 * law.rms_residual, 3)
      << " % of the peak force.\n"
      << "// Simbody's HuntCrossleyForce has n = 3/2 only. The free campaign fit has n = "
      << rounded(campaign.free_exponent, 5) << " (c = " << rounded(campaign.free_stiffness)
      << " N/m^n,\n"
      << "// b = " << rounded(campaign.free_damping) << " s/m, RMS residual "
      << rounded(100 * campaign.free_rms_residual, 3)
      << " %); the n = 3/2 fit is the closest law Simbody has, and\n"
      << "// the errors below are those of the n = 3/2 law itself.\n"
      << "//\n"
      << "// Simbody's law (HuntCrossleyForceImpl): f = (4/3) sqrt(R) E x^(3/2) (1 + (3/2) c_s "
         "v),\n"
      << "// E = (k1' k2' / (k1' + k2'))^(3/2), k' = k^(2/3), c_s = (c1 k2' + c2 k1') / (k1' + "
         "k2').\n"
      << "// Both surfaces get the same k and c_s: k = 3 c / sqrt(2 R), c_s = 2 b / 3, R = the\n"
      << "// sphere radius (ContactGeometry::Sphere) against a ContactGeometry::HalfSpace.\n"
      << "// Velocities of the campaign: " << rounded(campaign.runs.front().velocity) << " to "
      << rounded(campaign.runs.back().velocity) << " m/s. The law against the FEM:\n"
      << error_table("//", campaign, model) << "\n"
      << "#pragma once\n\n"
      << "#include <Simbody.h>\n\n"
      << "namespace impact_contact {\n\n"
      << "inline constexpr double sphere_mass = " << as_written(campaign.mass) << ";   // kg\n"
      << "inline constexpr double sphere_radius = " << as_written(campaign.radius)
      << "; // m, of ContactGeometry::Sphere\n"
      << "inline constexpr double stiffness = " << as_written(contact.surface_stiffness)
      << ";   // Pa, both surfaces\n"
      << "inline constexpr double dissipation = " << as_written(contact.surface_dissipation)
      << "; // s/m, both surfaces\n\n"
      << "/// Gives the sphere's and the plane's surfaces of a HuntCrossleyForce the calibrated\n"
      << "/// contact (no friction, as in the FEM).\n"
      << "inline void set_body_parameters(SimTK::HuntCrossleyForce& force,\n"
      << "                                SimTK::ContactSurfaceIndex sphere,\n"
      << "                                SimTK::ContactSurfaceIndex plane) {\n"
      << "  force.setBodyParameters(sphere, stiffness, dissipation, 0, 0, 0);\n"
      << "  force.setBodyParameters(plane, stiffness, dissipation, 0, 0, 0);\n"
      << "}\n\n"
      << "} // namespace impact_contact\n";
  return out.str();
}

} // namespace export_text
namespace exporters {

using json = nlohmann::json;

std::vector<ExportedFile> simbody(const ExportCampaign& campaign, const CampaignImpact&) {
  ExportList list;
  const HertzLawFit& hc = campaign.hunt_crossley;
  const SimbodyContact simbody = simbody_contact(hc.stiffness, hc.damping, campaign.radius);
  const auto hc_figures = law_on_campaign(campaign, hc);
  list.files.emplace_back("simbody/impact_contact.hpp",
                          export_text::simbody_file(campaign, simbody, hc_figures));
  list.exports.push_back(
      {{"tool", "simbody"},
       {"tool_version", "3.7"},
       {"file", "simbody/impact_contact.hpp"},
       {"model", std::string(model_keys::hunt_crossley)},
       {"basis", "campaign.hunt_crossley_hertz_exponent"},
       {"force_law", "F = c x^(3/2) (1 + b dx/dt)"},
       {"calibrated",
        {{"c", value_unit(hc.stiffness, "N/m^1.5")},
         {"n", value_unit(1.5, "1")},
         {"b", value_unit(hc.damping, "s/m")}}},
       {"parameters",
        {{"stiffness", value_unit(simbody.surface_stiffness, "Pa")},
         {"dissipation", value_unit(simbody.surface_dissipation, "s/m")}}},
       {"mapping",
        "HuntCrossleyForce::setBodyParameters on both surfaces: stiffness = 3 c / "
        "sqrt(2 R), dissipation = 2 b / 3 (Simbody: f = (4/3) sqrt(R) E x^(3/2) "
        "(1 + (3/2) c_s v))"},
       {"same_law", true},
       {"note", "Simbody's law has n = 3/2; the free campaign fit has n = " +
                    export_text::rounded(campaign.free_exponent, 5) +
                    ", so the n = 3/2 campaign fit is exported"},
       {"reference_velocity", nullptr},
       {"predictions", predictions_json(campaign, hc_figures)}});

  return list.zipped();
}

} // namespace exporters
} // namespace impact::postprocess
