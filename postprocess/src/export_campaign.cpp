// What impact-export reads from a calibration (the JSON of impact-calibrate, layout in
// postprocess/README.md), and the impacts of the calibrated Hertz-type laws.

#include "impact_postprocess/simulator_export.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <algorithm>
#include <cmath>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& message) {
  throw ExportInputError(file + ": " + message);
}

// The number at `key` of `object`, which must be finite (and positive unless allowed).
double number_at(const json& object, const std::string& key, const std::string& file,
                 const std::string& where, bool positive = true) {
  if (!object.is_object() || !object.contains(key) || !object.at(key).is_number())
    fail(file, where + "." + key + " is missing or not a number");
  const double value = object.at(key).get<double>();
  if (!std::isfinite(value) || (positive && !(value > 0)))
    fail(file, where + "." + key + " must be a finite" + (positive ? " positive" : "") +
                   " number (got " + std::to_string(value) + ")");
  return value;
}

double parameter(const json& fit, const std::string& name, const std::string& file,
                 const std::string& where) {
  if (!fit.contains("parameters") || !fit.at("parameters").contains(name))
    fail(file, where + ".parameters." + name + " is missing");
  return number_at(fit.at("parameters").at(name), "value", file,
                   where + ".parameters." + name);
}

// A campaign fit at n = 3/2 with damping parameter `damping_name`; none if `fit` is null.
std::optional<HertzLawFit> hertz_law(const json& fit, const std::string& model,
                                     const std::string& damping_name, const std::string& file,
                                     const std::string& where) {
  if (fit.is_null()) return std::nullopt;
  if (!fit.value("converged", false)) fail(file, where + " did not converge: it is not exported");
  const double exponent = parameter(fit, "n", file, where);
  if (std::abs(exponent - 1.5) > 1e-12)
    fail(file, where + " has n = " + std::to_string(exponent) + ", expected 1.5");
  return HertzLawFit{model, parameter(fit, "c", file, where),
                     parameter(fit, damping_name, file, where),
                     number_at(fit, "rms_residual", file, where)};
}

} // namespace

ExportCampaign read_export_campaign(const json& calibration, const std::string& file,
                                    double radius) {
  if (!calibration.is_object() || calibration.value("format", "") != "impact-calibration")
    fail(file, "not a calibration of impact-calibrate (\"format\" is not \"impact-calibration\")");
  if (calibration.value("format_version", 0) != 1)
    fail(file, "format_version must be 1");
  if (!(std::isfinite(radius) && radius > 0))
    throw ExportInputError("sphere radius must be a finite positive length in m (got " +
                           std::to_string(radius) + ")");

  ExportCampaign campaign;
  campaign.calibration_file = file;
  campaign.radius = radius;

  const json& runs = calibration.value("runs", json::array());
  if (!runs.is_array() || runs.size() < 2)
    fail(file, "the export needs a campaign of at least two runs (\"runs\" has " +
                   std::to_string(runs.is_array() ? runs.size() : 0) + ")");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string where = "runs[" + std::to_string(i) + "]";
    const json& run = runs[i];
    const double mass = number_at(run, "mass", file, where);
    if (i == 0) campaign.mass = mass;
    else if (std::abs(mass / campaign.mass - 1) > 1e-9)
      fail(file, where + ".mass = " + std::to_string(mass) + " kg differs from runs[0].mass = " +
                     std::to_string(campaign.mass) + " kg: one sphere per export");
    if (!run.contains("measured")) fail(file, where + ".measured is missing");
    const json& measured = run.at("measured");
    const std::string m = where + ".measured";
    campaign.runs.push_back({run.value("source", ""), number_at(run, "impact_velocity", file, where),
                             {number_at(measured, "restitution", file, m),
                              number_at(measured, "contact_time", file, m),
                              number_at(measured, "force_max", file, m)}});
  }
  std::sort(campaign.runs.begin(), campaign.runs.end(),
            [](const auto& a, const auto& b) { return a.velocity < b.velocity; });

  const json& multibody = calibration.value("multibody", json());
  if (multibody.is_null()) fail(file, "\"multibody\" is null: the campaign was not fitted");
  campaign.free_stiffness = number_at(multibody, "c", file, "multibody");
  campaign.free_exponent = number_at(multibody, "n", file, "multibody");
  campaign.free_damping = number_at(multibody, "b", file, "multibody", false);

  if (!calibration.contains("campaign") || !calibration.at("campaign").value("fitted", false))
    fail(file, "campaign.fitted is not true: the export needs a campaign fit");
  const json& fits = calibration.at("campaign");
  const json& free_fit = fits.value("hunt_crossley", json());
  if (free_fit.is_null()) fail(file, "campaign.hunt_crossley is null");
  campaign.free_rms_residual = number_at(free_fit, "rms_residual", file, "campaign.hunt_crossley");

  const auto hunt_crossley =
      hertz_law(fits.value("hunt_crossley_hertz_exponent", json()), "hunt-crossley", "b", file,
                "campaign.hunt_crossley_hertz_exponent");
  if (!hunt_crossley)
    fail(file, "campaign.hunt_crossley_hertz_exponent is null (Simbody needs n = 3/2): "
               "recalibrate with the current impact-calibrate");
  campaign.hunt_crossley = *hunt_crossley;

  for (const json& law : fits.value("comparison_laws", json::array())) {
    const std::string model = law.value("model", "");
    const std::string where = "campaign.comparison_laws[" + model + "]";
    if (model == "kuwabara-kono") campaign.kuwabara_kono = hertz_law(law, model, "A", file, where);
    if (model == "tsuji") campaign.tsuji = hertz_law(law, model, "eta", file, where);
  }
  if (!campaign.kuwabara_kono && !campaign.tsuji)
    fail(file, "the calibration has no campaign fit of kuwabara-kono or tsuji, the laws that "
               "LAMMPS's granular damping can represent: calibrate with --laws all (or a list "
               "holding kuwabara-kono or tsuji)");
  return campaign;
}

ImpactFigures hertz_law_impact(const HertzLawFit& law, double mass, double velocity) {
  if (law.model == "hunt-crossley") {
    const auto response =
        reduced::HuntCrossleyImpact(mass, law.stiffness, 1.5, law.damping, velocity).response();
    return {response.restitution, response.contact_time, response.force_max};
  }
  const reduced::ContactSetup setup{mass, law.stiffness, 1.5};
  const auto result = reduced::integrate_impact(
      mass, velocity, reduced::comparison_law(law.model).force_law(law.damping, setup), 1e-12);
  return {result.restitution, result.contact_time, result.force_max};
}

} // namespace impact::postprocess
