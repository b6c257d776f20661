// The calibration JSON (calibration_json.hpp): writer and typed reader of the same layout.

#include "impact_postprocess/calibration/calibration_json.hpp"
#include "impact_postprocess/models/model_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// ---- Writing ----------------------------------------------------------------------------

json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json estimate_json(const Estimate& estimate, const std::string& unit, bool fixed) {
  return {{"value", number(estimate.value)},
          {"standard_error", number(estimate.standard_error)},
          {"interval", json::array({number(estimate.lower), number(estimate.upper)})},
          {"unit", unit},
          {"fixed", fixed}};
}

json quality_json(const FitQuality& quality) {
  return {{"rms_residual", number(quality.rms_residual)},
          {"r_squared", number(quality.r_squared)},
          {"samples", quality.samples}};
}

json prediction_json(const ImpactPrediction& prediction) {
  return {{"damping", number(prediction.damping)},
          {"restitution", number(prediction.restitution)},
          {"contact_time", number(prediction.contact_time)},
          {"force_max", number(prediction.force_max)},
          {"time_force_max", number(prediction.time_force_max)},
          {"approach_max", number(prediction.approach_max)}};
}

json quantities_json(const ImpactFigures& quantities) {
  return {{"restitution", number(quantities.restitution)},
          {"contact_time", number(quantities.contact_time)},
          {"force_max", number(quantities.force_max)},
          {"time_force_max", number(quantities.time_force_max)},
          {"approach_max", number(quantities.approach_max)}};
}

std::vector<std::string> units_of(const ModelFit& fit) {
  std::vector<std::string> units{"N/m^n", "1", fit.parameter_unit};
  for (const auto& entry : fit.extra) units.push_back(entry.unit);
  return units;
}

json fit_json(const ModelFit& fit) {
  const std::vector<std::string> names = fit.parameter_names();
  const std::size_t k = names.size();
  json parameters = {{"c", estimate_json(fit.stiffness, "N/m^n", false)},
                     {"n", estimate_json(fit.exponent, "1", fit.exponent_fixed)},
                     {fit.parameter_name,
                      estimate_json(fit.parameter, fit.parameter_unit, fit.parameter_fixed)}};
  for (const auto& entry : fit.extra)
    parameters[entry.name] = estimate_json(entry.estimate, entry.unit, false);
  json correlation = json::object(), covariance = json::array();
  for (std::size_t i = 0; i < k; ++i) {
    json row = json::array();
    for (std::size_t j = 0; j < k; ++j) {
      row.push_back(number(fit.covariance.size() == k * k ? fit.covariance[i * k + j] : nan));
      if (j > i)
        correlation[names[i] + "," + names[j]] =
            number(fit.correlation.size() == k * k ? fit.correlation[i * k + j] : nan);
    }
    covariance.push_back(row);
  }
  json result = {{"model", fit.model},
                 {"parameters", parameters},
                 {"parameter_order", names},
                 {"free_parameters", fit.free_parameters()},
                 {"correlation", correlation},
                 {"covariance", {{"order", names}, {"matrix", covariance}}},
                 {"reference_approach", {{"value", number(fit.reference_approach)}, {"unit", "m"}}},
                 {"force_at_reference_approach", estimate_json(fit.force_at_reference, "N", false)},
                 {"converged", fit.converged},
                 {"iterations", fit.iterations},
                 {"solver_message", fit.solver_message}};
  result.update(quality_json(fit.quality));
  return result;
}

json parameter_values_json(const std::vector<std::string>& names,
                           const std::vector<double>& values) {
  json result = json::object();
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
    result[names[i]] = number(values[i]);
  return result;
}

