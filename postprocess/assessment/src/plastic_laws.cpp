// The elastic-plastic laws against an elastic-plastic FEM campaign (plastic_laws.hpp, PlasticLaws):
// Thornton (1997) and Jackson–Green (2005) from the scenario's material with nothing fitted,
// and their campaign fits when the calibration holds them; their restitution and permanent
// approach over the tested range and at the runs, and their loops at the runs; and the
// restitution fit of Jackson, Green & Marghitu (2010) from the material (e only; its constants
// as read in one implementation, unconfirmed: README, "Elastic-plastic impact laws").

#include "steps.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/jackson_green_marghitu.hpp>
#include <impact_reduced/contact_formulas.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace impact::postprocess::detail {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t grid_points = 80;
constexpr std::size_t loop_points = 80; // per branch

double median_mass(const std::vector<ReportRun>& runs) {
  std::vector<double> masses;
  for (const auto& run : runs) masses.push_back(run.mass);
  std::nth_element(masses.begin(), masses.begin() + std::ptrdiff_t(masses.size() / 2),
                   masses.end());
  return masses[masses.size() / 2];
}

// A law at one impact: e, its permanent approach and, when asked, its loop.
struct LawAt {
  double restitution = nan;
  double permanent_approach = nan;
  ImpactHistory loop;
};
using LawEvaluator = std::function<LawAt(double mass, double velocity, bool with_loop)>;

void add_loop(LawAt& at, const std::vector<reduced::ImpactSample>& samples) {
  for (const auto& sample : samples) {
    at.loop.time.push_back(sample.time);
    at.loop.approach.push_back(sample.approach);
    at.loop.force.push_back(sample.force);
  }
}

// A rate-independent law: its contact for c and the yield parameter p.
LawEvaluator rate_independent(const ContactModel& model, double stiffness, double parameter) {
  return [model, stiffness, parameter](double mass, double velocity, bool with_loop) {
    const auto contact =
        model.plastic_contact(parameter, reduced::ContactSetup{mass, stiffness, 1.5});
    const auto response = reduced::elastic_plastic_impact(mass, velocity, *contact);
    LawAt at{response.restitution, response.residual_approach, {}};
    if (with_loop)
      add_loop(at, reduced::elastic_plastic_impact_loop(mass, velocity, *contact, loop_points));
    return at;
  };
}

// A damped elastic-plastic law (damped_plastic_models.hpp) for c and its dissipation
// parameters; its loop has as many samples as a rate-independent law's two branches.
LawEvaluator damped(const ContactModel& model, double stiffness, std::vector<double> dissipation) {
  return [model, stiffness, dissipation](double mass, double velocity, bool with_loop) {
    const auto impact = damped_plastic_impact(model, mass, velocity, stiffness, dissipation);
    LawAt at{impact->restitution(), impact->separation_approach(), {}};
    if (with_loop) add_loop(at, impact->history(2 * loop_points));
    return at;
  };
}

// One law over the grid and at the runs.
PlasticLawCurve curve_of(std::string key, std::string label, bool fitted, double stiffness,
                         std::vector<ModelParameter> parameters, const LawEvaluator& law,
                         const std::vector<double>& grid, double mass,
                         const std::vector<ReportRun>& runs) {
  PlasticLawCurve curve{std::move(key),
                        std::move(label),
                        fitted,
                        stiffness,
                        std::move(parameters),
                        0,
                        {},
                        {},
                        {},
                        {},
                        {},
                        {}};
  for (double v : grid) {
    curve.velocity.push_back(v);
    LawAt at;
    try {
      at = law(mass, v, false);
    } catch (const std::exception&) {
      at = {};
    }
    curve.restitution.push_back(at.restitution);
    curve.permanent_approach.push_back(at.permanent_approach);
  }
  for (const auto& run : runs) {
    LawAt at;
    try {
      at = law(run.mass, run.velocity, true);
    } catch (const std::exception&) {
      at = {};
    }
    curve.run_restitution.push_back(at.restitution);
    curve.run_permanent_approach.push_back(at.permanent_approach);
    curve.loops.push_back(std::move(at.loop));
  }
  return curve;
}

// A model's values after c: its names, values and units as the calibration gives them.
std::vector<ModelParameter> parameters_of(const std::vector<std::string>& names,
                                          const std::vector<std::string>& units,
                                          const std::vector<double>& values) {
  std::vector<ModelParameter> parameters;
  for (std::size_t i = 0; i < names.size() && i < values.size() && i < units.size(); ++i)
    parameters.push_back({names[i], values[i], units[i]});
  return parameters;
}

