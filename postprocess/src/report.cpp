// The numbers of the model-validity report (report.hpp): FEM quantities and histories,
// the predictions of the four reduced models, the errors, the energy and yield checks and
// the validity verdict.

#include "impact_postprocess/report.hpp"

#include "impact_postprocess/contact_models.hpp"
#include "impact_postprocess/fem_run_format.hpp"
#include "report_json.hpp"

#include <impact_reduced/hertz_stiffness.hpp>
#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace impact::postprocess {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double published_damping = 0.1;            // s/m, the published example
constexpr double published_hertz_stiffness = 1.7135e10; // N/m^1.5, steel ball on steel
constexpr std::size_t model_history_points = 300;
constexpr std::size_t fem_history_samples = 1500;
// impact-fem's parameter of the sphere radius (a text attribute of the run file).
constexpr const char* sphere_radius_parameter = "Scenario/Sphere radius";

using detail::member;
using detail::number;

std::string format(double value, int digits = 4) {
  if (!std::isfinite(value)) return "n/a";
  std::ostringstream text;
  text.precision(digits);
  text << value;
  return text.str();
}

std::string percent(double fraction, int digits = 3) {
  if (!std::isfinite(fraction)) return "n/a";
  std::ostringstream text;
  text.precision(digits);
  text << (fraction >= 0 ? "+" : "") << fraction * 100 << " %";
  return text.str();
}

bool same_source(const std::string& a, const std::string& b) {
  if (a == b) return true;
  std::error_code error;
  const fs::path pa = fs::weakly_canonical(a, error);
  if (error) return false;
  const fs::path pb = fs::weakly_canonical(b, error);
  return !error && pa == pb;
}

bool same_velocity(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }

// The entry of a JSON list of runs that belongs to (source, velocity): same file, else the
// only entry at the same velocity.
const json* find_run_entry(const json& list, const std::string& source, double velocity) {
  if (!list.is_array()) return nullptr;
  for (const auto& entry : list)
    if (member(entry, "source").is_string() &&
        same_source(member(entry, "source").get<std::string>(), source))
      return &entry;
  const json* found = nullptr;
  for (const auto& entry : list)
    if (same_velocity(number(member(entry, "impact_velocity")), velocity)) {
      if (found) return nullptr; // ambiguous
      found = &entry;
    }
  return found;
}

std::optional<QuantityValues> prediction_values(const json& prediction) {
  if (!prediction.is_object()) return std::nullopt;
  QuantityValues values;
  for (std::size_t q = 0; q < impact_quantity_count; ++q)
    values[q] = number(member(prediction, quantity_key(q)));
  if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
    return std::nullopt;
  return values;
}

ReportEstimate estimate(const json& parameter) {
  const json& interval = member(parameter, "interval");
  return {number(member(parameter, "value")),
          interval.is_array() && interval.size() == 2 ? number(interval[0]) : nan,
          interval.is_array() && interval.size() == 2 ? number(interval[1]) : nan};
}

// ---- What a run records besides its histories -----------------------------------------

fs::path summary_of(const fs::path& file) {
  if (file.filename() == fem_format::history_file)
    return file.parent_path() / fem_format::summary_file;
  return file.parent_path() / (file.stem().string() + ".summary.json");
}

std::string lower_case(std::string text) {
  for (auto& character : text) character = char(std::tolower((unsigned char)character));
  return text;
}