json campaign_fit_json(const CampaignModelFit& campaign_fit) {
  json result = fit_json(campaign_fit.fit);
  const auto names = campaign_fit.fit.parameter_names();
  result["key"] = campaign_fit.key;
  result["label"] = campaign_fit.label;
  result["formula"] = campaign_fit.formula;
  result["reference"] = campaign_fit.reference;
  result["damping"] = {{"name", campaign_fit.damping_name}, {"unit", campaign_fit.damping_unit}};
  result["energy_weight"] = campaign_fit.energy_weight;
  result["intervals"] =
      "parameters[].interval: s^2 (J^T J)^-1, conditional on the model (residuals taken as "
      "independent noise); jackknife: over the fits with one velocity left out";
  json runs = json::array();
  for (const auto& run : campaign_fit.runs) {
    json entry = {{"source", run.source}, {"impact_velocity", number(run.velocity)}};
    entry.update(quality_json(run.quality));
    entry["prediction"] = prediction_json(run.prediction);
    entry["out_of_sample"] = run.out_of_sample ? prediction_json(*run.out_of_sample) : json(nullptr);
    runs.push_back(entry);
  }
  result["runs"] = runs;
  json held_out = json::array();
  for (const auto& fit : campaign_fit.held_out)
    held_out.push_back({{"velocity", number(fit.velocity)},
                        {"parameters", parameter_values_json(names, fit.parameters)},
                        {"converged", fit.converged}});
  result["held_out"] = held_out;
  if (campaign_fit.jackknife.empty()) {
    result["jackknife"] = nullptr;
  } else {
    json jackknife = json::object();
    const auto units = units_of(campaign_fit.fit);
    for (std::size_t i = 0; i < names.size() && i < campaign_fit.jackknife.size(); ++i) {
      json entry = estimate_json(campaign_fit.jackknife[i], units[i], false);
      entry.erase("fixed");
      jackknife[names[i]] = entry;
    }
    result["jackknife"] = jackknife;
  }
  return result;
}

json reference_json(const ReferenceModel& reference) {
  json parameters = {{"c", number(reference.stiffness)}, {"n", number(reference.exponent)}};
  if (!reference.dissipation.empty())
    parameters[reference.parameter_name] = number(reference.dissipation[0]);
  json runs = json::array();
  for (const auto& run : reference.runs) {
    json entry = {{"source", run.source}, {"impact_velocity", number(run.velocity)}};
    entry.update(quality_json(run.quality));
    entry["prediction"] = prediction_json(run.prediction);
    runs.push_back(entry);
  }
  return {{"key", reference.key},
          {"label", reference.label},
          {"model", reference.model},
          {"basis", reference.basis},
          {"parameters", parameters},
          {"parameter", {{"name", reference.parameter_name}, {"unit", reference.parameter_unit}}},
          {"runs", runs}};
}

json run_json(const RunCalibration& run) {
  return {{"source", run.source},
          {"impact_velocity", number(run.velocity)},
          {"mass", number(run.mass)},
          {"measured", quantities_json(run.measured)},
          {"restitution_fit",
           {{"b", {{"value", number(run.damping_from_restitution)}, {"unit", "s/m"}}},
            {"beta", number(run.impact_parameter)},
            {"method", "exact inverse of k(beta) (impact_parameter_from_restitution), b = beta / V; "
                       "no interval: exact for the measured restitution"}}},
          {"loading_fit", run.loading ? fit_json(*run.loading) : json(nullptr)},
          {"history_fit", run.history ? fit_json(*run.history) : json(nullptr)},
          {"history_prediction",
           run.history_prediction ? prediction_json(*run.history_prediction) : json(nullptr)}};
}

json ranking_json(const CampaignCalibration& campaign) {
  json ranking = json::array();
  for (const auto& entry : campaign.ranking) {
    json parameter = nullptr;
    if (const CampaignModelFit* fit = campaign.find(entry.key))
      parameter = {{"name", fit->fit.parameter_name},
                   {"value", number(fit->fit.parameter.value)},
                   {"unit", fit->fit.parameter_unit}};
    for (const auto& reference : campaign.reference_models)
      if (reference.key == entry.key)
        parameter = {{"name", reference.parameter_name},
                     {"value", number(reference.dissipation.empty() ? nan
                                                                     : reference.dissipation[0])},
                     {"unit", reference.parameter_unit}};
    ranking.push_back({{"model", entry.key},
                       {"free_parameters", entry.free_parameters},
                       {"score", number(entry.score)},
                       {"out_of_sample", entry.out_of_sample},
                       {"worst_error", number(entry.worst_error)},
                       {"in_sample_score", number(entry.in_sample_score)},
                       {"rms_residual", number(entry.rms_residual)},
                       {"converged", entry.converged},
                       {"family", entry.family},
                       {"parameter", parameter}});
  }
  return ranking;
}

