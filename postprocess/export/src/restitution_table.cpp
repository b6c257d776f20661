// The restitution table of impact-export (restitution_table.hpp).

#include "impact_postprocess/export/restitution_table.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/run/fem_run_record.hpp"
#include "impact_postprocess/same_value.hpp"

#include <impact_fem/as_written.h>
#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hunt_crossley_elastic_plastic.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/kuwabara_kono_elastic_plastic.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>
#include <impact_reduced/thornton.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A key of the calibration that names a damped elastic-plastic law: a fitted model or a
// reference model from the material.
bool damped_key(const std::string& key) {
  return is_damped_plastic_model(key) || key == model_keys::hunt_crossley_thornton_material ||
         key == model_keys::hunt_crossley_jackson_green_material ||
         key == model_keys::kuwabara_kono_thornton_material ||
         key == model_keys::kuwabara_kono_jackson_green_material;
}

// Where the calibration holds the law: its fit (with the out-of-sample predictions) or its
// reference model.
struct Source {
  const CampaignModelFit* fit = nullptr;
  const ReferenceModel* reference = nullptr;
};

Source find_source(const Calibration& calibration, const std::string& key) {
  Source source;
  source.fit = calibration.campaign.find(key);
  if (source.fit && !is_damped_plastic_model(source.fit->fit.model)) source.fit = nullptr;
  for (const auto& reference : calibration.campaign.reference_models)
    if (reference.key == key && is_damped_plastic_model(reference.model))
      source.reference = &reference;
  return source;
}