RunRecord read_record(const FemRun& run) {
  json summary = json::object();
  try {
    std::ifstream in(summary_of(run.source));
    if (in) summary = json::parse(in);
  } catch (const json::exception&) {
    summary = json::object(); // the reader has already accepted or rejected it
  }
  const auto value = [&](const std::string& key) -> std::optional<double> {
    const double from_summary = number(member(summary, key));
    if (std::isfinite(from_summary)) return from_summary;
    const auto attribute = run.numeric_attributes.find(fem_format::result_attribute_prefix + key);
    if (attribute != run.numeric_attributes.end() && std::isfinite(attribute->second))
      return attribute->second;
    return std::nullopt;
  };
  RunRecord record;
  record.energy_error = value(fem_format::energy_error_key);
  record.lost_energy_fraction = value("lost_energy_fraction");
  record.dissipated_energy_fraction = value("dissipated_energy_fraction");
  record.radiated_energy_fraction = value("radiated_energy_fraction");
  record.max_von_mises = value("max_von_mises");

  // A yield strength, wherever the run records one (the FEM materials are elastic or
  // viscoelastic; a scenario may carry it as a parameter or a result).
  const auto consider = [&](const std::string& key, double strength) {
    if (lower_case(key).find("yield") == std::string::npos) return;
    if (!(std::isfinite(strength) && strength > 0)) return;
    if (!record.yield_strength || strength < *record.yield_strength) {
      record.yield_strength = strength;
      record.yield_source = key;
    }
  };
  if (summary.is_object())
    for (const auto& [key, entry] : summary.items()) consider(key, number(entry));
  for (const auto& [key, entry] : run.numeric_attributes) consider(key, entry);
  for (const auto& [key, entry] : run.text_attributes) {
    try {
      std::size_t end = 0;
      const double strength = std::stod(entry, &end);
      if (end == entry.size()) consider(key, strength);
    } catch (const std::exception&) {
    }
  }
  return record;
}

ImpactHistory fem_window(const FemRun& run) {
  ImpactHistory window;
  const double t0 = run.first_contact_time, tc = run.contact_time;
  std::vector<std::size_t> inside;
  for (std::size_t i = 0; i < run.time.size(); ++i) {
    const double t = run.time[i] - t0;
    if (t >= -0.05 * tc && t <= 1.25 * tc) inside.push_back(i);
  }
  const std::size_t stride = std::max<std::size_t>(1, (inside.size() + fem_history_samples - 1) /
                                                          fem_history_samples);
  for (std::size_t k = 0; k < inside.size(); k += stride) {
    const std::size_t i = inside[k];
    window.time.push_back(run.time[i] - t0);
    window.approach.push_back(run.approach[i]);
    window.force.push_back(run.contact_force[i]);
  }
  return window;
}

// ---- Hertz stiffness of the scenario ----------------------------------------------------