// ---- Reading ----------------------------------------------------------------------------

class Reader {
public:
  Reader(const json& node, std::string path) : node_(node), path_(std::move(path)) {}

  Reader at(const std::string& key) const {
    if (!node_.is_object() || !node_.contains(key)) fail(key, "is missing");
    return {node_[key], path_ + "." + key};
  }
  Reader at(std::size_t index) const { return {node_.at(index), path_ + "[" + std::to_string(index) + "]"}; }
  bool has(const std::string& key) const {
    return node_.is_object() && node_.contains(key) && !node_[key].is_null();
  }
  bool is_null() const { return node_.is_null(); }
  std::size_t size() const {
    if (!node_.is_array()) fail("", "is not a list");
    return node_.size();
  }
  double number() const {
    if (node_.is_null()) return nan;
    if (!node_.is_number()) fail("", "is not a number");
    return node_.get<double>();
  }
  double number(const std::string& key) const { return at(key).number(); }
  std::string text(const std::string& key) const {
    const Reader value = at(key);
    if (!value.node_.is_string()) value.fail("", "is not a text");
    return value.node_.get<std::string>();
  }
  std::string text_or(const std::string& key, const std::string& fallback) const {
    return has(key) ? text(key) : fallback;
  }
  bool flag(const std::string& key) const {
    const Reader value = at(key);
    if (!value.node_.is_boolean()) value.fail("", "is not true or false");
    return value.node_.get<bool>();
  }
  std::size_t count(const std::string& key) const {
    const Reader value = at(key);
    if (!value.node_.is_number_unsigned()) value.fail("", "is not a count");
    return value.node_.get<std::size_t>();
  }
  std::vector<std::string> keys() const {
    std::vector<std::string> names;
    if (!node_.is_object()) fail("", "is not an object");
    for (const auto& item : node_.items()) names.push_back(item.key());
    return names;
  }
  std::vector<std::string> texts(const std::string& key) const {
    std::vector<std::string> values;
    const Reader list = at(key);
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!list.node_[i].is_string()) list.at(i).fail("", "is not a text");
      values.push_back(list.node_[i].get<std::string>());
    }
    return values;
  }
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw CalibrationFormatError("the calibration's " + path_ + (key.empty() ? "" : "." + key) +
                                 " " + problem);
  }

private:
  const json& node_;
  std::string path_;
};

Estimate read_estimate(const Reader& node) {
  const Reader interval = node.at("interval");
  if (interval.size() != 2) interval.fail("", "does not hold two numbers");
  return {node.number("value"), node.number("standard_error"), interval.at(0).number(),
          interval.at(1).number()};
}

FitQuality read_quality(const Reader& node) {
  return {node.number("rms_residual"), node.number("r_squared"), node.count("samples")};
}

ImpactFigures read_quantities(const Reader& node) {
  return {node.number("restitution"), node.number("contact_time"), node.number("force_max"),
          node.number("time_force_max"), node.number("approach_max")};
}

ImpactPrediction read_prediction(const Reader& node) {
  const double damping = node.number("damping"); // read first: the first missing key is named
  return {read_quantities(node), damping};
}

std::vector<double> read_matrix(const Reader& node, std::size_t k) {
  std::vector<double> values;
  if (node.size() != k) node.fail("", "is not " + std::to_string(k) + " x " + std::to_string(k));
  for (std::size_t i = 0; i < k; ++i) {
    const Reader row = node.at(i);
    if (row.size() != k) row.fail("", "does not hold " + std::to_string(k) + " numbers");
    for (std::size_t j = 0; j < k; ++j) values.push_back(row.at(j).number());
  }
  return values;
}

