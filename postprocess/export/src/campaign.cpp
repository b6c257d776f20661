// What impact-export reads from a calibration (the JSON of impact-calibrate, layout in
// postprocess/README.md), and the impacts of the calibrated Hertz-type laws.

#include "impact_postprocess/export/simulator_export.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/same_value.hpp"

#include "impact_postprocess/calibration/calibration_json.hpp"

#include "text.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <algorithm>
#include <cmath>

namespace impact::postprocess {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& message) {
  throw ExportInputError(file + ": " + message);
}

// A converged campaign fit at n = 3/2; none if there is no fit.
std::optional<HertzLawFit> hertz_law(const CampaignModelFit* fit, const std::string& model,
                                     const std::string& file, const std::string& where) {
  if (!fit) return std::nullopt;
  if (!fit->fit.converged) fail(file, where + " did not converge: it is not exported");
  if (std::abs(fit->fit.exponent.value - 1.5) > 1e-12)
    fail(file, where + " has n = " + std::to_string(fit->fit.exponent.value) + ", expected 1.5");
  const double c = fit->fit.stiffness.value, damping = fit->fit.parameter.value;
  if (!(std::isfinite(c) && c > 0 && std::isfinite(damping) && damping >= 0))
    fail(file, where + " has no finite positive c and damping constant");
  return HertzLawFit{model, c, damping, fit->fit.quality.rms_residual};
}

} // namespace

ExportCampaign read_export_campaign(const nlohmann::json& json, const std::string& file,
                                    double radius) {
  if (!(std::isfinite(radius) && radius > 0))
    throw ExportInputError("sphere radius must be a finite positive length in m (got " +
                           std::to_string(radius) + ")");
  // The typed reader of the calibration (calibration_json.hpp) checks the format.
  Calibration calibration;
  try {
    calibration = calibration_from_json(json);
  } catch (const CalibrationFormatError& error) {
    fail(file, error.what());
  }

  ExportCampaign campaign;
  campaign.calibration_file = file;
  campaign.radius = radius;
  if (calibration.runs.size() < 2)
    fail(file, "the export needs a campaign of at least two runs (\"runs\" has " +
                   std::to_string(calibration.runs.size()) + ")");
  for (std::size_t i = 0; i < calibration.runs.size(); ++i) {
    const RunCalibration& run = calibration.runs[i];
    const std::string where = "runs[" + std::to_string(i) + "]";
    if (!(std::isfinite(run.mass) && run.mass > 0)) fail(file, where + ".mass is not positive");
    if (i == 0)
      campaign.mass = run.mass;
    else if (!same_value(run.mass, campaign.mass))
      fail(file, where + ".mass = " + std::to_string(run.mass) +
                     " kg differs from runs[0].mass = " + std::to_string(campaign.mass) +
                     " kg: one sphere per export");
    const ImpactFigures& m = run.measured;
    if (!(std::isfinite(m.restitution) && std::isfinite(m.contact_time) &&
          std::isfinite(m.force_max)))
      fail(file, where + ".measured lacks restitution, contact_time or force_max");
    campaign.runs.push_back({run.source, run.velocity, m});
  }
  std::sort(campaign.runs.begin(), campaign.runs.end(),
            [](const auto& a, const auto& b) { return a.velocity < b.velocity; });

  const CampaignCalibration& fits = calibration.campaign;
  if (!fits.fitted) fail(file, "campaign.fitted is not true: the export needs a campaign fit");
  if (!fits.hunt_crossley) fail(file, "campaign.hunt_crossley is null");
  const ModelFit& free_fit = fits.hunt_crossley->fit;
  campaign.free_stiffness = free_fit.stiffness.value;
  campaign.free_exponent = free_fit.exponent.value;
  campaign.free_damping = free_fit.parameter.value;
  campaign.free_rms_residual = free_fit.quality.rms_residual;

  const auto hunt_crossley =
      hertz_law(fits.hunt_crossley_hertz_exponent ? &*fits.hunt_crossley_hertz_exponent : nullptr,
                std::string(model_keys::hunt_crossley), file,
                "campaign.hunt_crossley_hertz_exponent");
  if (!hunt_crossley)
    fail(file,
         "campaign.hunt_crossley_hertz_exponent is null (Simbody needs n = 3/2): "
         "recalibrate with the current impact-calibrate");
  campaign.hunt_crossley = *hunt_crossley;
  campaign.kuwabara_kono = hertz_law(fits.find("kuwabara-kono"), "kuwabara-kono", file,
                                     "campaign.comparison_laws[kuwabara-kono]");
  campaign.tsuji = hertz_law(fits.find("tsuji"), "tsuji", file, "campaign.comparison_laws[tsuji]");
  // Thornton's law fitted by the calibration (c, x_y): the LIGGGHTS export's plastic contact,
  // E* = 3 c / (4 sqrt(R)), p_y = 3 c sqrt(x_y) / (2 pi R) (plastic_models.hpp). The fit does
  // not split E* into the two bodies: the plate is given as rigid, the sphere E* with nu = 0
  // (nu enters only LIGGGHTS' tangential stiffness, unused by a normal impact).
  if (const CampaignModelFit* thornton = fits.find("thornton");
      thornton && thornton->fit.converged) {
    const double c = thornton->fit.stiffness.value, x_y = thornton->fit.parameter.value;
    if (std::isfinite(c) && c > 0 && std::isfinite(x_y) && x_y > 0) {
      PlasticContact plastic;
      plastic.contact_modulus = 0.75 * c / std::sqrt(radius);
      plastic.sphere_youngs_modulus = plastic.contact_modulus;
      plastic.sphere_poisson_ratio = 0;
      plastic.yield_pressure = thornton_yield_pressure(c, x_y, radius);
      plastic.yield_basis =
          "the calibration's Thornton fit (campaign.comparison_laws[thornton]: "
          "c = " +
          export_text::rounded(c) + " N/m^1.5, x_y = " + export_text::rounded(x_y) +
          " m; p_y = 3 c sqrt(x_y) / (2 pi R))";
      campaign.plastic = plastic;
    }
  }
  if (!campaign.kuwabara_kono && !campaign.tsuji)
    fail(file,
         "the calibration has no campaign fit of kuwabara-kono or tsuji, the laws that "
         "LAMMPS's granular damping can represent: calibrate with --laws all (or a list "
         "holding kuwabara-kono or tsuji)");
  return campaign;
}

ImpactFigures hertz_law_impact(const HertzLawFit& law, double mass, double velocity) {
  if (law.model == model_keys::hunt_crossley) {
    const auto response =
        reduced::HuntCrossleyImpact(mass, law.stiffness, 1.5, law.damping, velocity).response();
    return response.figures();
  }
  const reduced::ContactSetup setup{mass, law.stiffness, 1.5};
  const auto result =
      reduced::integrate_impact(mass, velocity,
                                reduced::comparison_law(law.model).force_law(law.damping, setup),
                                1e-12);
  return result.figures();
}

} // namespace impact::postprocess