// The damped elastic-plastic laws of the calibration: from the material (its reference
// models) and fitted (its campaign fits that converged), with the calibration's numbers.
void add_damped_laws(PlasticLaws& laws, const Calibration& calibration,
                     const std::vector<FemRun>& fem_runs, const std::vector<double>& grid,
                     double mass, const std::vector<ReportRun>& runs) {
  const CampaignCalibration& campaign = calibration.campaign;
  for (const auto& [key, label] :
       {std::pair{model_keys::hunt_crossley_thornton_material,
                  "Hunt–Crossley on Thornton (from the material, no fit)"},
        std::pair{model_keys::hunt_crossley_jackson_green_material,
                  "Hunt–Crossley on Jackson–Green (from the material, no fit)"},
        std::pair{model_keys::kuwabara_kono_thornton_material,
                  "Kuwabara–Kono on Thornton (from the material, no fit)"},
        std::pair{model_keys::kuwabara_kono_jackson_green_material,
                  "Kuwabara–Kono on Jackson–Green (from the material, no fit)"}})
    for (const auto& reference : campaign.reference_models)
      if (reference.key == key) try {
          std::vector<std::string> names{reference.parameter_name}, units{reference.parameter_unit};
          names.insert(names.end(), reference.extra_names.begin(), reference.extra_names.end());
          units.insert(units.end(), reference.extra_units.begin(), reference.extra_units.end());
          PlasticLawCurve curve = curve_of(reference.key, label, false, reference.stiffness,
                                           parameters_of(names, units, reference.dissipation),
                                           damped(comparison_model(reference.model, fem_runs),
                                                  reference.stiffness, reference.dissipation),
                                           grid, mass, runs);
          curve.damped = true;
          laws.laws.push_back(std::move(curve));
        } catch (const std::exception&) {
          // the model cannot be built for these runs: left out of the curves
        }
  for (const auto& [key, label] :
       {std::pair{model_keys::hunt_crossley_thornton, "Hunt–Crossley on Thornton (fitted)"},
        std::pair{model_keys::hunt_crossley_jackson_green,
                  "Hunt–Crossley on Jackson–Green (fitted)"},
        std::pair{model_keys::hunt_crossley_thornton_from_a,
                  "Hunt–Crossley on Thornton, b ∝ V^-4/5 (fitted)"},
        std::pair{model_keys::hunt_crossley_jackson_green_from_a,
                  "Hunt–Crossley on Jackson–Green, b ∝ V^-4/5 (fitted)"},
        std::pair{model_keys::kuwabara_kono_thornton, "Kuwabara–Kono on Thornton (fitted)"},
        std::pair{model_keys::kuwabara_kono_jackson_green,
                  "Kuwabara–Kono on Jackson–Green (fitted)"}})
    if (const CampaignModelFit* fit = campaign.find(std::string(key)))
      if (fit->fit.converged) try {
          const ModelFit& parameters = fit->fit;
          std::vector<std::string> names{parameters.parameter_name},
              units{parameters.parameter_unit};
          for (const auto& extra : parameters.extra) {
            names.push_back(extra.name);
            units.push_back(extra.unit);
          }
          PlasticLawCurve curve =
              curve_of(std::string(key), label, true, parameters.stiffness.value,
                       parameters_of(names, units, parameters.dissipation()),
                       damped(comparison_model(std::string(key), fem_runs),
                              parameters.stiffness.value, parameters.dissipation()),
                       grid, mass, runs);
          curve.free_parameters = parameters.free_parameters();
          curve.damped = true;
          laws.laws.push_back(std::move(curve));
        } catch (const std::exception&) {
          // the model cannot be built for these runs: left out of the curves
        }
}

// Jackson, Green & Marghitu's restitution fit for the scenario's contact, over the grid and
// at the runs (NaN where the fit gives e <= 0, far above its range). No force history: the
// permanent approach and the loops stay empty.
PlasticLawCurve jackson_green_marghitu_curve(const reduced::SphereFlatContact& contact,
                                             const std::vector<double>& grid, double mass,
                                             const std::vector<ReportRun>& runs) {
  const auto restitution = [&](double velocity, double m) {
    try {
      return reduced::jackson_green_marghitu_restitution(velocity, contact, m);
    } catch (const reduced::InvalidInput&) {
      return nan;
    }
  };
  PlasticLawCurve curve{std::string(model_keys::jackson_green_marghitu_material),
                        "Jackson–Green–Marghitu (e only, no fit)",
                        false,
                        nan,
                        {{"V_c", reduced::jackson_green_marghitu_critical_velocity(contact, mass),
                          "m/s"},
                         {"eps_y", reduced::jackson_green_marghitu_yield_strain(contact), "1"}},
                        0,
                        {},
                        {},
                        {},
                        {},
                        {},
                        {}};
  for (double v : grid) {
    curve.velocity.push_back(v);
    curve.restitution.push_back(restitution(v, mass));
  }
  for (const auto& run : runs) curve.run_restitution.push_back(restitution(run.velocity, run.mass));
  return curve;
}

