#pragma once
// The contact force of a restitution table's law (impact-export, restitution/<law>.json) as a
// simulator's extension computes it, step by step, from the tool's own state: Hunt–Crossley
// or Kuwabara–Kono damping on an elastic-plastic spring,
//     F = F_s(x) (1 + b x')   or   F = F_s(x) + A k_t(x) x',  k_t = dF_s/dx,
// F_s the spring's loading branch while the approach x grows (x' > 0) and, once it falls, the
// Hertzian unloading branch from the largest approach so far, x_max: the history variable the
// tool keeps (Simbody: a continuous state, LAMMPS: a variable of the fix's callback). The
// spring is the reduced library's (the table's law.reduced_library); b from the table
// (constant, or b(V) from A with the impact speed), or A (the table's law.damping.kind
// "kuwabara-kono": the library's kuwabara_kono_elastic_plastic_force). As the library's
// closed form (hunt_crossley_elastic_plastic.hpp): a Hunt–Crossley branch that would return
// more energy than the loading stored unloads along the loading branch; the contact cannot
// pull.

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/elastic_plastic_impact.hpp>
#include <impact_reduced/kuwabara_kono_elastic_plastic.hpp>
#include <impact_reduced/sphere_flat_fits.hpp>
#include <impact_reduced/thornton.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

namespace impact::consumers {

class DampedPlasticContact {
public:
  /// The law of a restitution table's JSON (format "impact-restitution-table").
  explicit DampedPlasticContact(const std::filesystem::path& table) {
    std::ifstream in(table);
    if (!in) throw std::runtime_error("cannot open " + table.string());
    const nlohmann::json document = nlohmann::json::parse(in);
    if (document.value("format", "") != "impact-restitution-table")
      throw std::runtime_error(table.string() + " is not an impact-restitution-table");
    const nlohmann::json& law = document.at("law");
    const nlohmann::json& library = law.at("reduced_library");
    mass_ = law.at("mass").at("value").get<double>();
    stiffness_ = law.at("spring").at("c").at("value").get<double>();
    const std::string spring = law.at("spring").at("name").get<std::string>();
    if (spring == "thornton")
      spring_ =
          std::make_shared<reduced::ThorntonContact>(library.at("radius").get<double>(),
                                                     library.at("contact_modulus").get<double>(),
                                                     library.at("yield_pressure").get<double>());
    else if (spring == "jackson-green")
      spring_ = std::make_shared<reduced::JacksonGreenContact>(reduced::SphereFlatContact{
          library.at("radius").get<double>(), library.at("contact_modulus").get<double>(),
          library.at("yield_strength").get<double>(), library.at("poisson_ratio").get<double>()});
    else
      throw std::runtime_error(table.string() + ": unknown spring '" + spring + "'");
    const nlohmann::json& damping = law.at("damping");
    const std::string kind = damping.at("kind").get<std::string>();
    if (kind != "hunt-crossley" && kind != "kuwabara-kono")
      throw std::runtime_error(table.string() + ": unknown damping '" + kind + "'");
    kuwabara_kono_ = kind == "kuwabara-kono";
    from_dissipative_constant_ = damping.contains("A");
    damping_parameter_ = from_dissipative_constant_ ? damping.at("A").at("value").get<double>()
                                                    : damping.at("b").at("value").get<double>();
  }

  double mass() const { return mass_; }
  const reduced::ElasticPlasticContact& spring() const { return *spring_; }

  /// The damping of an impact at speed V [m/s]: Kuwabara–Kono's A [s]; Hunt–Crossley's b
  /// [s/m], b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5) for a law with A, else the constant b.
  double damping(double impact_velocity) const {
    if (kuwabara_kono_ || !from_dissipative_constant_) return damping_parameter_;
    return 1.5 * reduced::brilliantov_gamma1() * damping_parameter_ *
           std::pow(stiffness_ / mass_, 0.4) * std::pow(impact_velocity, -0.8);
  }

  /// The force [N] pushing the bodies apart at approach x [m], approach rate v [m/s] (> 0
  /// closing), the largest approach so far x_max [m] (>= x where the tool keeps it exactly)
  /// and the damping of damping(V) (b [s/m] or A [s]).
  double force(double approach, double approach_rate, double approach_max, double b) const {
    if (!(approach > 0)) return 0;
    if (kuwabara_kono_)
      return std::max(0.0, reduced::kuwabara_kono_elastic_plastic_force(
                               *spring_, b, approach, approach_rate,
                               approach_rate > 0 ? 0.0 : std::max(approach_max, approach)));
    double spring_force;
    if (approach_rate > 0 || !(approach_max > 0)) {
      spring_force = spring_->loading_force(approach);
    } else {
      const double top = std::max(approach_max, approach);
      const Branch& branch = branch_from(top);
      spring_force =
          branch.along_loading
              ? spring_->loading_force(approach)
              : branch.unloading.stiffness *
                    std::pow(std::max(0.0, approach - branch.unloading.residual_approach), 1.5);
    }
    return std::max(0.0, spring_force * (1 + b * approach_rate));
  }

private:
  struct Branch {
    double approach_max = -1;
    reduced::HertzianUnloading unloading{0.0, 0.0};
    bool along_loading = false;
  };
  // The unloading branch from x_max, kept for the last x_max asked (it is fixed once the
  // approach falls).
  const Branch& branch_from(double approach_max) const {
    if (approach_max == branch_.approach_max) return branch_;
    branch_.approach_max = approach_max;
    branch_.unloading = spring_->unloading(approach_max);
    const auto& u = branch_.unloading;
    const double whole = 0.4 * u.stiffness * std::pow(approach_max - u.residual_approach, 2.5);
    const double released = u.residual_approach < 0
                                ? whole - 0.4 * u.stiffness * std::pow(-u.residual_approach, 2.5)
                                : whole;
    branch_.along_loading = !(released < spring_->loading_work(approach_max));
    return branch_;
  }

  double mass_, stiffness_, damping_parameter_;
  bool kuwabara_kono_, from_dissipative_constant_;
  std::shared_ptr<const reduced::ElasticPlasticContact> spring_;
  mutable Branch branch_;
};

} // namespace impact::consumers