ModelFit read_fit(const Reader& node) {
  ModelFit fit;
  fit.model = node.text("model");
  const std::vector<std::string> names = node.texts("parameter_order");
  if (names.size() < 3 || names[0] != "c" || names[1] != "n")
    node.at("parameter_order").fail("", "does not start with c, n and a dissipation parameter");
  const Reader parameters = node.at("parameters");
  fit.stiffness = read_estimate(parameters.at("c"));
  fit.exponent = read_estimate(parameters.at("n"));
  fit.exponent_fixed = parameters.at("n").flag("fixed");
  fit.parameter_name = names[2];
  fit.parameter_unit = parameters.at(names[2]).text("unit");
  fit.parameter = read_estimate(parameters.at(names[2]));
  fit.parameter_fixed = parameters.at(names[2]).flag("fixed");
  for (std::size_t i = 3; i < names.size(); ++i)
    fit.extra.push_back({names[i], parameters.at(names[i]).text("unit"),
                         read_estimate(parameters.at(names[i]))});
  const std::size_t k = names.size();
  fit.covariance = read_matrix(node.at("covariance").at("matrix"), k);
  fit.correlation.assign(k * k, nan);
  for (std::size_t i = 0; i < k; ++i) {
    fit.correlation[i * k + i] = 1;
    for (std::size_t j = i + 1; j < k; ++j) {
      const std::string pair = names[i] + "," + names[j];
      const double value = node.at("correlation").number(pair);
      fit.correlation[i * k + j] = fit.correlation[j * k + i] = value;
    }
  }
  fit.reference_approach = node.at("reference_approach").number("value");
  fit.force_at_reference = read_estimate(node.at("force_at_reference_approach"));
  fit.quality = read_quality(node);
  fit.converged = node.flag("converged");
  fit.iterations = int(node.number("iterations"));
  fit.solver_message = node.text("solver_message");
  return fit;
}

std::vector<double> read_values(const Reader& node, const std::vector<std::string>& names) {
  std::vector<double> values;
  for (const auto& name : names) values.push_back(node.number(name));
  return values;
}

CampaignModelFit read_campaign_fit(const Reader& node) {
  CampaignModelFit fit;
  fit.fit = read_fit(node);
  fit.key = node.text("key");
  fit.label = node.text("label");
  fit.formula = node.text("formula");
  fit.reference = node.text("reference");
  fit.damping_name = node.at("damping").text("name");
  fit.damping_unit = node.at("damping").text("unit");
  fit.energy_weight = node.number("energy_weight");
  const Reader runs = node.at("runs");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Reader run = runs.at(i);
    RunResidual residual{run.text("source"), run.number("impact_velocity"), read_quality(run),
                         read_prediction(run.at("prediction")), std::nullopt};
    if (run.has("out_of_sample")) residual.out_of_sample = read_prediction(run.at("out_of_sample"));
    fit.runs.push_back(residual);
  }
  const auto names = fit.fit.parameter_names();
  const Reader held_out = node.at("held_out");
  for (std::size_t i = 0; i < held_out.size(); ++i) {
    const Reader entry = held_out.at(i);
    fit.held_out.push_back({entry.number("velocity"), read_values(entry.at("parameters"), names),
                            entry.flag("converged")});
  }
  if (node.has("jackknife"))
    for (const auto& name : names) fit.jackknife.push_back(read_estimate(node.at("jackknife").at(name)));
  return fit;
}

ReferenceModel read_reference(const Reader& node) {
  ReferenceModel reference;
  reference.key = node.text("key");
  reference.label = node.text("label");
  reference.model = node.text("model");
  reference.basis = node.text("basis");
  const Reader parameters = node.at("parameters");
  reference.stiffness = parameters.number("c");
  reference.exponent = parameters.number("n");
  reference.parameter_name = node.at("parameter").text("name");
  reference.parameter_unit = node.at("parameter").text("unit");
  if (parameters.has(reference.parameter_name))
    reference.dissipation = {parameters.number(reference.parameter_name)};
  const Reader runs = node.at("runs");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Reader run = runs.at(i);
    const ImpactPrediction prediction = read_prediction(run.at("prediction"));
    reference.runs.push_back({run.text("source"), run.number("impact_velocity"),
                              read_quality(run), prediction, prediction});
  }
  return reference;
}