std::optional<double> text_number(const FemRun& run, const std::string& key) {
  const auto found = run.text_attributes.find(key);
  if (found == run.text_attributes.end()) return std::nullopt;
  try {
    std::size_t end = 0;
    const double value = std::stod(found->second, &end);
    if (end == found->second.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// The material constants of "Sphere" or "Plate" as impact-fem stores its parameters:
// "<Body>/Material model" = name, constants in "<Body>/<Name>/Young's modulus", ...
std::optional<reduced::ElasticBody> elastic_body(const FemRun& run, const std::string& body) {
  const auto model = run.text_attributes.find(body + "/Material model");
  if (model == run.text_attributes.end() || model->second.empty()) return std::nullopt;
  std::string section = model->second;
  section[0] = char(std::toupper((unsigned char)section[0]));
  const auto young = text_number(run, body + "/" + section + "/Young's modulus");
  const auto poisson = text_number(run, body + "/" + section + "/Poisson's ratio");
  if (!young || !poisson) return std::nullopt;
  return reduced::ElasticBody{*young, *poisson};
}

std::pair<double, std::string> scenario_hertz_stiffness(const std::vector<FemRun>& runs) {
  for (const auto& run : runs) {
    auto sphere = elastic_body(run, "Sphere");
    const auto plate = elastic_body(run, "Plate");
    const auto radius = text_number(run, sphere_radius_parameter);
    if (!sphere || !plate || !radius) continue;
    sphere->radius = *radius;
    try {
      const double c = reduced::hertz_stiffness(*sphere, *plate);
      return {c, "Hertz value of the scenario's materials (sphere E = " +
                     format(sphere->youngs_modulus) + " Pa, nu = " +
                     format(sphere->poisson_ratio) + ", R = " + format(*radius) +
                     " m; plate E = " + format(plate->youngs_modulus) +
                     " Pa, nu = " + format(plate->poisson_ratio) + ") read from " + run.source};
    } catch (const std::exception&) {
    }
  }
  return {published_hertz_stiffness,
          "the runs do not record the scenario's materials, so the published steel value "
          "1.7135e10 N/m^1.5 (0.1 kg steel ball on steel) is used"};
}

// ---- Models ---------------------------------------------------------------------------

ImpactHistory hunt_crossley_history(const reduced::HuntCrossleyImpact& impact) {
  ImpactHistory history;
  for (const auto& state : impact.history(model_history_points)) {
    history.time.push_back(state.time);
    history.approach.push_back(state.approach);
    history.force.push_back(state.force);
  }
  return history;
}

// A Hunt–Crossley model evaluated by the reduced library at every run.
ReportModel closed_form_model(const std::vector<ReportRun>& runs, std::string key,
                              std::string label, double c, double n, double b,
                              std::string basis) {
  ReportModel model{std::move(key), std::move(label),
                    "c = " + format(c, 5) + " N/m^" + format(n) + ", n = " + format(n, 5) +
                        ", b = " + format(b, 4) + " s/m",
                    std::move(basis), true, {}};
  for (const auto& run : runs) {
    ModelAtRun at;
    try {
      const reduced::HuntCrossleyImpact impact(run.mass, c, n, b, run.velocity);
      const auto response = impact.response();
      at.values = QuantityValues{response.restitution, response.contact_time, response.force_max,
                                 response.approach_max};
      at.history = hunt_crossley_history(impact);
    } catch (const std::exception& error) {
      at.missing = error.what();
    }
    model.runs.push_back(std::move(at));
  }
  return model;
}

// A fit of the calibration JSON: values from its per-run predictions, curves recomputed.
ReportModel fitted_model(const std::vector<ReportRun>& runs, const json& fit, std::string key,
                         std::string label, std::string basis) {
  const json& parameters = member(fit, "parameters");
  const std::string name = member(fit, "model").is_string() ? fit["model"].get<std::string>()
                                                            : "hunt-crossley";
  const double c = number(member(member(parameters, "c"), "value"));
  const double n = number(member(member(parameters, "n"), "value"));
  std::string parameter_name = "b", unit = "s/m";
  double p = nan;
  for (const auto& [symbol, entry] : parameters.items())
    if (symbol != "c" && symbol != "n") {
      parameter_name = symbol;
      p = number(member(entry, "value"));
      if (member(entry, "unit").is_string()) unit = entry["unit"].get<std::string>();
    }
  ReportModel model{std::move(key), std::move(label),
                    "c = " + format(c, 5) + " N/m^n, n = " + format(n, 5) + ", " +
                        parameter_name + " = " + format(p, 5) + " " + unit,
                    std::move(basis), member(fit, "converged") == true, {}};
  std::optional<ContactModel> law;
  try {
    law = name == "hunt-crossley" ? hunt_crossley_model() : comparison_model(name);
  } catch (const std::exception&) {
  }
  for (const auto& run : runs) {
    ModelAtRun at;
    const json* entry = find_run_entry(member(fit, "runs"), run.source, run.velocity);
    if (!entry) {
      at.missing = "the calibration has no prediction of " + name + " for this run";
      model.runs.push_back(std::move(at));
      continue;
    }
    const json& prediction = member(*entry, "prediction");
    at.values = prediction_values(prediction);
    if (!at.values) at.missing = "the calibration's prediction of " + name + " is incomplete";
    try {
      if (!law) throw std::runtime_error("unknown model " + name);
      const double damping = number(member(prediction, "damping"));
      const auto force = law->force_law(damping, {run.mass, c, n});
      for (const auto& sample : reduced::integrate_impact_history(run.mass, run.velocity, force,
                                                                  model_history_points)) {
        at.history.time.push_back(sample.time);
        at.history.approach.push_back(sample.approach);
        at.history.force.push_back(sample.force);
      }
    } catch (const std::exception& error) {
      at.history = {};
      if (at.missing.empty()) at.missing = std::string("no history: ") + error.what();
    }
    model.runs.push_back(std::move(at));
  }
  return model;
}

// Each run's own force-history fit, for a calibration without a campaign fit.
ReportModel per_run_model(const std::vector<ReportRun>& runs, const json& calibration,
                          const std::string& reason) {
  ReportModel model{"calibrated", "Hunt–Crossley (per-run fit)",
                    "c, n, b of each run's force-history fit (table of runs)",
                    "no campaign fit (" + reason + "): each run is compared with its own "
                    "force-history fit, which says nothing about other velocities",
                    true, {}};
  for (const auto& run : runs) {
    ModelAtRun at;
    const json* entry = find_run_entry(member(calibration, "runs"), run.source, run.velocity);
    const json& fit = entry ? member(*entry, "history_fit") : json();
    if (!entry || !fit.is_object()) {
      at.missing = "the calibration has no force-history fit of this run";
      model.runs.push_back(std::move(at));
      continue;
    }
    if (member(fit, "converged") != true) model.converged = false;
    at.values = prediction_values(member(*entry, "history_prediction"));
    if (!at.values) at.missing = "the calibration has no prediction of this run's fit";
    try {
      const json& p = member(fit, "parameters");
      const reduced::HuntCrossleyImpact impact(
          run.mass, number(member(member(p, "c"), "value")),
          number(member(member(p, "n"), "value")), number(member(member(p, "b"), "value")),
          run.velocity);
      at.history = hunt_crossley_history(impact);
    } catch (const std::exception& error) {
      if (at.missing.empty()) at.missing = std::string("no history: ") + error.what();
    }
    model.runs.push_back(std::move(at));
  }
  return model;
}

ReportModel missing_model(const std::vector<ReportRun>& runs, std::string key, std::string label,
                          const std::string& why) {
  ReportModel model{std::move(key), std::move(label), "n/a", why, true, {}};
  for (std::size_t i = 0; i < runs.size(); ++i) model.runs.push_back({std::nullopt, {}, why});
  return model;
}

// ---- Verdict --------------------------------------------------------------------------

constexpr std::array<std::size_t, 3> verdict_quantities = {0, 1, 2};
const std::array<const char*, impact_quantity_count> quantity_words = {
    "restitution", "contact time", "peak force", "peak approach"};

double relative_error(double model, double fem) { return (model - fem) / std::abs(fem); }

std::string velocity_list(const std::vector<double>& velocities) {
  std::string text;
  for (std::size_t i = 0; i < velocities.size(); ++i)
    text += (i == 0 ? "" : i + 1 == velocities.size() ? " and " : ", ") + format(velocities[i]);
  return text + " m/s";
}

void add_verdict(Report& report) {
  const ReportModel& model = report.models.front();
  const std::size_t count = report.runs.size();
  if (!report.campaign_fitted) {
    report.cause = "No verdict: " +
                   (report.campaign_reason.empty() ? std::string("the campaign was not fitted")
                                                   : report.campaign_reason) +
                   ". A validity range needs the campaign fit over at least two velocities.";
    return;
  }
  if (!model.converged) {
    report.cause = "No verdict: the campaign fit of Hunt–Crossley did not converge, so its "
                   "predictions (shown, marked 'not converged') cannot decide where the model "
                   "holds. Rerun the calibration with more iterations or check the runs.";
    return;
  }
  // errors[i][q] for the three verdict quantities.
  std::vector<std::array<double, impact_quantity_count>> errors(count);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t q = 0; q < impact_quantity_count; ++q)
      errors[i][q] = model.runs[i].values
                         ? relative_error((*model.runs[i].values)[q], report.runs[i].fem[q])
                         : nan;
  report.verdict_available = true;
  for (double tolerance : {0.02, 0.05}) {
    ToleranceVerdict verdict{tolerance, {}, std::nullopt, {}};
    for (std::size_t i = 0; i < count; ++i) {
      int pass = 1;
      for (std::size_t q : verdict_quantities) {
        if (!std::isfinite(errors[i][q])) pass = -1;
        else if (pass == 1 && std::abs(errors[i][q]) > tolerance) pass = 0;
      }
      verdict.passes.push_back(pass);
    }
    // The widest contiguous stretch of passing velocities.
    std::size_t best_begin = 0, best_length = 0;
    for (std::size_t i = 0; i < count;) {
      if (verdict.passes[i] != 1) { ++i; continue; }
      std::size_t j = i;
      while (j < count && verdict.passes[j] == 1) ++j;
      if (j - i > best_length) { best_begin = i; best_length = j - i; }
      i = j;
    }
    const std::string band = format(tolerance * 100) + " %";
    std::vector<double> failing, unknown;
    for (std::size_t i = 0; i < count; ++i) {
      if (verdict.passes[i] == 0) failing.push_back(report.runs[i].velocity);
      if (verdict.passes[i] == -1) unknown.push_back(report.runs[i].velocity);
    }
    std::string text;
    if (best_length == 0) {
      text = "Within " + band + ": at no tested velocity.";
    } else {
      const double low = report.runs[best_begin].velocity;
      const double high = report.runs[best_begin + best_length - 1].velocity;
      verdict.range = std::array<double, 2>{low, high};
      text = "Within " + band + ": " +
             (best_length == count ? "over the whole tested range, " : "") + "V = " +
             format(low) + " to " + format(high) + " m/s (" + std::to_string(best_length) +
             " of " + std::to_string(count) + " tested velocities).";
      if (!failing.empty())
        text += " Outside " + band + " at V = " + velocity_list(failing) +
                "; the limits lie between the last tested velocity inside and the first outside.";
    }
    if (!unknown.empty())
      text += " Not decided at V = " + velocity_list(unknown) + " (prediction missing).";
    verdict.text = text;
    report.verdicts.push_back(std::move(verdict));
  }

  // The cause: which quantity leaves the bands first, and the trend of the per-run b.
  std::ostringstream cause;
  double worst = 0;
  std::size_t worst_run = 0, worst_quantity = 0;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t q : verdict_quantities)
      if (std::isfinite(errors[i][q]) && std::abs(errors[i][q]) > worst) {
        worst = std::abs(errors[i][q]);
        worst_run = i;
        worst_quantity = q;
      }
  if (worst <= 0.02) {
    cause << "The calibrated Hunt–Crossley model holds within 2 % at every tested velocity; the "
             "largest error is " << percent(errors[worst_run][worst_quantity]) << " ("
          << quantity_words[worst_quantity] << " at V = " << format(report.runs[worst_run].velocity)
          << " m/s).";
  } else {
    // The quantity with the fewest velocities inside the 2 % band breaks first.
    std::size_t first = verdict_quantities[0];
    int fewest = int(count) + 1;
    double first_worst = 0;
    for (std::size_t q : verdict_quantities) {
      int inside = 0;
      double largest = 0;
      for (std::size_t i = 0; i < count; ++i)
        if (std::isfinite(errors[i][q])) {
          if (std::abs(errors[i][q]) <= 0.02) ++inside;
          largest = std::max(largest, std::abs(errors[i][q]));
        }
      if (inside < fewest || (inside == fewest && largest > first_worst)) {
        first = q;
        fewest = inside;
        first_worst = largest;
      }
    }
    cause << "The " << quantity_words[first] << " breaks first: it is within 2 % at "
          << fewest << " of " << count << " velocities, with errors";
    for (std::size_t i = 0; i < count; ++i)
      cause << (i ? "," : "") << " " << percent(errors[i][first]) << " at "
            << format(report.runs[i].velocity) << " m/s";
    cause << ". The largest error of all is " << percent(errors[worst_run][worst_quantity])
          << " (" << quantity_words[worst_quantity] << " at V = "
          << format(report.runs[worst_run].velocity) << " m/s).";
    const bool low_end = worst_run == 0, high_end = worst_run + 1 == count;
    if (low_end || high_end)
      cause << " The errors grow towards the " << (low_end ? "lowest" : "highest")
            << " tested velocity.";
  }
  report.cause = cause.str();
}

// How the per-run b (from the restitution) varies with V: least-squares line.
std::string damping_trend(const std::vector<ReportRun>& runs) {
  std::vector<double> v, b;
  for (const auto& run : runs)
    if (std::isfinite(run.damping_from_restitution)) {
      v.push_back(run.velocity);
      b.push_back(run.damping_from_restitution);
    }
  if (v.size() < 2) return "";
  const double n = double(v.size());
  double mv = 0, mb = 0;
  for (std::size_t i = 0; i < v.size(); ++i) { mv += v[i] / n; mb += b[i] / n; }
  double svv = 0, svb = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    svv += (v[i] - mv) * (v[i] - mv);
    svb += (v[i] - mv) * (b[i] - mb);
  }
  if (!(svv > 0) || !(mb > 0)) return "";
  const double slope = svb / svv;
  const double change = slope * (v.back() - v.front()) / mb;
  const auto [low, high] = std::minmax_element(b.begin(), b.end());
  std::ostringstream text;
  text << "Per-run b from the restitution: " << format(b.front()) << " s/m at "
       << format(v.front()) << " m/s to " << format(b.back()) << " s/m at " << format(v.back())
       << " m/s (range " << format(*low) << " to " << format(*high)
       << " s/m); the least-squares line changes by " << percent(change)
       << " of the mean over the tested range. ";
  if (std::abs(change) <= 0.02 && (*high - *low) <= 0.04 * mb)
    text << "b is constant within 2 %: the dissipation has the velocity dependence of "
            "Hunt–Crossley (constant b).";
  else
    text << "b " << (change > 0 ? "rises" : "falls")
         << " with V: one constant b cannot give the FEM restitution at every velocity, so the "
            "FEM dissipation is not of Hunt–Crossley's form over this range"
         << (change > 0 ? "" : " (a falling b means e decreases more slowly with V than "
                               "Hunt–Crossley predicts)")
         << ".";
  return text.str();
}

} // namespace

