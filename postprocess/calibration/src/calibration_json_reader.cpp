// The typed reader of the calibration JSON (calibration_json.hpp, calibration_from_json): the
// layout that calibration_json.cpp writes, every key checked and named when it is missing.

#include "impact_postprocess/calibration/calibration_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact::postprocess {

namespace {

using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

class Reader {
public:
  Reader(const json& node, std::string path) : node_(node), path_(std::move(path)) {}

  Reader at(const std::string& key) const {
    if (!node_.is_object() || !node_.contains(key)) fail(key, "is missing");
    return {node_[key], path_ + "." + key};
  }
  Reader at(std::size_t index) const {
    return {node_.at(index), path_ + "[" + std::to_string(index) + "]"};
  }
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
  fit.stiffness_fixed = parameters.at("c").flag("fixed");
  fit.exponent = read_estimate(parameters.at("n"));
  fit.exponent_fixed = parameters.at("n").flag("fixed");
  fit.parameter_name = names[2];
  fit.parameter_unit = parameters.at(names[2]).text("unit");
  fit.parameter = read_estimate(parameters.at(names[2]));
  fit.parameter_fixed = parameters.at(names[2]).flag("fixed");
  for (std::size_t i = 3; i < names.size(); ++i)
    fit.extra.push_back(
        {names[i], parameters.at(names[i]).text("unit"), read_estimate(parameters.at(names[i]))});
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
    for (const auto& name : names)
      fit.jackknife.push_back(read_estimate(node.at("jackknife").at(name)));
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
  // Further dissipation parameters (a damped elastic-plastic model's A); absent before them.
  if (node.has("extra_parameters")) {
    const Reader extra = node.at("extra_parameters");
    for (std::size_t i = 0; i < extra.size(); ++i) {
      const std::string name = extra.at(i).text("name");
      reference.extra_names.push_back(name);
      reference.extra_units.push_back(extra.at(i).text("unit"));
      reference.dissipation.push_back(parameters.number(name));
    }
  }
  const Reader runs = node.at("runs");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Reader run = runs.at(i);
    const ImpactPrediction prediction = read_prediction(run.at("prediction"));
    reference.runs.push_back({run.text("source"), run.number("impact_velocity"), read_quality(run),
                              prediction, prediction});
  }
  return reference;
}

std::optional<CampaignModelFit> read_optional_fit(const Reader& campaign, const std::string& key) {
  if (!campaign.has(key)) return std::nullopt;
  return read_campaign_fit(campaign.at(key));
}

// The recommendation for a multibody code.

} // namespace

Calibration calibration_from_json(const json& document) {
  const Reader root(document, "top level");
  if (!document.is_object() || root.text_or("format", "") != "impact-calibration")
    throw CalibrationFormatError(
        "it is not a calibration of impact-calibrate (no \"format\": "
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
    campaign.ranking.push_back(
        {entry.text("model"), entry.count("free_parameters"), entry.number("score"),
         entry.flag("out_of_sample"), entry.number("worst_error"), entry.number("in_sample_score"),
         entry.number("rms_residual"), entry.flag("converged"), entry.texts("family")});
  }
  return calibration;
}

} // namespace impact::postprocess
