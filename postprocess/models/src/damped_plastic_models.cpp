// The damped elastic-plastic comparison models (damped_plastic_models.hpp).

#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/jackson_green_model.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/models/plastic_models.hpp"
#include "impact_postprocess/models/simulated_force.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/hertz_contact.hpp>
#include <impact_reduced/hunt_crossley.hpp>
#include <impact_reduced/hunt_crossley_elastic_plastic.hpp>
#include <impact_reduced/invalid_input.hpp>
#include <impact_reduced/kuwabara_kono_elastic_plastic.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>

namespace impact::postprocess {

namespace {

// b(V) of the "-from-a" models, in words.
const std::string matched_damping_formula =
    "b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5), gamma_1 = 1.730173, V the speed at first "
    "contact";

// ---- Hunt–Crossley damping: the reduced library's closed form ------------------------------

class HuntCrossleyPlasticImpact final : public DampedPlasticImpact {
public:
  HuntCrossleyPlasticImpact(double mass,
                            std::shared_ptr<const reduced::ElasticPlasticContact> spring,
                            double damping, double velocity)
      : impact_(mass, std::move(spring), damping, velocity) {}

  reduced::ImpactFigures figures() const override { return impact_.response().figures(); }
  double restitution() const override { return impact_.restitution(); }
  double separation_approach() const override { return impact_.separation_approach(); }
  // The closed-form history on the Hertz spring (HuntCrossleyImpact's power law). On another
  // spring the library inverts its time quadratures instant by instant, which takes about
  // 60 ms per instant on Thornton's (measured, two busy cores: 78 s for 1200 instants), far
  // too slow for a fit; so the compression is integrated (integrate_impact_history at
  // detail::compression_tolerance: 1e-10, as the comparison laws, on a continuous spring;
  // 1e-13 on the Jackson–Green spring, whose jump at 1.9 omega_c makes the residuals at 1e-10
  // scatter with the parameters, measured there) under F_L(x) (1 + b x') up to its maximum
  // approach, and the restitution is the closed-form power-law history of the Hunt–Crossley
  // impact on the unloading branch k_u (x - x_r)^(3/2) that reaches the same x_max (the
  // library's own construction of that phase, hunt_crossley_elastic_plastic.hpp). About
  // `points` samples, equally spaced in time within each phase.
  std::vector<reduced::ImpactSample> history(std::size_t points) const override {
    std::vector<reduced::ImpactSample> samples;
    if (dynamic_cast<const reduced::HertzContact*>(&impact_.spring())) {
      for (const auto& state : impact_.history(points))
        samples.push_back({state.time, state.approach, state.approach_rate, state.force});
      return samples;
    }
    const double mass = impact_.mass(), velocity = impact_.velocity(), b = impact_.damping();
    const reduced::ElasticPlasticContact& spring = impact_.spring();
    const reduced::ContactForceLaw loading = [&spring, b](double x, double rate) {
      return spring.loading_force(std::max(x, 0.0)) * (1 + b * rate);
    };
    const reduced::HertzianUnloading branch = impact_.unloading();
    if (!(branch.stiffness > 0)) // elastic: the whole impact on the loading branch
      return reduced::integrate_impact_history(mass, velocity, loading, points,
                                               detail::compression_tolerance(spring, tolerance));
    // The compression's samples (rate > 0) and its end, where the rate crosses 0 between two
    // samples: linear in the rate there (error ~ h^2 b F / (8 m) in time, 1e-7 of t_c for the
    // FEM's sampling), one integration instead of a second one for the event.
    const auto loaded =
        reduced::integrate_impact_history(mass, velocity, loading, points,
                                          detail::compression_tolerance(spring, tolerance));
    double compression = loaded.back().time;
    for (std::size_t k = 0; k < loaded.size(); ++k) {
      if (loaded[k].approach_rate > 0) {
        samples.push_back(loaded[k]);
        continue;
      }
      const auto& before = loaded[k - 1]; // k > 0: the first sample is at the impact velocity
      compression = before.time + (loaded[k].time - before.time) * before.approach_rate /
                                      (before.approach_rate - loaded[k].approach_rate);
      break;
    }
    const double top = impact_.approach_max();
    samples.push_back({compression, top, 0.0, spring.loading_force(top)});
    // The unloading branch's impact: its V_U stores (2/5) k_u (x_max - x_r)^(5/2) at x_max.
    const double work = 0.4 * branch.stiffness * std::pow(top - branch.residual_approach, 2.5);
    const reduced::HuntCrossleyImpact unloading(mass, branch.stiffness, 1.5, b,
                                                branch_velocity(mass, b, work));
    const double shift = compression - unloading.compression_time();
    for (const auto& state : unloading.history(points)) {
      if (!(state.time > unloading.compression_time())) continue;
      const double approach = state.approach + branch.residual_approach;
      if (approach < 0) break; // x_r < 0: the surfaces part at x = 0 (appended below)
      samples.push_back({state.time + shift, approach, state.approach_rate, state.force});
    }
    if (branch.residual_approach < 0) {
      const double rate = impact_.rebound_velocity();
      samples.push_back({shift + unloading.time_at_approach(-branch.residual_approach,
                                                            reduced::ImpactPhase::restitution),
                         0.0, rate, impact_.force(0.0, rate, reduced::ImpactPhase::restitution)});
    }
    return samples;
  }
  double force(double approach, double approach_rate) const override {
    return impact_.force(std::max(approach, 0.0), approach_rate,
                         approach_rate > 0 ? reduced::ImpactPhase::compression
                                           : reduced::ImpactPhase::restitution);
  }

private:
  // The impact velocity V_U of the Hunt–Crossley impact (mass m, damping b) whose compression
  // stores `work` at its maximum approach: b V - ln(1 + b V) = b^2 W / m (Newton in beta =
  // b V, from below, monotone after the first step).
  static double branch_velocity(double mass, double b, double work) {
    const double elastic = std::sqrt(2 * work / mass);
    if (!(b > 0)) return elastic;
    const double target = b * b * work / mass;
    double beta = b * elastic;
    for (int i = 0; i < 100; ++i) {
      const double step = (beta - std::log1p(beta) - target) * (1 + beta) / beta;
      beta -= step;
      if (std::abs(step) <= 1e-15 * beta) break;
    }
    return beta / b;
  }