std::optional<CampaignModelFit> read_optional_fit(const Reader& campaign, const std::string& key) {
  if (!campaign.has(key)) return std::nullopt;
  return read_campaign_fit(campaign.at(key));
}

// The recommendation for a multibody code.
json multibody_json(const Calibration& calibration) {
  json multibody = nullptr;
  std::string basis;
  if (const ModelFit* recommended = recommended_hunt_crossley(calibration, &basis))
    multibody = {{"model", std::string(model_keys::hunt_crossley)},
                 {"force_law", "F = c x^n (1 + b dx/dt) for approach x > 0, else F = 0"},
                 {"c", number(recommended->stiffness.value)},
                 {"n", number(recommended->exponent.value)},
                 {"b", number(recommended->parameter.value)},
                 {"units", {{"c", "N/m^n"}, {"n", "1"}, {"b", "s/m"}}},
                 {"basis", basis},
                 {"converged", recommended->converged}};

  return multibody;
}

// b(V): one line more in a multibody code, and what the campaign shows the FEM needs.
json velocity_damping_json(const CampaignCalibration& campaign) {
  json velocity_damping = nullptr;
  if (const auto& fit = campaign.hunt_crossley_velocity_damping)
    velocity_damping = {
        {"model", std::string(model_keys::hunt_crossley_velocity_damping)},
        {"force_law", "F = c x^n (1 + b dx/dt) for approach x > 0, else F = 0, with "
                      "b = b_1 (V_0 / 1 m/s)^(-q), V_0 the approach speed at first contact"},
        {"c", number(fit->fit.stiffness.value)},
        {"n", number(fit->fit.exponent.value)},
        {"b_1", number(fit->fit.parameter.value)},
        {"q", number(fit->fit.extra.empty() ? nan : fit->fit.extra.front().estimate.value)},
        {"units", {{"c", "N/m^n"}, {"n", "1"}, {"b_1", "s/m"}, {"q", "1"}}},
        {"basis", "campaign fit of " + fit->label},
        {"converged", fit->fit.converged}};

  return velocity_damping;
}

json restitution_maps_json(const CampaignCalibration& campaign) {
  json maps = json::array();
  for (const auto& map : campaign.restitution_maps) {
    json map_runs = json::array();
    for (const auto& run : map.runs)
      map_runs.push_back({{"source", run.source},
                          {"impact_velocity", number(run.velocity)},
                          {"target_restitution", number(run.target)},
                          {"prediction", prediction_json(run.prediction)}});
    maps.push_back({{"law", map.law}, {"formula", map.formula}, {"runs", map_runs}});
  }
  return maps;
}

json units_json() {
  return {{"c", "N/m^n"},
        {"n", "1"},
        {"b", "s/m"},
        {"b_1", "s/m (b at V = 1 m/s)"},
        {"q", "1"},
        {"A", "s"},
        {"e", "1"},
        {"impact_velocity", "m/s"},
        {"mass", "kg"},
        {"restitution", "1"},
        {"contact_time", "s"},
        {"force_max", "N"},
        {"time_force_max", "s (from first contact)"},
        {"approach_max", "m"},
        {"rms_residual", "1 (RMS of (F_model - F_FEM) / peak FEM force of the run)"},
        {"r_squared", "1"},
        {"score", "1 (RMS of the relative errors of 1 - e^2, t_c, F_max, x_max over the runs)"}};
}