std::string list(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

const RunResidual* residual_at(const std::vector<RunResidual>& runs, double velocity) {
  for (const auto& run : runs)
    if (same_value(run.velocity, velocity)) return &run;
  return nullptr;
}

std::array<double, 3> relative_errors(const reduced::ImpactFigures& law, const ImpactFigures& fem) {
  return {law.restitution / fem.restitution - 1, law.contact_time / fem.contact_time - 1,
          law.force_max / fem.force_max - 1};
}

std::string number(double value) {
  return std::isfinite(value) ? impact_fem::as_written(value) : std::string();
}

json number_or_null(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

// The columns: name, unit, meaning. The CSV and the JSON rows carry them in this order.
struct Column {
  const char* name;
  const char* unit;
  const char* meaning;
};
const std::vector<Column>& columns() {
  static const std::vector<Column> list = {
      {"impact_velocity", "m/s", "V, the normal speed at first contact"},
      {"row", "-", "fem: a velocity of the FEM campaign; interpolated: a velocity between them"},
      {"damping", "s/m",
       "b(V), the law's Hunt-Crossley damping at this V (empty: Kuwabara-Kono damping, whose A "
       "does not depend on V)"},
      {"restitution", "1", "e of the law"},
      {"contact_time", "s", "t_c of the law"},
      {"force_max", "N", "F_max of the law"},
      {"approach_max", "m", "x_max of the law"},
      {"permanent_approach", "m", "x_s of the law, where the bodies part (0: elastic)"},
      {"fem_restitution", "1", "e of the FEM (empty: no FEM run at this V)"},
      {"fem_restitution_uncertainty", "1",
       "relative numerical uncertainty of the FEM's e (GCI of the run's verification; empty: "
       "not known)"},
      {"fem_contact_time", "s", "t_c of the FEM"},
      {"fem_contact_time_uncertainty", "1", "relative uncertainty of the FEM's t_c"},
      {"fem_force_max", "N", "F_max of the FEM"},
      {"fem_force_max_uncertainty", "1", "relative uncertainty of the FEM's F_max"},
      {"error_restitution", "1",
       "law / FEM - 1 in e (the exported law; empty: not known, no FEM at this V)"},
      {"error_contact_time", "1", "law / FEM - 1 in t_c"},
      {"error_force_max", "1", "law / FEM - 1 in F_max"},
      {"out_of_sample_error_restitution", "1",
       "the same error of the law fitted without this velocity (empty: not known)"},
      {"out_of_sample_error_contact_time", "1", "the same in t_c"},
      {"out_of_sample_error_force_max", "1", "the same in F_max"},
  };
  return list;
}

std::vector<std::string> row_fields(const RestitutionTableRow& row) {
  const auto& law = row.law;
  std::vector<std::string> fields = {number(row.velocity),     row.fem ? "fem" : "interpolated",
                                     number(row.damping),      number(law.restitution),
                                     number(law.contact_time), number(law.force_max),
                                     number(law.approach_max), number(law.separation_approach)};
  if (row.fem) {
    const auto& fem = *row.fem;
    fields.push_back(number(fem.figures.restitution));
    fields.push_back(number(fem.uncertainty[0]));
    fields.push_back(number(fem.figures.contact_time));
    fields.push_back(number(fem.uncertainty[1]));
    fields.push_back(number(fem.figures.force_max));
    fields.push_back(number(fem.uncertainty[2]));
    for (double error : fem.error) fields.push_back(number(error));
    for (double error : fem.out_of_sample_error) fields.push_back(number(error));
  } else {
    fields.resize(columns().size());
  }
  return fields;
}

json law_json(const RestitutionTableLaw& law) {
  const bool thornton = law.spring == "thornton";
  json spring = {{"name", law.spring},
                 {"c", {{"value", law.stiffness}, {"unit", "N/m^1.5"}}},
                 {thornton ? "x_y" : "Y",
                  {{"value", law.yield_parameter}, {"unit", thornton ? "m" : "Pa"}}}};
  if (!thornton) {
    spring["R"] = {{"value", law.radius}, {"unit", "m"}};
    spring["nu"] = {{"value", law.poisson_ratio}, {"unit", "1"}};
  }
  json reduced_library;
  if (thornton)
    reduced_library = {{"spring",
                        "impact::reduced::ThorntonContact(radius, contact_modulus, "
                        "yield_pressure)"},
                       {"radius", 1.0},
                       {"contact_modulus", 0.75 * law.stiffness},
                       {"yield_pressure",
                        thornton_yield_pressure(law.stiffness, law.yield_parameter, 1.0)},
                       {"note", "R = 1 m: Thornton's law depends on R only through c and x_y"}};
  else
    reduced_library = {{"spring",
                        "impact::reduced::JacksonGreenContact({radius, contact_modulus, "
                        "yield_strength, poisson_ratio})"},
                       {"radius", law.radius},
                       {"contact_modulus", 0.75 * law.stiffness / std::sqrt(law.radius)},
                       {"yield_strength", law.yield_parameter},
                       {"poisson_ratio", law.poisson_ratio}};
  const bool kuwabara_kono = law.damping == TableDamping::kuwabara_kono;
  reduced_library["impact"] =
      kuwabara_kono ? "impact::reduced::kuwabara_kono_elastic_plastic_impact(mass, V, spring, A)"
                    : "impact::reduced::HuntCrossleyElasticPlasticImpact(mass, spring, b(V), V)";
  if (kuwabara_kono)
    reduced_library["force"] =
        "impact::reduced::kuwabara_kono_elastic_plastic_force(spring, A, x, x', x_max)";
  json damping;
  switch (law.damping) {
    case TableDamping::hunt_crossley:
      damping = {{"kind", "hunt-crossley"},
                 {"b", {{"value", law.damping_parameter}, {"unit", "s/m"}}}};
      break;
    case TableDamping::hunt_crossley_of_velocity:
      damping = {{"kind", "hunt-crossley"},
                 {"A", {{"value", law.damping_parameter}, {"unit", "s"}}},
                 {"b(V)", "(3/2) gamma_1 A (c/m)^(2/5) V^(-4/5), gamma_1 = " +
                              impact_fem::as_written(reduced::brilliantov_gamma1())}};
      break;
    case TableDamping::kuwabara_kono:
      damping = {{"kind", "kuwabara-kono"},
                 {"A", {{"value", law.damping_parameter}, {"unit", "s"}}}};
      break;
  }
  return {{"key", law.key},
          {"model", law.model},
          {"label", law.label},
          {"force_law",
           std::string(kuwabara_kono
                           ? "F = F_s(x) + A k_t(x) x', k_t = dF_s/dx of the current branch"
                           : "F = F_s(x) (1 + b x')") +
               ", x the approach, x' its rate; F_s the loading branch while x grows, the "
               "Hertzian unloading branch from x_max after; contact ends where " +
               (kuwabara_kono ? "the force returns to 0" : "the unloading branch returns to 0")},
          {"formula", law.formula},
          {"reference", law.reference},
          {"basis", law.basis},
          {"rank", law.rank},
          {"score", number_or_null(law.score)},
          {"mass", {{"value", law.mass}, {"unit", "kg"}}},
          {"sphere_radius", {{"value", law.radius}, {"unit", "m"}}},
          {"spring", spring},
          {"damping", damping},
          {"reduced_library", reduced_library}};
}

} // namespace

std::shared_ptr<const reduced::ElasticPlasticContact> table_spring(const RestitutionTableLaw& law) {
  if (law.spring == "thornton")
    return std::make_shared<reduced::ThorntonContact>(1.0, 0.75 * law.stiffness,
                                                      thornton_yield_pressure(law.stiffness,
                                                                              law.yield_parameter,
                                                                              1.0));
  return std::make_shared<reduced::JacksonGreenContact>(
      reduced::SphereFlatContact{law.radius, 0.75 * law.stiffness / std::sqrt(law.radius),
                                 law.yield_parameter, law.poisson_ratio});
}

double table_damping(const RestitutionTableLaw& law, double velocity) {
  switch (law.damping) {
    case TableDamping::hunt_crossley:
      return law.damping_parameter;
    case TableDamping::hunt_crossley_of_velocity:
      return matched_hunt_crossley_damping(law.damping_parameter, velocity,
                                           {law.mass, law.stiffness, 1.5});
    case TableDamping::kuwabara_kono:
      break;
  }
  return nan;
}

std::vector<std::string> restitution_table_laws(const Calibration& calibration) {
  std::vector<std::string> keys;
  for (const auto& ranked : calibration.campaign.ranking) {
    if (!damped_key(ranked.key) || !ranked.converged) continue;
    const Source source = find_source(calibration, ranked.key);
    if (source.fit || source.reference) keys.push_back(ranked.key);
  }
  return keys;
}

namespace {

// The law of the table: the one asked for (it must be a damped elastic-plastic law the
// calibration holds, fitted to convergence), else the best ranked of those.
std::string table_law_key(const Calibration& calibration, const std::optional<std::string>& model) {
  const std::vector<std::string> available = restitution_table_laws(calibration);
  std::string key;
  if (model) {
    if (!damped_key(*model))
      throw RestitutionTableError("--law " + *model +
                                  ": not a damped elastic-plastic law (the "
                                  "calibration has " +
                                  list(available) + ")");
    key = *model;
  } else {
    if (available.empty())
      throw RestitutionTableError(
          "the calibration ranks no damped elastic-plastic law (impact-calibrate --laws "
          "hunt-crossley-thornton,...)");
    key = available.front();
  }
  const Source source = find_source(calibration, key);
  if (!source.fit && !source.reference)
    throw RestitutionTableError("the calibration has no law " + key + " (it has " +
                                list(available) + ")");
  if (source.fit && !source.fit->fit.converged)
    throw RestitutionTableError("the calibration's fit of " + key + " did not converge");
  return key;
}

// The law's constants: from its campaign fit or its reference (no fit), with the sphere the
// runs share (one mass per table; Jackson-Green's spring needs the radius and Poisson ratio).
RestitutionTableLaw table_law(const Calibration& calibration, const std::string& key,
                              const Source& source, const std::vector<FemRun>& runs) {
  RestitutionTableLaw law;
  law.key = key;
  law.model = source.fit ? source.fit->fit.model : source.reference->model;
  law.label = source.fit ? source.fit->label : source.reference->label;
  law.formula = source.fit ? source.fit->formula : model_formula(law.model);
  law.reference = source.fit ? source.fit->reference : "";
  law.basis = source.fit ? "fitted to the campaign's force histories and energy losses "
                           "(impact-calibrate), c held at the Hertz value where the runs "
                           "record the materials"
                         : source.reference->basis;
  law.stiffness = source.fit ? source.fit->fit.stiffness.value : source.reference->stiffness;
  const std::vector<double> dissipation =
      source.fit ? source.fit->fit.dissipation() : source.reference->dissipation;
  if (dissipation.size() != 2)
    throw RestitutionTableError(key + ": expected two dissipation parameters (yield, damping)");
  law.yield_parameter = dissipation[0];
  law.damping_parameter = dissipation[1];
  law.damping = damped_plastic_damping(law.model);
  law.spring = damped_plastic_needs_scenario(law.model) ? "jackson-green" : "thornton";
  law.rank = 0;
  law.score = nan;
  for (std::size_t i = 0; i < calibration.campaign.ranking.size(); ++i)
    if (calibration.campaign.ranking[i].key == key) {
      law.rank = i + 1;
      law.score = calibration.campaign.ranking[i].score;
    }
  law.mass = runs.front().mass;
  for (const auto& run : runs)
    if (!same_value(run.mass, law.mass))
      throw RestitutionTableError(run.source + ": mass " + std::to_string(run.mass) +
                                  " kg differs from the other runs': one sphere per table");
  const auto scenario = sphere_flat_scenario(runs);
  law.radius = scenario ? scenario->radius : nan;
  law.poisson_ratio = nan;
  if (law.spring == "jackson-green") {
    if (!scenario)
      throw RestitutionTableError(key +
                                  ": the runs do not record the sphere radius and Poisson "
                                  "ratio that Jackson-Green's spring needs");
    law.poisson_ratio = scenario->poisson_ratio;
  }
  return law;
}

// The velocities of the table: log-spaced over the campaign's range, and the runs' own (with
// their run), increasing.
std::vector<std::pair<double, const FemRun*>> table_velocities(const std::vector<FemRun>& runs,
                                                               std::size_t points) {
  std::vector<const FemRun*> by_velocity;
  for (const auto& run : runs) by_velocity.push_back(&run);
  std::sort(by_velocity.begin(), by_velocity.end(), [](const FemRun* a, const FemRun* b) {
    return a->impact_velocity < b->impact_velocity;
  });
  const double low = by_velocity.front()->impact_velocity,
               high = by_velocity.back()->impact_velocity;
  std::vector<std::pair<double, const FemRun*>> velocities;
  for (const FemRun* run : by_velocity) velocities.emplace_back(run->impact_velocity, run);
  for (std::size_t k = 0; k < points; ++k) {
    const double velocity =
        k + 1 == points ? high : low * std::pow(high / low, double(k) / double(points - 1));
    const bool at_run = std::any_of(velocities.begin(), velocities.end(), [&](const auto& entry) {
      return entry.second && same_value(entry.first, velocity);
    });
    if (!at_run) velocities.emplace_back(velocity, nullptr);
  }
  std::sort(velocities.begin(), velocities.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return velocities;
}

// The FEM at a run of the table: its figures (the calibration's measured numbers where it has
// the run), their uncertainty, and the law's errors against them, in and out of sample.
RestitutionTableFem fem_at(const FemRun& fem_run, const Calibration& calibration,
                           const Source& source, const RestitutionTableRow& row) {
  const double velocity = row.velocity;
  RestitutionTableFem fem;
  fem.source = fem_run.source;
  fem.figures = measured_quantities(fem_run);
  for (const auto& entry : calibration.runs)
    if (same_value(entry.velocity, velocity)) fem.figures = entry.measured;
  const FemUncertainty uncertainty = fem_uncertainty(read_fem_run_record(fem_run), fem.figures);
  const Quantity judged[3] = {Quantity::restitution, Quantity::contact_time, Quantity::force_max};
  for (std::size_t q = 0; q < 3; ++q) {
    fem.uncertainty[q] = uncertainty[std::size_t(judged[q])].relative;
    fem.uncertainty_source[q] = uncertainty[std::size_t(judged[q])].source;
  }
  fem.error = relative_errors(row.law.figures(), fem.figures);
  fem.out_of_sample_error = {nan, nan, nan};
  const RunResidual* residual =
      residual_at(source.fit ? source.fit->runs : source.reference->runs, velocity);
  if (residual) {
    const ImpactPrediction& predicted =
        source.fit
            ? residual->out_of_sample.value_or(ImpactPrediction{{nan, nan, nan, nan, nan}, nan})
            : residual->prediction;
    fem.out_of_sample_error = relative_errors(predicted, fem.figures);
  }
  return fem;
}

// The law's impact at V: the closed form (Hunt–Crossley) or the integration (Kuwabara–Kono).
RestitutionTableResponse table_response(
    const RestitutionTableLaw& law,
    const std::shared_ptr<const reduced::ElasticPlasticContact>& spring, double velocity) {
  if (law.damping == TableDamping::kuwabara_kono) {
    const reduced::OdeImpactResult r =
        reduced::kuwabara_kono_elastic_plastic_impact(law.mass, velocity, *spring,
                                                      law.damping_parameter);
    return {r.restitution,    r.contact_time, r.force_max,
            r.time_force_max, r.approach_max, r.approach_at_separation};
  }
  const reduced::HuntCrossleyElasticPlasticResponse r =
      reduced::HuntCrossleyElasticPlasticImpact(law.mass, spring, table_damping(law, velocity),
                                                velocity)
          .response();
  return {r.restitution,    r.contact_time, r.force_max,
          r.time_force_max, r.approach_max, r.separation_approach};
}

} // namespace

RestitutionTable restitution_table(const Calibration& calibration, const std::vector<FemRun>& runs,
                                   const std::optional<std::string>& model, std::size_t points) {
  if (points < 2)
    throw reduced::InvalidInput("points", "the table needs at least 2 velocities, got " +
                                              std::to_string(points));
  if (runs.empty()) throw RestitutionTableError("the campaign has no runs");
  const std::string key = table_law_key(calibration, model);
  const Source source = find_source(calibration, key);
  RestitutionTable table;
  table.law = table_law(calibration, key, source, runs);
  const RestitutionTableLaw& law = table.law;

  const auto spring = table_spring(law);
  for (const auto& [velocity, run] : table_velocities(runs, points)) {
    RestitutionTableRow row;
    row.velocity = velocity;
    row.damping = table_damping(law, velocity);
    try {
      row.law = table_response(law, spring, velocity);
    } catch (const std::exception& error) {
      throw RestitutionTableError(key + " at V = " + std::to_string(velocity) +
                                  " m/s: " + error.what());
    }
    if (run) row.fem = fem_at(*run, calibration, source, row);
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::string restitution_table_csv(const RestitutionTable& table) {
  const RestitutionTableLaw& law = table.law;
  std::ostringstream out;
  out << "# impact-restitution-table 1 (impact-export): e(V), t_c(V), F_max(V) of one "
         "calibrated contact law\n"
      << "# law: " << law.key << " (" << law.label << ")";
  if (law.rank > 0) out << ", rank " << law.rank << " of the calibration, score " << law.score;
  out << "\n# force law: " << law.formula << "\n"
      << "# mass m = " << impact_fem::as_written(law.mass)
      << " kg; c = " << impact_fem::as_written(law.stiffness) << " N/m^1.5; "
      << (law.spring == "thornton" ? "x_y = " : "Y = ")
      << impact_fem::as_written(law.yield_parameter) << (law.spring == "thornton" ? " m" : " Pa");
  if (law.spring == "jackson-green")
    out << "; R = " << impact_fem::as_written(law.radius)
        << " m; nu = " << impact_fem::as_written(law.poisson_ratio);
  switch (law.damping) {
    case TableDamping::hunt_crossley:
      out << "; b = " << impact_fem::as_written(law.damping_parameter) << " s/m";
      break;
    case TableDamping::hunt_crossley_of_velocity:
      out << "; A = " << impact_fem::as_written(law.damping_parameter)
          << " s, b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5)";
      break;
    case TableDamping::kuwabara_kono:
      out << "; A = " << impact_fem::as_written(law.damping_parameter)
          << " s (Kuwabara-Kono: F = F_s + A k_t x')";
      break;
  }
  out << "\n# basis: " << law.basis << "\n"
      << "# FEM uncertainty: relative, the interval FEM value (1 +- U) that the report's "
         "verdict uses (GCI of the run's verification, else what the history shows)\n"
      << "# empty field: not known (error columns: no FEM run at this velocity)\n"
      << "# columns (unit):\n";
  for (const auto& column : columns())
    out << "#   " << column.name << " [" << column.unit << "]: " << column.meaning << "\n";
  for (std::size_t i = 0; i < columns().size(); ++i) out << (i ? "," : "") << columns()[i].name;
  out << "\n";
  for (const auto& row : table.rows) {
    const auto fields = row_fields(row);
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
    out << "\n";
  }
  return out.str();
}

json restitution_table_json(const RestitutionTable& table) {
  json units = json::object(), meanings = json::object(), names = json::array();
  for (const auto& column : columns()) {
    units[column.name] = column.unit;
    meanings[column.name] = column.meaning;
    names.push_back(column.name);
  }
  json rows = json::array();
  for (const auto& row : table.rows) {
    const auto fields = row_fields(row);
    json entry = json::object();
    for (std::size_t i = 0; i < columns().size(); ++i) {
      const std::string name = columns()[i].name;
      if (name == "row")
        entry[name] = fields[i];
      else
        entry[name] = fields[i].empty() ? json(nullptr) : json(std::stod(fields[i]));
    }
    entry["error_known"] = row.fem.has_value();
    if (row.fem) {
      entry["fem_source"] = row.fem->source;
      entry["fem_uncertainty_source"] = {{"restitution", row.fem->uncertainty_source[0]},
                                         {"contact_time", row.fem->uncertainty_source[1]},
                                         {"force_max", row.fem->uncertainty_source[2]}};
    }
    rows.push_back(entry);
  }
  return {{"format", "impact-restitution-table"},
          {"format_version", 1},
          {"generated_by", "impact-export"},
          {"law", law_json(table.law)},
          {"columns", names},
          {"units", units},
          {"meaning", meanings},
          {"not_known", "null: not known (the error columns: no FEM run at this velocity)"},
          {"rows", rows}};
}

} // namespace impact::postprocess