  static constexpr double tolerance = 1e-10;
  reduced::HuntCrossleyElasticPlasticImpact impact_;
};

// ---- Kuwabara–Kono damping: the reduced library's integration -----------------------------

class KuwabaraKonoPlasticImpact final : public DampedPlasticImpact {
public:
  KuwabaraKonoPlasticImpact(double mass,
                            std::shared_ptr<const reduced::ElasticPlasticContact> spring,
                            double dissipative_constant, double velocity)
      : spring_(std::move(spring)),
        mass_(mass),
        velocity_(velocity),
        a_(dissipative_constant),
        result_(reduced::kuwabara_kono_elastic_plastic_impact(mass, velocity, *spring_, a_)) {}

  reduced::ImpactFigures figures() const override { return result_.figures(); }
  double restitution() const override { return result_.restitution; }
  double separation_approach() const override { return result_.approach_at_separation; }
  // The library's samples, each re-stepped from the start of its step (no interpolation).
  std::vector<reduced::ImpactSample> history(std::size_t points) const override {
    return reduced::kuwabara_kono_elastic_plastic_history(mass_, velocity_, *spring_, a_, points);
  }
  // The branch of this impact's x_max once the approach falls; no tension (the contact ends
  // where the force returns to 0, so an interpolated state just past it carries none).
  double force(double approach, double approach_rate) const override {
    return std::max(0.0, reduced::kuwabara_kono_elastic_plastic_force(
                             *spring_, a_, std::max(approach, 0.0), approach_rate,
                             approach_rate > 0 ? 0.0 : result_.approach_max));
  }

private:
  std::shared_ptr<const reduced::ElasticPlasticContact> spring_;
  double mass_, velocity_, a_;
  reduced::OdeImpactResult result_;
};

std::optional<double> material_dissipative_constant(const std::vector<FemRun>& runs,
                                                    std::string& basis) {
  const ScenarioMaterials materials = scenario_materials(runs);
  basis = materials.dissipative_basis;
  if (!materials.dissipative_constant || !(*materials.dissipative_constant > 0))
    return std::nullopt;
  return materials.dissipative_constant;
}

std::string damping_basis(double dissipative_constant, const std::string& source, double stiffness,
                          const std::vector<FemRun>& runs) {
  std::string text = "A = " + significant(dissipative_constant, 6) + " s from " + source + "; " +
                     matched_damping_formula +
                     ": Hunt-Crossley's small-loss restitution 1 - e = (2/3) b V (Hunt & "
                     "Crossley 1975) set equal to Kuwabara-Kono's 1 - e = gamma_1 A (c/m)^(2/5) "
                     "V^(1/5) (Schwager & Pöschel 1998) on the Hertz spring";
  if (!runs.empty() && runs.front().mass > 0)
    text += " (b = " +
            significant(matched_hunt_crossley_damping(dissipative_constant, 1.0,
                                                      {runs.front().mass, stiffness, 1.5}),
                        6) +
            " s/m at V = 1 m/s for m = " + significant(runs.front().mass, 6) + " kg)";
  return text;
}

} // namespace

const std::vector<std::string>& damped_plastic_model_names() {
  static const std::vector<std::string> names = {
      std::string(model_keys::hunt_crossley_thornton),
      std::string(model_keys::hunt_crossley_jackson_green),
      std::string(model_keys::hunt_crossley_thornton_from_a),
      std::string(model_keys::hunt_crossley_jackson_green_from_a),
      std::string(model_keys::kuwabara_kono_thornton),
      std::string(model_keys::kuwabara_kono_jackson_green)};
  return names;
}

bool is_damped_plastic_model(const std::string& name) {
  const auto& names = damped_plastic_model_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

DampedPlasticDamping damped_plastic_damping(const std::string& name) {
  if (!is_damped_plastic_model(name))
    throw reduced::InvalidInput("model", name + " is not a damped elastic-plastic model");
  if (name == model_keys::kuwabara_kono_thornton || name == model_keys::kuwabara_kono_jackson_green)
    return DampedPlasticDamping::kuwabara_kono;
  if (name == model_keys::hunt_crossley_thornton_from_a ||
      name == model_keys::hunt_crossley_jackson_green_from_a)
    return DampedPlasticDamping::hunt_crossley_of_velocity;
  return DampedPlasticDamping::hunt_crossley;
}

bool damped_plastic_needs_scenario(const std::string& name) {
  return name == model_keys::hunt_crossley_jackson_green ||
         name == model_keys::hunt_crossley_jackson_green_from_a ||
         name == model_keys::kuwabara_kono_jackson_green;
}

ContactModel damped_plastic_model(const std::string& name, const ContactModel& spring) {
  if (!is_damped_plastic_model(name))
    throw reduced::InvalidInput("model",
                                "model must be one of the damped elastic-plastic models "
                                "(hunt-crossley-thornton, hunt-crossley-jackson-green, "
                                "hunt-crossley-thornton-from-a, "
                                "hunt-crossley-jackson-green-from-a, kuwabara-kono-thornton, "
                                "kuwabara-kono-jackson-green), got '" +
                                    name + "'");
  if (!spring.plastic_contact || spring.damped_plastic())
    throw reduced::InvalidInput("spring", "the spring of " + name +
                                              " must be a rate-independent plastic model, got '" +
                                              spring.name + "'");
  ContactModel model = spring;
  model.name = name;
  if (damped_plastic_damping(name) == DampedPlasticDamping::kuwabara_kono) {
    model.spring_damping = SpringDamping::kuwabara_kono;
    model.formula =
        "F = F_s(x) + A k_t(x) x', k_t = dF_s/dx of the current branch, F_s the "
        "spring (" +
        spring.name + "): " + spring.formula;
    model.reference =
        "Kuwabara and Kono, Jpn. J. Appl. Phys. 26 (1987) 1230; Brilliantov et "
        "al., Phys. Rev. E 53 (1996) 5382 (damping), on " +
        spring.reference;
    // A of metals: retardation times of 1e-8 to 1e-4 s (as the "-from-a" models).
    model.extra_parameters = {{"A", "s", 1e-6, 0.0, 1e-2, 1e-6}};
    model.spring_damping_constant = [](const std::vector<double>& p, double,
                                       const reduced::ContactSetup&) { return p.at(1); };
    return model;
  }
  model.spring_damping = SpringDamping::hunt_crossley;
  const bool matched =
      damped_plastic_damping(name) == DampedPlasticDamping::hunt_crossley_of_velocity;
  model.formula = (matched ? "F = F_s(x) (1 + b(V) x'), " + matched_damping_formula
                           : std::string("F = F_s(x) (1 + b x'), b constant")) +
                  ", F_s the spring (" + spring.name + "): " + spring.formula;
  model.reference = "Hunt and Crossley, J. Appl. Mech. 42 (1975) 440-445 (damping), on " +
                    spring.reference +
                    (matched ? "; b(V) matched to Kuwabara-Kono's restitution (Schwager and "
                               "Pöschel, Phys. Rev. E 57 (1998) 650)"
                             : "");
  if (matched) {
    // A of metals: retardation times of 1e-8 to 1e-4 s.
    model.extra_parameters = {{"A", "s", 1e-6, 0.0, 1e-2, 1e-6}};
    model.spring_damping_constant = [](const std::vector<double>& p, double velocity,
                                       const reduced::ContactSetup& setup) {
      return matched_hunt_crossley_damping(p.at(1), velocity, setup);
    };
  } else {
    // b of the published steel example 0.1 s/m; up to 10 s/m (beta = b V = 50 at 5 m/s).
    model.extra_parameters = {{"b", "s/m", 0.0, 0.0, 10.0, 0.1}};
    model.spring_damping_constant = [](const std::vector<double>& p, double,
                                       const reduced::ContactSetup&) { return p.at(1); };
  }
  return model;
}

ContactModel damped_plastic_model(const std::string& name) {
  if (damped_plastic_needs_scenario(name))
    throw reduced::InvalidInput("model", "the model " + name +
                                             " needs the scenario's sphere "
                                             "radius and Poisson ratio: build it from the runs "
                                             "(comparison_model(name, runs))");
  return damped_plastic_model(name, plastic_model(std::string(model_keys::thornton)));
}

double matched_hunt_crossley_damping(double dissipative_constant, double velocity,
                                     const reduced::ContactSetup& setup) {
  reduced::require_non_negative("dissipative_constant", dissipative_constant);
  reduced::require_positive("velocity", velocity);
  reduced::require_positive("mass", setup.mass);
  reduced::require_positive("stiffness", setup.stiffness);
  return 1.5 * reduced::brilliantov_gamma1() * dissipative_constant *
         std::pow(setup.stiffness / setup.mass, 0.4) * std::pow(velocity, -0.8);
}

std::unique_ptr<const DampedPlasticImpact> damped_plastic_impact(
    const ContactModel& model, double mass, double velocity, double stiffness,
    const std::vector<double>& dissipation) {
  const reduced::ContactSetup setup{mass, stiffness, model.required_exponent.value_or(1.5)};
  const double yield_parameter = model.damping(dissipation, velocity, setup);
  const double damping = model.spring_damping_constant(dissipation, velocity, setup);
  switch (model.spring_damping) {
    case SpringDamping::hunt_crossley:
      return std::make_unique<HuntCrossleyPlasticImpact>(
          mass, model.plastic_contact(yield_parameter, setup), damping, velocity);
    case SpringDamping::kuwabara_kono:
      return std::make_unique<KuwabaraKonoPlasticImpact>(
          mass, model.plastic_contact(yield_parameter, setup), damping, velocity);
    case SpringDamping::none:
      break;
  }
  throw reduced::InvalidInput("model",
                              "the model " + model.name + " is not a damped elastic-plastic model");
}

namespace {

// The damped law `model_name` on a spring from the material (Thornton's or Jackson–Green's)
// with A of the materials; none without either.
std::optional<MaterialDampedPlastic> material_damped(const std::vector<FemRun>& runs,
                                                     std::string_view key, std::string label,
                                                     std::string_view model_name) {
  const bool thornton = !damped_plastic_needs_scenario(std::string(model_name));
  std::optional<double> stiffness, yield_parameter;
  std::string spring_basis;
  ContactModel model;
  if (thornton) {
    const auto material = material_thornton(runs);
    if (!material) return std::nullopt;
    stiffness = material->stiffness;
    yield_parameter = material->yield_approach;
    spring_basis = material->basis;
    model = damped_plastic_model(std::string(model_name));
  } else {
    const auto material = material_jackson_green(runs);
    if (!material) return std::nullopt;
    stiffness = material->stiffness;
    yield_parameter = material->yield_strength;
    spring_basis = material->basis;
    model = damped_plastic_model(std::string(model_name), material->model);
  }
  std::string source;
  const auto a = material_dissipative_constant(runs, source);
  if (!a) return std::nullopt;
  const std::string damping = model.spring_damping == SpringDamping::kuwabara_kono
                                  ? "A = " + significant(*a, 6) + " s from " + source +
                                        ", the law's own constant (F = F_s(x) + A k_t(x) x')"
                                  : damping_basis(*a, source, *stiffness, runs);
  return MaterialDampedPlastic{std::string(key),       std::move(label),
                               std::move(model),       *stiffness,
                               {*yield_parameter, *a}, spring_basis + "; " + damping};
}

} // namespace

std::optional<MaterialDampedPlastic> material_hunt_crossley_thornton(
    const std::vector<FemRun>& runs) {
  return material_damped(
      runs, model_keys::hunt_crossley_thornton_material,
      "Hunt–Crossley on Thornton, p_y = 1.6 Y and b(V) from A of the material (no fit)",
      model_keys::hunt_crossley_thornton_from_a);
}

std::optional<MaterialDampedPlastic> material_hunt_crossley_jackson_green(
    const std::vector<FemRun>& runs) {
  return material_damped(
      runs, model_keys::hunt_crossley_jackson_green_material,
      "Hunt–Crossley on Jackson–Green, E*, Y, nu and b(V) from A of the material (no fit)",
      model_keys::hunt_crossley_jackson_green_from_a);
}

std::optional<MaterialDampedPlastic> material_kuwabara_kono_thornton(
    const std::vector<FemRun>& runs) {
  return material_damped(runs, model_keys::kuwabara_kono_thornton_material,
                         "Kuwabara–Kono on Thornton, p_y = 1.6 Y and A of the material (no fit)",
                         model_keys::kuwabara_kono_thornton);
}

std::optional<MaterialDampedPlastic> material_kuwabara_kono_jackson_green(
    const std::vector<FemRun>& runs) {
  return material_damped(runs, model_keys::kuwabara_kono_jackson_green_material,
                         "Kuwabara–Kono on Jackson–Green, E*, Y, nu and A of the material (no fit)",
                         model_keys::kuwabara_kono_jackson_green);
}

} // namespace impact::postprocess