// The grid of the curves: from half of V_y (or below the slowest run) to above the fastest
// run, geometric.
std::vector<double> velocity_grid(const std::vector<ReportRun>& runs, double yield_velocity) {
  double low = 0.5 * yield_velocity, high = 2 * yield_velocity;
  for (const auto& run : runs) {
    low = std::min(low, 0.8 * run.velocity);
    high = std::max(high, 1.25 * run.velocity);
  }
  std::vector<double> grid;
  for (std::size_t i = 0; i < grid_points; ++i)
    grid.push_back(low * std::pow(high / low, double(i) / double(grid_points - 1)));
  return grid;
}

} // namespace

std::optional<PlasticLaws> plastic_laws(const std::vector<FemRun>& fem_runs,
                                        const std::vector<ReportRun>& runs,
                                        const std::optional<Calibration>& calibration) {
  const bool plastic = std::any_of(runs.begin(), runs.end(), [](const ReportRun& run) {
    return run.record.plastic_material;
  });
  if (!plastic || runs.empty()) return std::nullopt;
  const auto thornton = material_thornton(fem_runs);
  const auto jackson_green = material_jackson_green(fem_runs);
  const auto scenario = sphere_flat_scenario(fem_runs);
  if (!thornton || !scenario || !scenario->contact_modulus || !scenario->yield_strength)
    return std::nullopt;
  const double mass = median_mass(runs);
  PlasticLaws laws;
  laws.yield_velocity =
      thornton_yield_velocity(thornton->yield_approach, mass, thornton->stiffness);
  laws.jackson_green_yield_velocity =
      reduced::yield_velocity(reduced::yield_pressure(reduced::YieldCriterion::jackson_green,
                                                      *scenario->yield_strength,
                                                      scenario->poisson_ratio),
                              *scenario->contact_modulus, scenario->radius, mass);
  laws.mass = mass;
  laws.yield_strength = *scenario->yield_strength;
  laws.material_basis = scenario->basis;
  laws.hardening_left_out = impact::postprocess::hardening_left_out(fem_runs.front());
  const auto grid = velocity_grid(runs, laws.yield_velocity);

  laws.laws.push_back(curve_of(std::string(model_keys::thornton_material),
                               "Thornton (p_y = 1.6 Y, no fit)", false, thornton->stiffness,
                               {{"x_y", thornton->yield_approach, "m"}},
                               rate_independent(plastic_model(std::string(model_keys::thornton)),
                                                thornton->stiffness, thornton->yield_approach),
                               grid, mass, runs));
  if (jackson_green)
    laws.laws.push_back(curve_of(std::string(model_keys::jackson_green_material),
                                 "Jackson–Green (Y of the material, no fit)", false,
                                 jackson_green->stiffness, {{"Y", *scenario->yield_strength, "Pa"}},
                                 rate_independent(jackson_green->model, jackson_green->stiffness,
                                                  jackson_green->yield_strength),
                                 grid, mass, runs));
  laws.laws.push_back(
      jackson_green_marghitu_curve({scenario->radius, *scenario->contact_modulus,
                                    *scenario->yield_strength, scenario->poisson_ratio},
                                   grid, mass, runs));
  if (calibration)
    for (const auto& [key, label] :
         {std::pair{model_keys::thornton, "Thornton (fitted)"},
          std::pair{model_keys::jackson_green, "Jackson–Green (fitted)"}})
      if (const CampaignModelFit* fit = calibration->campaign.find(std::string(key)))
        if (fit->fit.converged) try {
            const ModelFit& parameters = fit->fit;
            PlasticLawCurve curve =
                curve_of(std::string(key), label, true, parameters.stiffness.value,
                         {{parameters.parameter_name, parameters.parameter.value,
                           parameters.parameter_unit}},
                         rate_independent(comparison_model(std::string(key), fem_runs),
                                          parameters.stiffness.value, parameters.parameter.value),
                         grid, mass, runs);
            curve.free_parameters = parameters.free_parameters();
            laws.laws.push_back(std::move(curve));
          } catch (const std::exception&) {
            // the model cannot be built for these runs: left out of the curves
          }
  if (calibration) add_damped_laws(laws, *calibration, fem_runs, grid, mass, runs);
  for (const auto& run : runs)
    laws.fem_permanent_approach.push_back(run.record.permanent_approach.value_or(nan));
  return laws;
}

} // namespace impact::postprocess::detail
