// The restitution table's files and manifest entries (exporter.hpp, restitution_table.hpp).

#include "exporter.hpp"
#include "impact_postprocess/same_value.hpp"

#include <string>

namespace impact::postprocess::exporters {

using json = nlohmann::json;

std::vector<ExportedFile> restitution(const ExportCampaign& campaign, const CampaignImpact&) {
  if (!campaign.restitution_table) return {};
  const RestitutionTable& table = *campaign.restitution_table;
  const std::string stem = "restitution/" + table.law.key;
  const std::string csv = stem + ".csv", json_file = stem + ".json";

  // The law at the campaign's velocities, in the order of the manifest's "fem".
  std::vector<ImpactFigures> figures;
  for (const auto& run : campaign.runs)
    for (const auto& row : table.rows)
      if (row.fem && same_value(row.velocity, run.velocity)) figures.push_back(row.law.figures());
  if (figures.size() != campaign.runs.size())
    throw ExportInputError("the restitution table of " + table.law.key +
                           " does not hold every velocity of the calibration");
  const json predictions = predictions_json(campaign, figures);
  const json common = {{"model", table.law.key},
                       {"reference_velocity", nullptr},
                       {"same_law", true},
                       {"predictions", predictions}};

  const std::string json_text = restitution_table_json(table).dump(2) + "\n";
  std::vector<ExportedFile> files;
  json entry = common;
  entry["tool"] = "restitution-table";
  entry["file"] = csv;
  entry["json"] = json_file;
  entry["note"] =
      "e(V), t_c(V), F_max(V) of the law for an impulse-based engine, with the FEM's values, "
      "their uncertainty and the law's error at the FEM's velocities";
  files.push_back({csv, restitution_table_csv(table), entry});
  // The two tools run the law of the table's JSON (its law.reduced_library); the file is
  // listed with each of them (written once per entry, the same text).
  entry = common;
  entry["tool"] = "simbody-custom";
  entry["tool_version"] = "3.7";
  entry["file"] = json_file;
  entry["mapping"] =
      "SimTK::Force::Custom: F = F_s(x) (1 + b x') on the sphere, x_max a continuous state "
      "(z' = max(x', 0)) that selects the unloading branch; the spring from the reduced "
      "library";
  files.push_back({json_file, json_text, entry});
  entry = common;
  entry["tool"] = "lammps-external";
  entry["file"] = json_file;
  entry["mapping"] =
      "LAMMPS fix external through the library interface: its callback sets the wall's force "
      "F = F_s(x) (1 + b x') on the sphere at every step, x_max kept between steps; the "
      "spring from the reduced library";
  files.push_back({json_file, json_text, entry});
  return files;
}

} // namespace impact::postprocess::exporters
