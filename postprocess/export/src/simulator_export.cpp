// The export directory of impact-export: the files for Simbody, MuJoCo, LAMMPS and LIGGGHTS and the
// manifest export.json that lists them with their parameters, the reduced model each one
// carries and that model's impacts at the campaign's velocities (format in
// postprocess/README.md).

#include "impact_postprocess/export/simulator_export.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/same_value.hpp"

#include "exporter.hpp"
#include "text.hpp"

#include <cmath>
#include <fstream>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

const CampaignImpact& reference_run(const ExportCampaign& campaign,
                                    std::optional<double> velocity) {
  if (!velocity) return campaign.runs[(campaign.runs.size() - 1) / 2];
  std::string velocities;
  for (const auto& run : campaign.runs) {
    if (same_value(run.velocity, *velocity)) return run;
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

namespace exporters {

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

const std::vector<std::pair<std::string, Exporter>>& registered_exporters() {
  static const std::vector<std::pair<std::string, Exporter>> exporters = {{"simbody", simbody},
                                                                          {"mujoco", mujoco},
                                                                          {"lammps", lammps},
                                                                          {"liggghts", liggghts},
                                                                          {"restitution",
                                                                           restitution}};
  return exporters;
}

} // namespace exporters

json write_exports(const ExportCampaign& campaign, std::optional<double> reference_velocity,
                   const fs::path& directory) {
  const CampaignImpact& reference = reference_run(campaign, reference_velocity);

  json fem = json::array();
  for (const auto& run : campaign.runs) {
    json entry = exporters::figures_json(run.velocity, run.fem);
    entry["source"] = run.source;
    fem.push_back(entry);
  }

  // Everything is computed before anything is written: bad input leaves no files.
  std::vector<std::pair<fs::path, std::string>> files;
  json exports = json::array();
  for (const auto& [name, exporter] : exporters::registered_exporters())
    for (auto& exported : exporter(campaign, reference)) {
      files.emplace_back(exported.file, std::move(exported.text));
      exports.push_back(std::move(exported.entry));
    }

  const json manifest = {{"format", "impact-export"},
                         {"format_version", 1},
                         {"generated_by", "impact-export"},
                         {"calibration", campaign.calibration_file},
                         {"sphere",
                          {{"mass", campaign.mass},
                           {"radius", campaign.radius},
                           {"units", {{"mass", "kg"}, {"radius", "m"}}}}},
                         {"reference_velocity", reference.velocity},
                         {"units",
                          {{"impact_velocity", "m/s"},
                           {"restitution", "1"},
                           {"contact_time", "s"},
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
