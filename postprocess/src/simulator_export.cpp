// The export directory of impact-export: the files for Simbody, MuJoCo and LAMMPS and the
// manifest export.json that lists them with their parameters, the reduced model each one
// carries and that model's impacts at the campaign's velocities (format in
// postprocess/README.md).

#include "impact_postprocess/simulator_export.hpp"

#include "export_text.hpp"

#include <cmath>
#include <fstream>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

json figures_json(double velocity, const ImpactFigures& figures) {
  return {{"impact_velocity", velocity},
          {"restitution", figures.restitution},
          {"contact_time", figures.contact_time},
          {"force_max", figures.force_max}};
}

json value_unit(double value, const std::string& unit) {
  return {{"value", value}, {"unit", unit}};
}

std::vector<ImpactFigures> law_on_campaign(const ExportCampaign& campaign, const HertzLawFit& law) {
  std::vector<ImpactFigures> figures;
  for (const auto& run : campaign.runs)
    figures.push_back(hertz_law_impact(law, campaign.mass, run.velocity));
  return figures;
}

json predictions_json(const ExportCampaign& campaign, const std::vector<ImpactFigures>& figures) {
  json list = json::array();
  for (std::size_t i = 0; i < figures.size(); ++i)
    list.push_back(figures_json(campaign.runs[i].velocity, figures[i]));
  return list;
}

const CampaignImpact& reference_run(const ExportCampaign& campaign,
                                    std::optional<double> velocity) {
  if (!velocity) return campaign.runs[(campaign.runs.size() - 1) / 2];
  std::string velocities;
  for (const auto& run : campaign.runs) {
    if (std::abs(run.velocity / *velocity - 1) <= 1e-6) return run;
    velocities += (velocities.empty() ? "" : ", ") + export_text::rounded(run.velocity);
  }
  throw ExportInputError("reference velocity " + export_text::rounded(*velocity) +
                         " m/s is not a velocity of the campaign (" + velocities + " m/s)");
}

void write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

} // namespace