const char* quantity_key(std::size_t quantity) {
  static const std::array<const char*, impact_quantity_count> keys = {
      "restitution", "contact_time", "force_max", "approach_max"};
  return keys.at(quantity);
}

Report build_report(const Campaign& campaign, const json& calibration,
                    std::vector<ReportProblem> problems, const std::string& campaign_source,
                    const std::string& calibration_source) {
  Report report;
  report.campaign_source = campaign_source;
  report.calibration_source = calibration_source;
  report.calibration = calibration;
  for (const auto& problem : campaign.problems)
    problems.push_back({problem.source, "input", problem.message});
  if (campaign.runs.empty())
    problems.push_back({campaign_source, "input", "no usable run: the report has no FEM data"});

  // Runs, with the calibration's measured numbers where it holds the run.
  for (const FemRun& fem : campaign.runs) {
    ReportRun run;
    run.source = fem.source;
    run.velocity = fem.impact_velocity;
    run.mass = fem.mass;
    run.fem = {fem.restitution, fem.contact_time, fem.force_max, fem.approach_max};
    run.fem_history = fem_window(fem);
    run.damping_from_restitution = nan;
    run.history_damping = run.history_stiffness = run.history_exponent = {nan, nan, nan};
    run.record = read_record(fem);
    if (const json* entry = find_run_entry(member(calibration, "runs"), fem.source,
                                           fem.impact_velocity)) {
      run.calibrated = true;
      if (const auto measured = prediction_values(member(*entry, "measured"))) run.fem = *measured;
      run.damping_from_restitution =
          number(member(member(member(*entry, "restitution_fit"), "b"), "value"));
      const json& parameters = member(member(*entry, "history_fit"), "parameters");
      run.history_damping = estimate(member(parameters, "b"));
      run.history_stiffness = estimate(member(parameters, "c"));
      run.history_exponent = estimate(member(parameters, "n"));
    } else if (!calibration.is_null()) {
      problems.push_back({fem.source, "input",
                          "the run is not in the calibration " + calibration_source +
                              ": only its FEM data are shown"});
    }
    report.runs.push_back(std::move(run));
  }

  // The calibration's own problems (input and convergence), kept as they are.
  if (calibration.is_object())
    for (const auto& problem : member(calibration, "problems")) {
      ReportProblem entry{member(problem, "source").is_string() ? problem["source"].get<std::string>() : "",
                          member(problem, "kind").is_string() ? problem["kind"].get<std::string>() : "input",
                          member(problem, "message").is_string() ? problem["message"].get<std::string>() : problem.dump()};
      const bool known = std::any_of(problems.begin(), problems.end(), [&](const ReportProblem& p) {
        return p.message == entry.message;
      });
      if (!known) problems.push_back(entry);
    }

  const auto [hertz, hertz_basis] = scenario_hertz_stiffness(campaign.runs);
  report.hertz_stiffness = hertz;
  report.hertz_basis = hertz_basis;

  // The four models.
  const json& campaign_json = member(calibration, "campaign");
  report.campaign_fitted = member(campaign_json, "fitted") == true &&
                           member(campaign_json, "hunt_crossley").is_object();
  report.campaign_reason = member(campaign_json, "reason").is_string()
                               ? campaign_json["reason"].get<std::string>()
                               : (calibration.is_null() ? "there is no calibration" : "");
  if (calibration.is_null())
    report.models.push_back(missing_model(report.runs, "calibrated", "Hunt–Crossley (calibrated)",
                                          "no calibration"));
  else if (report.campaign_fitted)
    report.models.push_back(fitted_model(report.runs, campaign_json["hunt_crossley"], "calibrated",
                                         "Hunt–Crossley (calibrated)",
                                         "campaign fit of the calibration: one (c, n, b) for all runs"));
  else
    report.models.push_back(per_run_model(report.runs, calibration,
                                          report.campaign_reason.empty()
                                              ? std::string("the campaign was not fitted")
                                              : report.campaign_reason));
  report.models.push_back(closed_form_model(report.runs, "published",
                                            "Hunt–Crossley (b = 0.1 s/m)", hertz, 1.5,
                                            published_damping,
                                            "the published example: b = 0.1 s/m, n = 3/2, c = " +
                                                hertz_basis));
  report.models.push_back(closed_form_model(report.runs, "hertz", "Hertz (b = 0)", hertz, 1.5, 0,
                                            "elastic Hertz impact, same c and n, no damping"));
  const json* best = nullptr;
  for (const auto& entry : member(campaign_json, "ranking"))
    if (member(entry, "model").is_string() && entry["model"] != "hunt-crossley") {
      for (const auto& law : member(campaign_json, "comparison_laws"))
        if (member(law, "model") == entry["model"]) best = &law;
      if (best) break;
    }
  if (best)
    report.models.push_back(fitted_model(report.runs, *best, "best-law",
                                         (*best)["model"].get<std::string>() + " (best law)",
                                         "the comparison law with the smallest RMS residual of "
                                         "the calibration's ranking, fitted to all runs"));
  else
    report.models.push_back(missing_model(report.runs, "best-law", "best comparison law",
                                          "the calibration has no fitted comparison law"));
  for (const auto& model : report.models)
    if (!model.converged)
      problems.push_back({model.label, "convergence",
                          "the fit of " + model.label +
                              " did not converge: its numbers are shown marked 'not converged'"});

  // Offsets from Hertz of the calibrated elastic part: n from the free fit, c from the fit
  // with n held at 3/2 (the free fit's c is in N/m^n, not comparable with c_Hertz), and the
  // trend of b.
  const json& hc = member(campaign_json, "hunt_crossley");
  if (hc.is_object()) {
    const auto parameter = [](const json& fit, const char* name) {
      return number(member(member(member(fit, "parameters"), name), "value"));
    };
    const auto not_converged = [](const json& fit) {
      return member(fit, "converged") == false ? std::string(" (not converged)") : std::string();
    };
    const double c = parameter(hc, "c");
    const double n = parameter(hc, "n");
    const json& fixed = member(campaign_json, "hunt_crossley_hertz_exponent");
    std::string note = "Offsets of the calibrated elastic part from Hertz (c_Hertz = " +
                       format(hertz, 5) + " N/m^1.5): n - 3/2 = " +
                       (n >= 1.5 ? "+" : "") + format(n - 1.5, 3) +
                       " (free fit of c, n, b: n = " + format(n, 6) + not_converged(hc) + ")";
    if (fixed.is_object()) {
      const double c_fixed = parameter(fixed, "c");
      note += "; c / c_Hertz - 1 = " + percent(c_fixed / hertz - 1) +
              " (fit with n fixed at 3/2, c and b free: c = " + format(c_fixed, 6) +
              " N/m^1.5" + not_converged(fixed) +
              "); for information, the free fit's c / c_Hertz - 1 = " + percent(c / hertz - 1) +
              " (c = " + format(c, 6) +
              " N/m^n at the fitted n: its unit depends on n, so it is not comparable with "
              "c_Hertz).";
    } else {
      note += "; the free fit's c / c_Hertz - 1 = " + percent(c / hertz - 1) + " (c = " +
              format(c, 6) +
              " N/m^n: its unit depends on n, so this offset means most when n is close to 3/2; "
              "the calibration has no fit with n fixed at 3/2).";
    }
    report.parameter_notes.push_back(note);
  }
  const std::string trend = damping_trend(report.runs);
  if (!trend.empty()) report.parameter_notes.push_back(trend);

  // Without a campaign fit there is no verdict: that is missing input (e.g. a single run or
  // velocity given explicitly, which impact-calibrate itself accepts as a per-run job).
  if (!report.runs.empty() && !report.campaign_fitted && !calibration.is_null()) {
    const std::string reason = report.campaign_reason.empty()
                                   ? std::string("the calibration has no campaign fit")
                                   : report.campaign_reason;
    const bool said = std::any_of(problems.begin(), problems.end(), [&](const ReportProblem& p) {
      return p.message.find(reason) != std::string::npos;
    });
    if (!said)
      problems.push_back({calibration_source, "input",
                          "no validity verdict: " + reason});
  }

  report.problems = std::move(problems);
  add_verdict(report);
  if (!trend.empty() && report.verdict_available) report.cause += " " + trend;
  if (report.verdict_available) {
    const json& ranking = member(campaign_json, "ranking");
    if (ranking.is_array() && !ranking.empty() && ranking[0]["model"] != "hunt-crossley")
      report.cause += " The comparison law " + ranking[0]["model"].get<std::string>() +
                      " fits the force histories better than Hunt–Crossley (RMS residual " +
                      format(number(ranking[0]["rms_residual"]) * 100, 3) + " % of the peak force).";
  }
  return report;
}

} // namespace impact::postprocess
