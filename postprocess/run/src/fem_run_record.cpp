#include "impact_postprocess/run/fem_run_record.hpp"

#include "impact_postprocess/run/fem_run_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

fs::path summary_of(const fs::path& file) {
  if (file.filename() == fem_format::history_file)
    return file.parent_path() / fem_format::summary_file;
  return file.parent_path() / (file.stem().string() + ".summary.json");
}

double median_step(const std::vector<double>& time) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < time.size(); ++i) steps.push_back(time[i] - time[i - 1]);
  if (steps.empty()) return nan;
  std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(steps.size() / 2), steps.end());
  return steps[steps.size() / 2];
}

// The approach at time t, linearly interpolated; NaN outside the history.
double approach_at(const FemRun& run, double t) {
  for (std::size_t i = 1; i < run.time.size(); ++i)
    if (run.time[i - 1] <= t && t <= run.time[i]) {
      const double w = (t - run.time[i - 1]) / (run.time[i] - run.time[i - 1]);
      return (1 - w) * run.approach[i - 1] + w * run.approach[i];
    }
  return nan;
}

std::string lower_case(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool has_plastic_material(const FemRun& run) {
  for (const char* key : {"Sphere/Material model", "Plate/Material model"}) {
    const auto model = run.text_attributes.find(key);
    if (model != run.text_attributes.end() && model->second == "elastic-plastic") return true;
  }
  return false;
}

} // namespace

double BodyStress::ratio() const {
  return max_von_mises && yield_strength ? *max_von_mises / *yield_strength : nan;
}

namespace {

// What the run's summary records, else the run file's attribute of the same key (the FEM
// writes both); a summary that cannot be read counts as empty (the run reader has already
// accepted or rejected it).
class RunSummary {
public:
  explicit RunSummary(const FemRun& run) : run(run) {
    try {
      std::ifstream in(summary_of(run.source));
      if (in) summary = json::parse(in);
    } catch (const json::exception&) {
      summary = json::object();
    }
  }
  std::optional<double> value(const std::string& key) const {
    if (summary.is_object() && summary.contains(key) && summary.at(key).is_number())
      return summary.at(key).get<double>();
    const auto attribute = run.numeric_attributes.find(fem_format::result_attribute_prefix + key);
    if (attribute != run.numeric_attributes.end() && std::isfinite(attribute->second))
      return attribute->second;
    return std::nullopt;
  }
  /// A true/false entry of the summary (none in the run file's attributes).
  std::optional<bool> flag(const std::string& key) const {
    if (summary.is_object() && summary.contains(key) && summary.at(key).is_boolean())
      return summary.at(key).get<bool>();
    return std::nullopt;
  }

private:
  const FemRun& run;
  json summary = json::object();
};

// A body's strength from one more source: the lowest positive one is kept, with its key.
void consider(BodyStress& body, const std::string& key, std::optional<double> strength) {
  if (!strength || !(*strength > 0)) return;
  if (!body.yield_strength || *strength < *body.yield_strength) {
    body.yield_strength = strength;
    body.yield_source = key;
  }
}

// Stresses and yield strengths, per body: impact-fem records "von_mises_max_<body>" and,
// for a body checked against a strength, "yield_strength_<body>"; the parameters
// "<Body>/Yield strength" (0 = none) and an elastic-plastic body's material constant give
// the strength when the summary does not. A summary of another tool may record only the
// generic pair "max_von_mises" / "yield_strength": then one entry for both bodies.
std::vector<BodyStress> body_stresses(const FemRun& run, const RunSummary& summary) {
  std::vector<BodyStress> bodies;
  const std::optional<double> generic_strength = summary.value("yield_strength");
  for (const char* name : {fem_format::sphere_body, fem_format::plate_body}) {
    const std::string key = lower_case(name); // impact-fem's summary names the bodies so
    BodyStress body{name, summary.value(fem_format::von_mises_max_prefix + key), {}, {}, {}};
    consider(body, fem_format::yield_strength_prefix + key,
             summary.value(fem_format::yield_strength_prefix + key));
    const std::string parameter = fem_format::body_parameter(name, fem_format::yield_strength);
    consider(body, parameter, text_number(run, parameter));
    // An elastic-plastic body's initial yield strength (its material's constant).
    const auto model = run.text_attributes.find(fem_format::material_model_parameter(name));
    if (model != run.text_attributes.end() && model->second == fem_format::elastic_plastic_model)
      consider(body,
               fem_format::material_parameter(name, fem_format::elastic_plastic_model,
                                              fem_format::yield_strength),
               material_constant(run, name, fem_format::yield_strength));
    if (!body.yield_strength) consider(body, "yield_strength", generic_strength);
    const std::string flag = fem_format::yield_exceeded_key + ("_" + key);
    if (const auto yields = summary.flag(flag))
      body.yields = *yields;
    else if (body.max_von_mises && body.yield_strength)
      body.yields = *body.max_von_mises > *body.yield_strength;
    bodies.push_back(std::move(body));
  }
  const bool per_body = std::any_of(bodies.begin(), bodies.end(),
                                    [](const BodyStress& body) { return body.max_von_mises; });
  if (const auto largest = summary.value(fem_format::max_von_mises_key); largest && !per_body) {
    BodyStress both{both_bodies, largest, {}, {}, {}};
    for (const auto& body : bodies) consider(both, body.yield_source, body.yield_strength);
    if (both.yield_strength) both.yields = *both.max_von_mises > *both.yield_strength;
    bodies = {std::move(both)};
  }
  return bodies;
}

// The body nearest to its own strength sets the record's stress and strength; the run yields
// as its summary says, else when a body yields.
void set_governing_body(FemRunRecord& record, const RunSummary& summary) {
  const BodyStress* governing = nullptr;
  for (const auto& body : record.bodies) {
    if (!body.max_von_mises) continue;
    const double ratio = body.ratio(), best = governing ? governing->ratio() : nan;
    if (!governing || (std::isfinite(ratio) && !(ratio <= best)) ||
        (!std::isfinite(ratio) && !std::isfinite(best) &&
         *body.max_von_mises > *governing->max_von_mises))
      governing = &body;
  }
  if (governing) {
    record.max_von_mises = governing->max_von_mises;
    record.yield_strength = governing->yield_strength;
    record.yield_source = governing->yield_source;
  }
  if (const auto yields = summary.flag(fem_format::yield_exceeded_key)) {
    record.yields = *yields;
  } else {
    for (const auto& body : record.bodies)
      if (body.yields) record.yields = record.yields.value_or(false) || *body.yields;
  }
}

} // namespace