json write_exports(const ExportCampaign& campaign, std::optional<double> reference_velocity,
                   const fs::path& directory) {
  const CampaignImpact& reference = reference_run(campaign, reference_velocity);

  json fem = json::array();
  for (const auto& run : campaign.runs) {
    json entry = figures_json(run.velocity, run.fem);
    entry["source"] = run.source;
    fem.push_back(entry);
  }

  // Everything is computed before anything is written: bad input leaves no files.
  std::vector<std::pair<fs::path, std::string>> files;
  json exports = json::array();

  const HertzLawFit& hc = campaign.hunt_crossley;
  const SimbodyContact simbody = simbody_contact(hc.stiffness, hc.damping, campaign.radius);
  const auto hc_figures = law_on_campaign(campaign, hc);
  files.emplace_back("simbody/impact_contact.hpp",
                     export_text::simbody_file(campaign, simbody, hc_figures));
  exports.push_back(
      {{"tool", "simbody"},
       {"tool_version", "3.7"},
       {"file", "simbody/impact_contact.hpp"},
       {"model", "hunt-crossley"},
       {"basis", "campaign.hunt_crossley_hertz_exponent"},
       {"force_law", "F = c x^(3/2) (1 + b dx/dt)"},
       {"calibrated", {{"c", value_unit(hc.stiffness, "N/m^1.5")}, {"n", value_unit(1.5, "1")},
                       {"b", value_unit(hc.damping, "s/m")}}},
       {"parameters", {{"stiffness", value_unit(simbody.surface_stiffness, "Pa")},
                       {"dissipation", value_unit(simbody.surface_dissipation, "s/m")}}},
       {"mapping", "HuntCrossleyForce::setBodyParameters on both surfaces: stiffness = 3 c / "
                   "sqrt(2 R), dissipation = 2 b / 3 (Simbody: f = (4/3) sqrt(R) E x^(3/2) "
                   "(1 + (3/2) c_s v))"},
       {"same_law", true},
       {"note", "Simbody's law has n = 3/2; the free campaign fit has n = " +
                    export_text::rounded(campaign.free_exponent, 5) +
                    ", so the n = 3/2 campaign fit is exported"},
       {"reference_velocity", nullptr},
       {"predictions", predictions_json(campaign, hc_figures)}});

  const MujocoContact mujoco = mujoco_contact(reference.fem.restitution,
                                              reference.fem.contact_time, reference.velocity);
  std::vector<ImpactFigures> linear;
  for (const auto& run : campaign.runs)
    linear.push_back(
        linear_contact_impact(mujoco.stiffness, mujoco.damping, campaign.mass, run.velocity));
  files.emplace_back("mujoco/impact_contact.xml",
                     export_text::mujoco_file(campaign, mujoco, linear));
  exports.push_back(
      {{"tool", "mujoco"},
       {"tool_version", "2.2.2"},
       {"file", "mujoco/impact_contact.xml"},
       {"model", "linear-spring-damper"},
       {"basis", "the FEM restitution and contact time at the reference velocity"},
       {"force_law", "F = m (K x + B dx/dt) while positive, else 0"},
       {"calibrated", {{"K", value_unit(mujoco.stiffness, "1/s^2")},
                       {"B", value_unit(mujoco.damping, "1/s")},
                       {"damping_ratio", value_unit(mujoco.damping_ratio, "1")}}},
       {"parameters", {{"solref", {-mujoco.stiffness, -mujoco.damping}},
                       {"solimp", {mujoco.impedance, mujoco.impedance, 0.001, 0.5, 2}},
                       {"condim", 1},
                       {"timestep", value_unit(mujoco.timestep, "s")}}},
       {"mapping", "direct solref (-K, -B) with flat solimp d: MuJoCo uses K / d^2, B / d and "
                   "the impedance d, so one free body obeys x'' = -(K x + B dx/dt), no pull"},
       {"same_law", true},
       {"note", "a linear contact: restitution and contact time do not depend on the velocity"},
       {"reference_velocity", reference.velocity},
       {"predictions", predictions_json(campaign, linear)}});

  std::vector<const HertzLawFit*> lammps_laws;
  if (campaign.kuwabara_kono) lammps_laws.push_back(&*campaign.kuwabara_kono);
  if (campaign.tsuji) lammps_laws.push_back(&*campaign.tsuji);
  const HertzLawFit* best = lammps_laws.front();
  for (const auto* law : lammps_laws)
    if (law->rms_residual < best->rms_residual) best = law;
  for (const auto* law : lammps_laws) {
    const bool kk = law->model == "kuwabara-kono";
    const LammpsContact lammps = lammps_contact(*law, campaign.mass, campaign.radius);
    const auto figures = law_on_campaign(campaign, *law);
    const std::string file = kk ? "lammps/kuwabara_kono.in" : "lammps/tsuji.in";
    files.emplace_back(file, export_text::lammps_file(campaign, *law, lammps, figures, law == best));
    exports.push_back(
        {{"tool", "lammps"},
         {"tool_version", "29 Sep 2021"},
         {"file", file},
         {"model", law->model},
         {"basis", "campaign.comparison_laws[" + law->model + "]"},
         {"force_law", kk ? "F = c x^(3/2) + (3/2) A c x^(1/2) dx/dt"
                          : "F = c x^(3/2) + eta x^(1/4) dx/dt"},
         {"calibrated", {{"c", value_unit(law->stiffness, "N/m^1.5")},
                         {kk ? "A" : "eta", value_unit(law->damping, kk ? "s" : "N s/m^(5/4)")}}},
         {"parameters",
          {{"normal_model", "hertz"},
           {"damping_model", lammps.damping_model},
           {"k_n", value_unit(lammps.normal_stiffness, "Pa")},
           {kk ? "eta_n0" : "e_in",
            value_unit(lammps.damping_coefficient, kk ? "1/(m s)" : "1")}}},
         {"mapping", kk ? "hertz k_n = c / sqrt(R); damping viscoelastic eta_n0 = (3/2) A c / "
                          "(m sqrt(R))"
                        : "hertz k_n = c / sqrt(R); damping tsuji with e_in solving LAMMPS's "
                          "alpha(e_in) = eta / sqrt(m c)"},
         {"same_law", true},
         {"recommended", law == best},
         {"rms_residual", law->rms_residual},
         {"note", "LAMMPS's granular damping has no Hunt-Crossley form; the law with the smaller "
                  "force-history residual is recommended"},
         {"reference_velocity", nullptr},
         {"predictions", predictions_json(campaign, figures)}});
  }

  const json manifest = {
      {"format", "impact-export"},
      {"format_version", 1},
      {"generated_by", "impact-export"},
      {"calibration", campaign.calibration_file},
      {"sphere", {{"mass", campaign.mass}, {"radius", campaign.radius},
                  {"units", {{"mass", "kg"}, {"radius", "m"}}}}},
      {"reference_velocity", reference.velocity},
      {"units", {{"impact_velocity", "m/s"}, {"restitution", "1"}, {"contact_time", "s"},
                 {"force_max", "N"}}},
      {"fem", fem},
      {"exports", exports}};
  files.emplace_back("export.json", manifest.dump(2) + "\n");

  // Written beside the target and moved into place, so a failure leaves no half directory.
  fs::path partial = directory;
  partial += ".partial";
  fs::remove_all(partial);
  for (const auto& [name, text] : files) write_text(partial / name, text);
  fs::remove_all(directory);
  fs::rename(partial, directory);
  return manifest;
}

} // namespace impact::postprocess
