#include "simulator_run.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace impact::consumers {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

double crossing(double t0, double x0, double t1, double x1) {
  return t0 + (t1 - t0) * x0 / (x0 - x1);
}

DropFigures figures(const json& entry) {
  return {entry.at("restitution").get<double>(), entry.at("contact_time").get<double>(),
          entry.at("force_max").get<double>()};
}

json figures_json(const DropFigures& f) {
  return {{"restitution", f.restitution},
          {"energy_loss", 1 - f.restitution * f.restitution},
          {"contact_time", f.contact_time},
          {"force_max", f.force_max}};
}

json errors_json(const DropFigures& tool, const DropFigures& reference) {
  return {{"restitution", tool.restitution / reference.restitution - 1},
          {"energy_loss", (1 - tool.restitution * tool.restitution) /
                                  (1 - reference.restitution * reference.restitution) -
                              1},
          {"contact_time", tool.contact_time / reference.contact_time - 1},
          {"force_max", tool.force_max / reference.force_max - 1}};
}

} // namespace

DropFigures measure_drop(const std::vector<DropSample>& s, double impact_velocity,
                         double rebound_velocity) {
  std::size_t first = 0;
  while (first < s.size() && !(s[first].approach > 0)) ++first;
  if (first == 0 || first == s.size())
    throw std::runtime_error("the drop has no contact (or starts in contact)");
  const double start =
      crossing(s[first - 1].time, s[first - 1].approach, s[first].time, s[first].approach);
  std::size_t end = first;
  double force_max = 0;
  while (end < s.size() && s[end].force != 0) force_max = std::max(force_max, s[end++].force);
  if (end == s.size()) throw std::runtime_error("the contact has not ended at the last sample");
  if (end - first < 3) throw std::runtime_error("the contact lasts fewer than 3 samples");
  const DropSample& a = s[end - 1];
  const DropSample& b = s[end];
  double stop;
  if (!(b.approach > 0)) {
    stop = crossing(a.time, a.approach, b.time, b.approach);
  } else {
    const DropSample& p = s[end - 2];
    stop = std::min(b.time, crossing(p.time, p.force, a.time, a.force));
  }
  return {rebound_velocity / impact_velocity, stop - start, force_max};
}

std::vector<ExportEntry> read_export(const fs::path& directory, const std::string& tool) {
  const fs::path path = directory / "export.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::vector<ExportEntry> entries;
  try {
    const json manifest = json::parse(in);
    if (manifest.value("format", "") != "impact-export" || manifest.value("format_version", 0) != 1)
      throw std::runtime_error("not an impact-export manifest of format_version 1");
    std::vector<DropFigures> fem;
    std::vector<double> velocities;
    for (const auto& run : manifest.at("fem")) {
      velocities.push_back(run.at("impact_velocity").get<double>());
      fem.push_back(figures(run));
    }
    for (const auto& item : manifest.at("exports")) {
      if (item.at("tool").get<std::string>() != tool) continue;
      ExportEntry entry;
      entry.directory = directory;
      entry.tool = tool;
      entry.model = item.at("model").get<std::string>();
      entry.file = item.at("file").get<std::string>();
      entry.mass = manifest.at("sphere").at("mass").get<double>();
      entry.radius = manifest.at("sphere").at("radius").get<double>();
      const json& reference = item.at("reference_velocity");
      entry.reference_velocity = reference.is_number() ? reference.get<double>()
                                                       : std::numeric_limits<double>::quiet_NaN();
      entry.velocities = velocities;
      entry.fem = fem;
      for (const auto& prediction : item.at("predictions"))
        entry.reduced_model.push_back(figures(prediction));
      if (entry.reduced_model.size() != velocities.size())
        throw std::runtime_error("the predictions of " + entry.file + " do not match the runs");
      entries.push_back(entry);
    }
  } catch (const json::exception& error) {
    throw std::runtime_error(path.string() + ": " + error.what());
  }
  if (entries.empty()) throw std::runtime_error(path.string() + " has no export for " + tool);
  return entries;
}

void write_simulator_run(const fs::path& output, const ExportEntry& entry,
                         const std::string& tool_version,
                         const std::vector<DropFigures>& measured) {
  json runs = json::array();
  for (std::size_t i = 0; i < measured.size(); ++i)
    runs.push_back({{"impact_velocity", entry.velocities[i]},
                    {"tool", figures_json(measured[i])},
                    {"reduced_model", figures_json(entry.reduced_model[i])},
                    {"fem", figures_json(entry.fem[i])},
                    {"error_vs_reduced_model", errors_json(measured[i], entry.reduced_model[i])},
                    {"error_vs_fem", errors_json(measured[i], entry.fem[i])}});
  const json result = {{"format", "impact-simulator-run"},
                       {"format_version", 1},
                       {"tool", entry.tool},
                       {"tool_version", tool_version},
                       {"model", entry.model},
                       {"export",
                        fs::absolute(entry.directory / "export.json").lexically_normal().string()},
                       {"file", entry.file},
                       {"reference_velocity", std::isfinite(entry.reference_velocity)
                                                  ? json(entry.reference_velocity)
                                                  : json(nullptr)},
                       {"units",
                        {{"impact_velocity", "m/s"},
                         {"restitution", "1"},
                         {"energy_loss", "1 (1 - e^2)"},
                         {"contact_time", "s"},
                         {"force_max", "N"},
                         {"errors", "1 (tool / reference - 1)"}}},
                       {"runs", runs}};
  fs::create_directories(fs::absolute(output).parent_path());
  const fs::path temporary = output.string() + ".tmp";
  {
    std::ofstream out(temporary);
    out << result.dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, output);
}

void print_simulator_run(const ExportEntry& entry, const std::vector<DropFigures>& measured) {
  std::printf("%s (%s, %s): errors against the reduced model | against the FEM\n",
              entry.tool.c_str(), entry.model.c_str(), entry.file.c_str());
  std::printf(
      "  V [m/s]   e          t_c [s]      F_max [N]   | de/e     dt/t     dF/F     | de/e    dt/t "
      "   dF/F\n");
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const auto& m = measured[i];
    const auto& r = entry.reduced_model[i];
    const auto& f = entry.fem[i];
    std::printf(
        "  %-8.4g  %-9.6f  %-11.5g  %-10.5g  | %+.1e %+.1e %+.1e | %+.2f%% %+.2f%% %+.2f%%\n",
        entry.velocities[i], m.restitution, m.contact_time, m.force_max,
        m.restitution / r.restitution - 1, m.contact_time / r.contact_time - 1,
        m.force_max / r.force_max - 1, 100 * (m.restitution / f.restitution - 1),
        100 * (m.contact_time / f.contact_time - 1), 100 * (m.force_max / f.force_max - 1));
  }
}

} // namespace impact::consumers