FemRunRecord read_fem_run_record(const FemRun& run) {
  const RunSummary summary(run);
  const auto value = [&](const std::string& key) { return summary.value(key); };
  FemRunRecord record;
  record.energy_error = value(fem_format::energy_error_key);
  record.lost_energy_fraction = value(fem_format::lost_energy_fraction_key);
  record.dissipated_energy_fraction = value(fem_format::dissipated_energy_fraction_key);
  record.radiated_energy_fraction = value(fem_format::radiated_energy_fraction_key);

  record.energy_error_final = value(fem_format::energy_error_final_key);

  record.bodies = body_stresses(run, summary);
  set_governing_body(record, summary);

  record.plastic_material = has_plastic_material(run);
  if (record.plastic_material) {
    record.permanent_approach = value("permanent_approach"); // impact-fem's plasticity summary
    if (!record.permanent_approach) {
      const double measured = approach_at(run, run.first_contact_time + run.contact_time);
      if (std::isfinite(measured)) record.permanent_approach = std::max(measured, 0.0);
    }
  }

  const auto oscillation = value(fem_format::force_oscillation_key);
  const auto after_release = value(fem_format::force_after_release_key);
  if (oscillation && after_release) {
    record.smoothness = {*oscillation, *after_release};
    record.smoothness_source = "summary.json";
  } else {
    record.smoothness = force_smoothness(run.contact_force);
    record.smoothness_source = "measured on the force history";
  }
  record.time_step = value(fem_format::time_step_key).value_or(median_step(run.time));
  record.release_span = release_span(run.time, run.contact_force);
  try {
    record.verification = read_verification(run.source);
  } catch (const RunInputError& error) {
    record.verification_problem = error.what();
  }
  return record;
}

FemUncertainty fem_uncertainty(const FemRunRecord& record, const ImpactFigures& fem) {
  FemUncertainty uncertainty;
  for (auto& entry : uncertainty) entry = {nan, "not known (no verification of the run)"};
  const auto set = [&](Quantity quantity, double relative, std::string source) {
    uncertainty[std::size_t(quantity)] = {relative, std::move(source)};
  };
  if (record.verification) {
    const auto& quantities = record.verification->quantities;
    const std::string source = "GCI of the verification (" + record.verification->source + ")";
    const auto gci = [&](const char* key) {
      const auto found = quantities.find(key);
      return found == quantities.end() ? nan : found->second.gci_fine;
    };
    set(Quantity::contact_time, gci(fem_format::contact_time_key), source);
    set(Quantity::force_max, gci(fem_format::force_max_key), source);
    set(Quantity::time_force_max, gci(fem_format::time_force_max_key), source);
    set(Quantity::approach_max, gci(fem_format::approach_max_key), source);
    const auto restitution = quantities.find(fem_format::restitution_key);
    if (restitution != quantities.end()) {
      double absolute = restitution->second.gci_fine_absolute;
      if (!std::isfinite(absolute))
        absolute = restitution->second.gci_fine * std::abs(fem.restitution);
      const double e = fem.restitution;
      set(Quantity::restitution, absolute / e, source);
      set(Quantity::restitution_deficit, absolute / (1 - e), source);
      set(Quantity::energy_loss, 2 * e * absolute / (1 - e * e), source);
    }
    return uncertainty;
  }
  if (std::isfinite(record.smoothness.oscillation))
    set(Quantity::force_max, record.smoothness.oscillation,
        "step-to-step oscillation of the force history (" + record.smoothness_source + ")");
  if (std::isfinite(record.time_step) && fem.contact_time > 0) {
    const bool chatter = record.release_span > record.time_step;
    set(Quantity::contact_time, std::max(record.time_step, record.release_span) / fem.contact_time,
        chatter ? "the release chatter (force after the first zero that follows the peak)"
                : "one time step (the contact time is bound to the steps)");
  }
  if (std::isfinite(record.time_step) && fem.time_force_max > 0)
    set(Quantity::time_force_max, record.time_step / fem.time_force_max, "one time step");
  return uncertainty;
}

} // namespace impact::postprocess