json campaign_json(const CampaignCalibration& campaign) {
  const auto optional_fit = [](const std::optional<CampaignModelFit>& fit) {
    return fit ? campaign_fit_json(*fit) : json(nullptr);
  };
  json laws = json::array();
  for (const auto& law : campaign.comparison_laws) laws.push_back(campaign_fit_json(law));
  json references = json::array();
  for (const auto& reference : campaign.reference_models) references.push_back(reference_json(reference));
  return {{"fitted", campaign.fitted},
          {"reason", campaign.reason.empty() ? json(nullptr) : json(campaign.reason)},
        {"velocities", campaign.velocities},
        {"energy_weight", campaign.energy_weight},
        {"published_damping", number(campaign.published_damping)},
        {"hertz_stiffness", {{"value", number(campaign.hertz_stiffness)}, {"unit", "N/m^1.5"},
                             {"basis", campaign.hertz_basis}}},
        {"material_dissipative_constant",
         {{"value", campaign.material_dissipative_constant
                        ? number(*campaign.material_dissipative_constant)
                        : json(nullptr)},
          {"unit", "s"},
          {"basis", campaign.material_basis}}},
        {"hunt_crossley", optional_fit(campaign.hunt_crossley)},
        {"hunt_crossley_energy", optional_fit(campaign.hunt_crossley_energy)},
        {"hunt_crossley_hertz_exponent", optional_fit(campaign.hunt_crossley_hertz_exponent)},
        {"hunt_crossley_velocity_damping", optional_fit(campaign.hunt_crossley_velocity_damping)},
        {"comparison_laws", laws},
        {"reference_models", references},
        {"restitution_maps", restitution_maps_json(campaign)},
        {"ranking", ranking_json(campaign)}};
}

} // namespace

json to_json(const Calibration& calibration) {
  json problems = json::array();
  for (const auto& problem : calibration.problems)
    problems.push_back({{"source", problem.source},
                        {"kind", std::string(kind_name(problem.kind))},
                        {"message", problem.message}});
  json runs = json::array();
  for (const auto& run : calibration.runs) runs.push_back(run_json(run));
  return {{"format", "impact-calibration"},
          {"format_version", calibration_format_version},
          {"generated_by", "impact-calibrate"},
          {"status", calibration.problems.empty() ? "complete" : "incomplete"},
          {"problems", problems},
          {"confidence_level", calibration.confidence_level},
          {"units", units_json()},
          {"multibody", multibody_json(calibration)},
          {"multibody_velocity_damping", velocity_damping_json(calibration.campaign)},
          {"runs", runs},
          {"campaign", campaign_json(calibration.campaign)}};
}

