// The page of the model-validity report: one list of blocks (headings, paragraphs, tables,
// figures) built from a Report, rendered twice, as Markdown and as self-contained HTML, so
// that the two pages say the same thing. Also the figure data for report_figures.py.

#include "impact_postprocess/report.hpp"

#include "report_json.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- Numbers as the tables show them ----------------------------------------------------

// Six significant digits: enough to compare with the calibration JSON to 1e-5.
std::string cell(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string percent_cell(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%+.3g %%", fraction * 100);
  return text;
}

std::string short_number(double value) {
  if (!std::isfinite(value)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// Display scale of each quantity: restitution [1], contact time [us], peak force [kN],
// peak approach [um].
const std::array<double, impact_quantity_count> display_scale = {1, 1e6, 1e-3, 1e6};
const std::array<const char*, impact_quantity_count> display_name = {
    "restitution e [1]", "contact time t_c [µs]", "peak force F_max [kN]",
    "peak approach x_max [µm]"};
const std::array<const char*, impact_quantity_count> short_name = {"e", "t_c", "F_max", "x_max"};

// ---- The document ---------------------------------------------------------------------

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct Block {
  enum class Kind { heading, paragraph, list, table, figure, code } kind;
  int level = 2;
  std::string text;
  std::vector<std::string> items;
  Table table;
  ReportFigure figure;
};

class Document {
public:
  void heading(const std::string& text, int level = 2) {
    blocks.push_back({Block::Kind::heading, level, text, {}, {}, {}});
  }
  void paragraph(const std::string& text) {
    blocks.push_back({Block::Kind::paragraph, 0, text, {}, {}, {}});
  }
  void list(std::vector<std::string> items) {
    if (!items.empty()) blocks.push_back({Block::Kind::list, 0, "", std::move(items), {}, {}});
  }
  void table(Table table) { blocks.push_back({Block::Kind::table, 0, "", {}, std::move(table), {}}); }
  void figure(const ReportFigure& figure) {
    blocks.push_back({Block::Kind::figure, 0, "", {}, {}, figure});
  }
  void code(const std::string& text) { blocks.push_back({Block::Kind::code, 0, text, {}, {}, {}}); }
  std::vector<Block> blocks;
};

// A run's file relative to the campaign directory when it lies inside it.
std::string shown_source(const std::string& source, const std::string& campaign) {
  if (campaign.empty()) return source;
  const fs::path relative = fs::path(source).lexically_relative(campaign);
  if (relative.empty() || *relative.begin() == "..") return source;
  return relative.string();
}

std::string velocity_label(double velocity) { return "V = " + short_number(velocity) + " m/s"; }

std::string model_cell(const ReportModel& model, std::size_t run, std::size_t quantity) {
  const auto& at = model.runs[run];
  if (!at.values) return "n/a";
  return cell((*at.values)[quantity] * display_scale[quantity]) +
         (model.converged ? "" : " (not converged)");
}

using detail::member;
using detail::number;

Document build_document(const Report& report, const fs::path& figures_directory) {
  Document doc;
  doc.heading("Impact model-validity report", 1);
  doc.paragraph("Campaign: " + report.campaign_source + ". Calibration: " +
                (report.calibration_source.empty() ? std::string("none")
                                                   : report.calibration_source) +
                ". Every number below is computed by impact-report (C++, impact::reduced and "
                "the calibration JSON); the figures are drawn from them by report_figures.py.");

  // Status: what is missing.
  doc.heading("Status");
  if (report.problems.empty()) {
    doc.paragraph("Complete: every run was read, every fit converged and every figure was drawn.");
  } else {
    doc.paragraph("INCOMPLETE: " + std::to_string(report.problems.size()) +
                  " problem(s); the sections below leave out or mark what they affect.");
    std::vector<std::string> items;
    for (const auto& problem : report.problems)
      items.push_back("[" + problem.kind + "] " +
                      (problem.source.empty() ? "" : problem.source + ": ") + problem.message);
    doc.list(items);
  }
  if (report.runs.empty()) {
    doc.paragraph("No FEM run could be read: there is nothing to compare. Fix the problems "
                  "above and run impact-report again.");
    return doc;
  }

  const ReportModel& calibrated = report.models.front();
  const std::size_t count = report.runs.size();

  // Verdict.
  doc.heading("Validity verdict");
  doc.paragraph("Where the calibrated Hunt–Crossley model (" + calibrated.parameters +
                ") predicts restitution, contact time and peak force within 2 % and within 5 % "
                "of the FEM (relative error of each quantity, all three at once).");
  if (report.verdict_available) {
    std::vector<std::string> items;
    for (const auto& verdict : report.verdicts) items.push_back(verdict.text);
    doc.list(items);
  }
  doc.paragraph("Cause: " + report.cause);
  if (report.verdict_available) {
    Table table{{"V [m/s]", "error e", "error t_c", "error F_max", "within 2 %", "within 5 %"}, {}};
    for (std::size_t i = 0; i < count; ++i) {
      std::vector<std::string> row{cell(report.runs[i].velocity)};
      for (std::size_t q = 0; q < 3; ++q)
        row.push_back(calibrated.runs[i].values
                          ? percent_cell(((*calibrated.runs[i].values)[q] - report.runs[i].fem[q]) /
                                         std::abs(report.runs[i].fem[q]))
                          : "n/a");
      for (const auto& verdict : report.verdicts)
        row.push_back(verdict.passes[i] == 1 ? "yes" : verdict.passes[i] == 0 ? "no" : "unknown");
      table.rows.push_back(row);
    }
    doc.table(table);
  }

  // Calibrated parameters.
  doc.heading("Calibrated parameters");
  const json& campaign = member(report.calibration, "campaign");
  const json& hc = member(campaign, "hunt_crossley");
  if (hc.is_object()) {
    const double level = number(member(report.calibration, "confidence_level"));
    doc.paragraph("Campaign fit of Hunt–Crossley F = c x^n (1 + b dx/dt) to the force histories "
                  "of all runs (calibration JSON, campaign.hunt_crossley); intervals at " +
                  short_number(level * 100) + " % confidence. RMS residual " +
                  short_number(number(member(hc, "rms_residual")) * 100) +
                  " % of the peak force, R^2 = " + cell(number(member(hc, "r_squared"))) +
                  ", converged: " + (member(hc, "converged") == true ? "yes" : "NO") + ".");
    Table table{{"parameter", "value", "standard error", "interval lower", "interval upper", "unit"}, {}};
    for (const char* name : {"c", "n", "b"}) {
      const json& p = member(member(hc, "parameters"), name);
      const json& interval = member(p, "interval");
      table.rows.push_back({name, cell(number(member(p, "value"))),
                            cell(number(member(p, "standard_error"))),
                            cell(interval.is_array() ? number(interval[0]) : nan),
                            cell(interval.is_array() ? number(interval[1]) : nan),
                            member(p, "unit").is_string() ? p["unit"].get<std::string>() : ""});
    }
    doc.table(table);
    const json& correlation = member(hc, "correlation");
    doc.paragraph("Correlations: c,n = " + cell(number(member(correlation, "c,n"))) +
                  "; c,b = " + cell(number(member(correlation, "c,b"))) + "; n,b = " +
                  cell(number(member(correlation, "n,b"))) + ".");
  } else {
    doc.paragraph("No campaign fit: " +
                  (report.campaign_reason.empty() ? std::string("the calibration has none")
                                                  : report.campaign_reason) +
                  ". The runs' own fits are in the table of runs.");
  }
  doc.list(report.parameter_notes);
  const json& multibody = member(report.calibration, "multibody");
  if (multibody.is_object())
    doc.code("For a multibody code (" +
             (member(multibody, "basis").is_string() ? multibody["basis"].get<std::string>() : "") +
             "):\n  F = c x^n (1 + b dx/dt)\n  c = " + cell(number(member(multibody, "c"))) +
             " N/m^n\n  n = " + cell(number(member(multibody, "n"))) + "\n  b = " +
             cell(number(member(multibody, "b"))) + " s/m");
  const json& ranking = member(campaign, "ranking");
  if (ranking.is_array() && !ranking.empty()) {
    doc.paragraph("Ranking of the laws fitted to all runs (calibration JSON, campaign.ranking), "
                  "by RMS residual of the force histories:");
    Table table{{"rank", "model", "parameter", "value", "unit", "RMS residual [%]", "R^2", "converged"}, {}};
    int rank = 1;
    for (const auto& entry : ranking) {
      const json& parameter = member(entry, "parameter");
      table.rows.push_back(
          {std::to_string(rank++),
           member(entry, "model").is_string() ? entry["model"].get<std::string>() : "?",
           member(parameter, "name").is_string() ? parameter["name"].get<std::string>() : "",
           cell(number(member(parameter, "value"))),
           member(parameter, "unit").is_string() ? parameter["unit"].get<std::string>() : "",
           cell(number(member(entry, "rms_residual")) * 100),
           cell(number(member(entry, "r_squared"))),
           member(entry, "converged") == true ? "yes" : "no"});
    }
    doc.table(table);
  }

  // Runs.
  doc.heading("Runs");
  doc.paragraph("FEM quantities (the calibration's 'measured' numbers) and the per-run "
                "calibration: b from the restitution through the exact inverse of k(bV), and "
                "c, n, b of the run's force-history fit with its interval.");
  {
    Table table{{"V [m/s]", "mass [kg]", "e [1]", "t_c [µs]", "F_max [kN]", "x_max [µm]",
                 "b from e [s/m]", "b history fit [s/m]", "b interval [s/m]", "n history fit",
                 "c history fit [N/m^n]", "source"}, {}};
    for (const auto& run : report.runs)
      table.rows.push_back(
          {cell(run.velocity), cell(run.mass), cell(run.fem[0]), cell(run.fem[1] * 1e6),
           cell(run.fem[2] * 1e-3), cell(run.fem[3] * 1e6), cell(run.damping_from_restitution),
           cell(run.history_damping.value),
           std::isfinite(run.history_damping.lower)
               ? cell(run.history_damping.lower) + " to " + cell(run.history_damping.upper)
               : "n/a",
           cell(run.history_exponent.value), cell(run.history_stiffness.value),
           shown_source(run.source, report.campaign_source) +
               (run.calibrated ? "" : " (not in the calibration)")});
    doc.table(table);
  }

  // Models.
  doc.heading("Reduced models compared");
  {
    std::vector<std::string> items;
    for (const auto& model : report.models)
      items.push_back(model.label + ": " + model.parameters + ". " + model.basis +
                      (model.converged ? "" : " (NOT CONVERGED)"));
    doc.list(items);
  }

  const auto figures = report_figures(report);
  const auto figure = [&](const std::string& file) {
    for (const auto& f : figures)
      if (f.file == file) doc.figure({(figures_directory / f.file).string(), f.caption});
  };

  doc.heading("Force–approach loops");
  figure("loops.png");
  doc.heading("Approach and force against time");
  figure("histories.png");

  doc.heading("Restitution, contact time, peak force and peak approach against V");
  figure("quantities.png");
  for (std::size_t q = 0; q < impact_quantity_count; ++q) {
    Table table{{"V [m/s]", std::string("FEM ") + display_name[q]}, {}};
    for (const auto& model : report.models) table.header.push_back(model.label);
    for (std::size_t i = 0; i < count; ++i) {
      std::vector<std::string> row{cell(report.runs[i].velocity),
                                   cell(report.runs[i].fem[q] * display_scale[q])};
      for (const auto& model : report.models) row.push_back(model_cell(model, i, q));
      table.rows.push_back(row);
    }
    doc.paragraph(display_name[q]);
    doc.table(table);
  }

  doc.heading("Per-run damping b against V");
  doc.paragraph("b is constant only where Hunt–Crossley is the right law: a trend of the per-run "
                "b with V says that the dissipation of the FEM does not have Hunt–Crossley's "
                "velocity dependence.");
  figure("damping.png");

  doc.heading("Errors of the reduced models against the FEM");
  doc.paragraph("Relative error (model - FEM) / FEM of each quantity at each velocity.");
  figure("errors.png");
  {
    Table table{{"model", "quantity"}, {}};
    for (const auto& run : report.runs) table.header.push_back(velocity_label(run.velocity));
    for (const auto& model : report.models)
      for (std::size_t q = 0; q < impact_quantity_count; ++q) {
        std::vector<std::string> row{model.label, short_name[q]};
        for (std::size_t i = 0; i < count; ++i)
          row.push_back(model.runs[i].values
                            ? percent_cell(((*model.runs[i].values)[q] - report.runs[i].fem[q]) /
                                           std::abs(report.runs[i].fem[q])) +
                                  (model.converged ? "" : " (not converged)")
                            : "n/a");
        table.rows.push_back(row);
      }
    doc.table(table);
    std::vector<std::string> missing;
    for (const auto& model : report.models)
      for (std::size_t i = 0; i < count; ++i)
        if (!model.runs[i].values)
          missing.push_back(model.label + " at " + velocity_label(report.runs[i].velocity) +
                            ": " + model.runs[i].missing);
    if (!missing.empty()) {
      doc.paragraph("Missing predictions (n/a above):");
      doc.list(missing);
    }
  }

  doc.heading("Energy balance and yield check");
  doc.paragraph("energy error: the largest |energy balance error| / initial energy of the run "
                "(energy_error of summary.json). Lost: 1 - e^2 of the FEM restitution. Yield: the "
                "largest von Mises stress against a yield strength recorded by the run.");
  {
    Table table{{"V [m/s]", "energy error [%]", "lost 1-e^2 [%]", "dissipated [%]",
                 "radiated [%]", "max von Mises [MPa]", "yield strength [MPa]", "yield check"}, {}};
    const auto optional_cell = [](const std::optional<double>& value, double scale) {
      return value ? cell(*value * scale) : std::string("not recorded");
    };
    for (const auto& run : report.runs) {
      const auto& record = run.record;
      std::string check;
      if (!record.max_von_mises) check = "not recorded (no max_von_mises)";
      else if (!record.yield_strength) check = "yield strength not recorded";
      else {
        const double ratio = *record.max_von_mises / *record.yield_strength;
        check = (ratio < 1 ? "elastic: " : "YIELDS: ") + short_number(ratio * 100) +
                " % of the yield strength (" + record.yield_source + ")";
      }
      table.rows.push_back({cell(run.velocity), optional_cell(record.energy_error, 100),
                            cell((1 - run.fem[0] * run.fem[0]) * 100),
                            optional_cell(record.dissipated_energy_fraction, 100),
                            optional_cell(record.radiated_energy_fraction, 100),
                            optional_cell(record.max_von_mises, 1e-6),
                            optional_cell(record.yield_strength, 1e-6), check});
    }
    doc.table(table);
  }
  return doc;
}

// ---- Rendering ------------------------------------------------------------------------

std::string escape_html(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string escape_markdown_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                       (unsigned char)bytes[i + 2];
    for (int shift : {18, 12, 6, 0}) out += alphabet[(v >> shift) & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string read_binary(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_atomically(const fs::path& file, const std::string& text) {
  const fs::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  fs::rename(temporary, file);
}

} // namespace

std::vector<ReportFigure> report_figures(const Report& report) {
  if (report.runs.empty()) return {};
  return {{"loops.png", "Force against approach per velocity: FEM and calibrated Hunt–Crossley."},
          {"histories.png", "Approach and contact force against time since first contact, per "
                            "velocity: FEM and calibrated Hunt–Crossley."},
          {"quantities.png", "Restitution, contact time, peak force and peak approach against "
                             "V: FEM and the four reduced models."},
          {"damping.png", "Per-run b against V: from the restitution (exact inverse of k) and "
                          "from each run's force-history fit (with its interval), the campaign "
                          "b with its interval, and the published 0.1 s/m."},
          {"errors.png", "Relative errors of restitution, contact time and peak force against V "
                         "for the calibrated Hunt–Crossley model and the best comparison law, "
                         "with the 2 % and 5 % bands."}};
}

json figure_specification(const Report& report) {
  json figures = json::array();
  if (report.runs.empty()) return {{"figures", figures}};
  const auto scaled = [](const std::vector<double>& values, double scale) {
    json out = json::array();
    for (double v : values) out.push_back(std::isfinite(v) ? json(v * scale) : json(nullptr));
    return out;
  };
  const auto series = [](const std::string& label, json x, json y, const std::string& color,
                         const std::string& linestyle, const std::string& marker) {
    return json{{"label", label}, {"x", std::move(x)}, {"y", std::move(y)}, {"color", color},
                {"linestyle", linestyle}, {"marker", marker}};
  };
  const ReportModel& calibrated = report.models.front();
  const std::array<const char*, 4> colors = {"tab:red", "tab:blue", "tab:green", "tab:purple"};
  const std::array<const char*, 4> styles = {"--", "-.", ":", "--"};
  const std::array<const char*, 4> markers = {"s", "^", "v", "D"};

  json loops = json::array(), histories = json::array();
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const auto& run = report.runs[i];
    const auto& model = calibrated.runs[i].history;
    const std::string title = velocity_label(run.velocity);
    const auto panel = [&](const std::string& xlabel, const std::string& ylabel) {
      return json{{"title", title}, {"xlabel", xlabel}, {"ylabel", ylabel},
                  {"series", json::array()}};
    };
    json loop = panel("approach x [µm]", "contact force F [kN]");
    loop["series"].push_back(series("FEM", scaled(run.fem_history.approach, 1e6),
                                    scaled(run.fem_history.force, 1e-3), "black", "-", ""));
    json approach = panel("time since first contact [µs]", "approach x [µm]");
    approach["series"].push_back(series("FEM", scaled(run.fem_history.time, 1e6),
                                        scaled(run.fem_history.approach, 1e6), "black", "-", ""));
    json force = panel("time since first contact [µs]", "contact force F [kN]");
    force["series"].push_back(series("FEM", scaled(run.fem_history.time, 1e6),
                                     scaled(run.fem_history.force, 1e-3), "black", "-", ""));
    if (!model.time.empty()) {
      loop["series"].push_back(series(calibrated.label, scaled(model.approach, 1e6),
                                      scaled(model.force, 1e-3), colors[0], "--", ""));
      approach["series"].push_back(series(calibrated.label, scaled(model.time, 1e6),
                                          scaled(model.approach, 1e6), colors[0], "--", ""));
      force["series"].push_back(series(calibrated.label, scaled(model.time, 1e6),
                                       scaled(model.force, 1e-3), colors[0], "--", ""));
    } else {
      loop["note"] = calibrated.runs[i].missing;
    }
    loops.push_back(loop);
    histories.push_back(approach);
    histories.push_back(force);
  }
  figures.push_back({{"file", "loops.png"}, {"title", "Force–approach loops"}, {"columns", 3},
                     {"panels", loops}});
  figures.push_back({{"file", "histories.png"}, {"title", "Approach and force against time"},
                     {"columns", 2}, {"panels", histories}});

  std::vector<double> velocities;
  for (const auto& run : report.runs) velocities.push_back(run.velocity);
  json quantity_panels = json::array();
  for (std::size_t q = 0; q < impact_quantity_count; ++q) {
    std::vector<double> fem;
    for (const auto& run : report.runs) fem.push_back(run.fem[q]);
    json panel = {{"title", display_name[q]}, {"xlabel", "impact velocity V [m/s]"},
                  {"ylabel", display_name[q]},
                  {"series", json::array({series("FEM", scaled(velocities, 1),
                                                 scaled(fem, display_scale[q]), "black", "-", "o")})}};
    for (std::size_t k = 0; k < report.models.size(); ++k) {
      std::vector<double> values;
      for (const auto& at : report.models[k].runs) values.push_back(at.values ? (*at.values)[q] : nan);
      panel["series"].push_back(series(report.models[k].label, scaled(velocities, 1),
                                       scaled(values, display_scale[q]), colors[k % 4],
                                       styles[k % 4], markers[k % 4]));
    }
    quantity_panels.push_back(panel);
  }
  figures.push_back({{"file", "quantities.png"}, {"title", "Impact quantities against V"},
                     {"columns", 2}, {"panels", quantity_panels}});

  std::vector<double> b_restitution, b_history, b_low, b_high;
  for (const auto& run : report.runs) {
    b_restitution.push_back(run.damping_from_restitution);
    b_history.push_back(run.history_damping.value);
    b_low.push_back(run.history_damping.value - run.history_damping.lower);
    b_high.push_back(run.history_damping.upper - run.history_damping.value);
  }
  json damping = {{"title", "per-run b (constant only where Hunt–Crossley is the right law)"},
                  {"xlabel", "impact velocity V [m/s]"}, {"ylabel", "damping b [s/m]"},
                  {"series", json::array({series("b from the restitution", scaled(velocities, 1),
                                                 scaled(b_restitution, 1), "black", "-", "o")})},
                  {"hlines", json::array({{{"y", 0.1}, {"label", "published b = 0.1 s/m"},
                                           {"color", "tab:blue"}, {"linestyle", ":"}}})},
                  {"bands", json::array()}};
  json history_series = series("b of the force-history fit", scaled(velocities, 1),
                               scaled(b_history, 1), "tab:orange", "none", "s");
  history_series["yerr"] = {scaled(b_low, 1), scaled(b_high, 1)};
  damping["series"].push_back(history_series);
  const json& hc = member(member(report.calibration, "campaign"), "hunt_crossley");
  if (hc.is_object()) {
    const json& b = member(member(hc, "parameters"), "b");
    damping["hlines"].push_back({{"y", number(member(b, "value"))},
                                 {"label", "campaign b (calibrated)"},
                                 {"color", "tab:red"}, {"linestyle", "--"}});
    const json& interval = member(b, "interval");
    if (interval.is_array() && interval.size() == 2 && interval[0].is_number() &&
        interval[1].is_number())
      damping["bands"].push_back({{"y0", interval[0]}, {"y1", interval[1]}, {"color", "tab:red"},
                                  {"alpha", 0.15}, {"label", "campaign b interval"}});
  }
  figures.push_back({{"file", "damping.png"}, {"title", "Per-run damping"}, {"columns", 1},
                     {"panels", json::array({damping})}});

  json error_panels = json::array();
  for (std::size_t q = 0; q < 3; ++q) {
    static const std::array<const char*, 3> names = {"restitution", "contact time", "peak force"};
    json panel = {{"title", std::string("error of the ") + names[q]},
                  {"xlabel", "impact velocity V [m/s]"}, {"ylabel", "(model - FEM) / FEM [%]"},
                  {"series", json::array()},
                  {"bands", json::array({{{"y0", -5}, {"y1", 5}, {"color", "tab:orange"},
                                          {"alpha", 0.12}, {"label", "±5 %"}},
                                         {{"y0", -2}, {"y1", 2}, {"color", "tab:green"},
                                          {"alpha", 0.18}, {"label", "±2 %"}}})}};
    for (std::size_t k = 0; k < report.models.size(); ++k) {
      const auto& model = report.models[k];
      if (model.key != "calibrated" && model.key != "best-law") continue;
      std::vector<double> errors;
      for (std::size_t i = 0; i < report.runs.size(); ++i)
        errors.push_back(model.runs[i].values
                             ? ((*model.runs[i].values)[q] - report.runs[i].fem[q]) /
                                   std::abs(report.runs[i].fem[q])
                             : nan);
      panel["series"].push_back(series(model.label, scaled(velocities, 1), scaled(errors, 100),
                                       colors[k % 4], styles[k % 4], markers[k % 4]));
    }
    error_panels.push_back(panel);
  }
  figures.push_back({{"file", "errors.png"}, {"title", "Errors against the FEM"}, {"columns", 3},
                     {"panels", error_panels}});
  return {{"figures", figures}};
}

void write_report_markdown(const Report& report, const fs::path& file,
                           const fs::path& figures_directory) {
  const Document doc = build_document(report, figures_directory);
  std::ostringstream out;
  for (const auto& block : doc.blocks) {
    switch (block.kind) {
    case Block::Kind::heading: out << std::string(block.level, '#') << ' ' << block.text << "\n\n"; break;
    case Block::Kind::paragraph: out << block.text << "\n\n"; break;
    case Block::Kind::list:
      for (const auto& item : block.items) out << "- " << item << '\n';
      out << '\n';
      break;
    case Block::Kind::code: out << "```\n" << block.text << "\n```\n\n"; break;
    case Block::Kind::table: {
      const auto row = [&](const std::vector<std::string>& cells) {
        out << '|';
        for (const auto& c : cells) out << ' ' << escape_markdown_cell(c) << " |";
        out << '\n';
      };
      row(block.table.header);
      out << '|';
      for (std::size_t i = 0; i < block.table.header.size(); ++i) out << "---|";
      out << '\n';
      for (const auto& r : block.table.rows) row(r);
      out << '\n';
      break;
    }
    case Block::Kind::figure: {
      const fs::path image = file.parent_path() / block.figure.file;
      if (fs::exists(image) && fs::file_size(image) > 0)
        out << "![" << block.figure.caption << "](" << block.figure.file << ")\n\n*"
            << block.figure.caption << "*\n\n";
      else
        out << "*Figure missing (" << block.figure.file << " was not drawn, see Status): "
            << block.figure.caption << "*\n\n";
      break;
    }
    }
  }
  write_atomically(file, out.str());
}

void write_report_html(const Report& report, const fs::path& file,
                       const fs::path& figures_directory) {
  const Document doc = build_document(report, figures_directory);
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<title>Impact model-validity report</title>\n<style>\n"
         "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:2em auto;max-width:1150px;"
         "color:#222;line-height:1.45;padding:0 1em}\n"
         "h1{border-bottom:3px solid #b22;padding-bottom:.2em}h2{border-bottom:1px solid #ccc;"
         "margin-top:1.6em}\n"
         "table{border-collapse:collapse;margin:.6em 0 1.2em;font-size:.85em}\n"
         "th,td{border:1px solid #bbb;padding:.25em .5em;text-align:right}\n"
         "th{background:#eef2f7}td:first-child,th:first-child{text-align:left}\n"
         "tr:nth-child(even) td{background:#fafafa}\n"
         "figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}\n"
         "figcaption{font-style:italic;color:#555}\n"
         "pre{background:#f4f4f4;padding:.8em;border-left:4px solid #b22}\n"
         ".missing{color:#b22;font-weight:bold}\n"
         "</style>\n</head>\n<body>\n";
  for (const auto& block : doc.blocks) {
    switch (block.kind) {
    case Block::Kind::heading:
      out << "<h" << block.level << '>' << escape_html(block.text) << "</h" << block.level << ">\n";
      break;
    case Block::Kind::paragraph:
      out << (block.text.rfind("INCOMPLETE", 0) == 0 ? "<p class=\"missing\">" : "<p>")
          << escape_html(block.text) << "</p>\n";
      break;
    case Block::Kind::list:
      out << "<ul>\n";
      for (const auto& item : block.items) out << "<li>" << escape_html(item) << "</li>\n";
      out << "</ul>\n";
      break;
    case Block::Kind::code: out << "<pre>" << escape_html(block.text) << "</pre>\n"; break;
    case Block::Kind::table:
      out << "<table>\n<tr>";
      for (const auto& c : block.table.header) out << "<th>" << escape_html(c) << "</th>";
      out << "</tr>\n";
      for (const auto& r : block.table.rows) {
        out << "<tr>";
        for (const auto& c : r) out << "<td>" << escape_html(c) << "</td>";
        out << "</tr>\n";
      }
      out << "</table>\n";
      break;
    case Block::Kind::figure: {
      const fs::path image = file.parent_path() / block.figure.file;
      if (fs::exists(image) && fs::file_size(image) > 0)
        out << "<figure><img alt=\"" << escape_html(block.figure.caption)
            << "\" src=\"data:image/png;base64," << base64(read_binary(image))
            << "\"><figcaption>" << escape_html(block.figure.caption) << "</figcaption></figure>\n";
      else
        out << "<p class=\"missing\">Figure missing (" << escape_html(block.figure.file)
            << " was not drawn, see Status): " << escape_html(block.figure.caption) << "</p>\n";
      break;
    }
    }
  }
  out << "</body>\n</html>\n";
  write_atomically(file, out.str());
}

} // namespace impact::postprocess
