#pragma once
/// @file
/// Hertz's elastic contact as an elastic-plastic contact law that never yields: loading and
/// unloading along F = c x^(3/2), no permanent approach. It is the spring of the elastic
/// limit of every damped elastic-plastic law (hunt_crossley_elastic_plastic.hpp), where
/// Hunt-Crossley on this spring is exactly HuntCrossleyImpact with n = 3/2.

#include "impact_reduced/elastic_plastic_impact.hpp"

namespace impact::reduced {

class HertzContact final : public ElasticPlasticContact {
public:
  /// c > 0 [N/m^1.5] (contact_formulas.hpp). Throws InvalidInput("stiffness") otherwise.
  explicit HertzContact(double stiffness);
  double stiffness() const { return stiffness_; }
  double loading_force(double approach) const override;
  double loading_work(double approach) const override;
  double loading_stiffness(double approach) const override;
  /// Both with one square root (the same values as the two calls).
  std::pair<double, double> loading_force_and_stiffness(double approach) const override;
  /// In closed form: (5 W / (2 c))^(2/5).
  double loading_approach(double work) const override;
  /// In closed form, without cancellation for small d.
  double loading_work_below(double approach_max, double distance) const override;
  std::optional<PowerLawCoefficients> loading_power_law() const override {
    return PowerLawCoefficients{stiffness_, 1.5};
  }
  /// The loading branch itself: stiffness c, residual approach 0.
  HertzianUnloading unloading(double approach_max) const override;

private:
  double stiffness_;
};

} // namespace impact::reduced