Calibration calibration_from_json(const json& document) {
  const Reader root(document, "top level");
  if (!document.is_object() || root.text_or("format", "") != "impact-calibration")
    throw CalibrationFormatError("it is not a calibration of impact-calibrate (no \"format\": "
                                 "\"impact-calibration\")");
  const double version = root.number("format_version");
  if (version != calibration_format_version)
    throw CalibrationFormatError(
        "its format_version is " + std::to_string(int(version)) + ", this impact-report reads " +
        std::to_string(calibration_format_version) + ": run impact-calibrate again");
  Calibration calibration;
  calibration.confidence_level = root.number("confidence_level");
  const Reader problems = root.at("problems");
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const Reader problem = problems.at(i);
    const std::string kind = problem.text("kind");
    const auto known = kind_from_name(kind);
    if (!known)
      throw CalibrationFormatError("problems[" + std::to_string(i) + "].kind is '" + kind +
                                   "', not one of input, no rebound, quality, convergence, "
                                   "figures");
    calibration.problems.push_back({problem.text("source"), *known, problem.text("message")});
  }
  const Reader runs = root.at("runs");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Reader run = runs.at(i);
    RunCalibration entry;
    entry.source = run.text("source");
    entry.velocity = run.number("impact_velocity");
    entry.mass = run.number("mass");
    entry.measured = read_quantities(run.at("measured"));
    entry.damping_from_restitution = run.at("restitution_fit").at("b").number("value");
    entry.impact_parameter = run.at("restitution_fit").number("beta");
    if (run.has("loading_fit")) entry.loading = read_fit(run.at("loading_fit"));
    if (run.has("history_fit")) entry.history = read_fit(run.at("history_fit"));
    if (run.has("history_prediction"))
      entry.history_prediction = read_prediction(run.at("history_prediction"));
    calibration.runs.push_back(entry);
  }
  const Reader node = root.at("campaign");
  CampaignCalibration& campaign = calibration.campaign;
  campaign.fitted = node.flag("fitted");
  campaign.reason = node.text_or("reason", "");
  const Reader velocities = node.at("velocities");
  for (std::size_t i = 0; i < velocities.size(); ++i)
    campaign.velocities.push_back(velocities.at(i).number());
  campaign.energy_weight = node.number("energy_weight");
  campaign.published_damping = node.number("published_damping");
  campaign.hertz_stiffness = node.at("hertz_stiffness").number("value");
  campaign.hertz_basis = node.at("hertz_stiffness").text("basis");
  const double material = node.at("material_dissipative_constant").number("value");
  if (std::isfinite(material)) campaign.material_dissipative_constant = material;
  campaign.material_basis = node.at("material_dissipative_constant").text("basis");
  campaign.hunt_crossley = read_optional_fit(node, "hunt_crossley");
  campaign.hunt_crossley_energy = read_optional_fit(node, "hunt_crossley_energy");
  campaign.hunt_crossley_hertz_exponent = read_optional_fit(node, "hunt_crossley_hertz_exponent");
  campaign.hunt_crossley_velocity_damping =
      read_optional_fit(node, "hunt_crossley_velocity_damping");
  const Reader laws = node.at("comparison_laws");
  for (std::size_t i = 0; i < laws.size(); ++i)
    campaign.comparison_laws.push_back(read_campaign_fit(laws.at(i)));
  const Reader references = node.at("reference_models");
  for (std::size_t i = 0; i < references.size(); ++i)
    campaign.reference_models.push_back(read_reference(references.at(i)));
  const Reader maps = node.at("restitution_maps");
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const Reader map = maps.at(i);
    RestitutionMapEvaluation evaluation{map.text("law"), map.text("formula"), {}};
    const Reader map_runs = map.at("runs");
    for (std::size_t j = 0; j < map_runs.size(); ++j) {
      const Reader run = map_runs.at(j);
      evaluation.runs.push_back({run.text("source"), run.number("impact_velocity"),
                                 run.number("target_restitution"),
                                 read_prediction(run.at("prediction"))});
    }
    campaign.restitution_maps.push_back(evaluation);
  }
  const Reader ranking = node.at("ranking");
  for (std::size_t i = 0; i < ranking.size(); ++i) {
    const Reader entry = ranking.at(i);
    campaign.ranking.push_back({entry.text("model"), entry.count("free_parameters"),
                                entry.number("score"), entry.flag("out_of_sample"),
                                entry.number("worst_error"), entry.number("in_sample_score"),
                                entry.number("rms_residual"), entry.flag("converged"),
                                entry.texts("family")});
  }
  return calibration;
}

const ModelFit* recommended_hunt_crossley(const Calibration& calibration, std::string* basis) {
  const CampaignCalibration& campaign = calibration.campaign;
  if (campaign.hunt_crossley) {
    // The constant-b fit with the better rank (out of sample where there is a ranking).
    for (const auto& entry : campaign.ranking)
      if (entry.key == model_keys::hunt_crossley ||
          (entry.key == model_keys::hunt_crossley_energy && campaign.hunt_crossley_energy)) {
        const CampaignModelFit* fit = campaign.find(entry.key);
        if (basis)
          *basis = "campaign fit of hunt-crossley to all runs (" + fit->label +
                   "), the better ranked of the constant-b fits";
        return &fit->fit;
      }
    if (basis) *basis = "campaign fit of hunt-crossley to all runs (force histories)";
    return &campaign.hunt_crossley->fit;
  }
  if (calibration.runs.size() == 1 && calibration.runs.front().history) {
    if (basis) *basis = "force-history fit of the single run " + calibration.runs.front().source;
    return &*calibration.runs.front().history;
  }
  return nullptr;
}

} // namespace impact::postprocess
