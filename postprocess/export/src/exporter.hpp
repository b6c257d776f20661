#pragma once
// One exporter per simulator behind one interface (write_exports, simulator_export.hpp): each
// turns the campaign into its files and their manifest entries, and is registered by name.
// Adding a simulator is one new file with its exporter and one line in registered_exporters.

#include "impact_postprocess/export/simulator_export.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace impact::postprocess::exporters {

/// A file of the export directory and its entry in export.json's "exports".
struct ExportedFile {
  std::string file; ///< relative to the export directory
  std::string text;
  nlohmann::json entry;
};

/// An exporter: the campaign (with MuJoCo's reference run) to files. Throws ExportInputError
/// for a campaign its tool's contact cannot represent.
using Exporter = std::vector<ExportedFile> (*)(const ExportCampaign& campaign,
                                               const CampaignImpact& reference);

std::vector<ExportedFile> simbody(const ExportCampaign& campaign, const CampaignImpact& reference);
std::vector<ExportedFile> mujoco(const ExportCampaign& campaign, const CampaignImpact& reference);
std::vector<ExportedFile> lammps(const ExportCampaign& campaign, const CampaignImpact& reference);
/// None when the campaign has no plastic contact.
std::vector<ExportedFile> liggghts(const ExportCampaign& campaign, const CampaignImpact& reference);
/// The restitution table (CSV, JSON) of a damped elastic-plastic law, and the entries of the
/// tools that run that law through their own extension mechanisms (Simbody's Force::Custom,
/// LAMMPS's fix external: tests/consumers); none without a table.
std::vector<ExportedFile> restitution(const ExportCampaign& campaign,
                                      const CampaignImpact& reference);

/// The files of one exporter and their manifest entries, collected in the order written.
struct ExportList {
  std::vector<std::pair<std::string, std::string>> files; ///< name, text
  nlohmann::json exports = nlohmann::json::array();
  std::vector<ExportedFile> zipped() const {
    std::vector<ExportedFile> result;
    for (std::size_t i = 0; i < files.size(); ++i)
      result.push_back({files[i].first, files[i].second, exports[i]});
    return result;
  }
};

/// The exporters by name, in the order of the manifest.
const std::vector<std::pair<std::string, Exporter>>& registered_exporters();

// Shared by the exporters (simulator_export.cpp).
nlohmann::json value_unit(double value, const std::string& unit);
nlohmann::json figures_json(double velocity, const ImpactFigures& figures);
/// A Hertz-type law's impacts at the campaign's velocities.
std::vector<ImpactFigures> law_on_campaign(const ExportCampaign& campaign, const HertzLawFit& law);
/// The model's impacts as the manifest lists them, one per run.
nlohmann::json predictions_json(const ExportCampaign& campaign,
                                const std::vector<ImpactFigures>& figures);

} // namespace impact::postprocess::exporters
