// The dissipative constant of the viscoelastic-sphere law from the material (see
// viscoelastic_dissipation.hpp for the formula and its source).

#include "impact_reduced/viscoelastic_dissipation.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <string>

namespace impact::reduced {

namespace {

double body_constant(const std::string& prefix, double poisson_ratio, double deviatoric,
                     double volumetric) {
  require_open_interval((prefix + "poisson_ratio").c_str(), poisson_ratio, 0.0, 0.5);
  require_non_negative((prefix + "deviatoric_retardation_time").c_str(), deviatoric);
  require_non_negative((prefix + "volumetric_retardation_time").c_str(), volumetric);
  const double nu = poisson_ratio;
  const double shear = deviatoric * (1 - 2 * nu); // tau_d (1 - 2 nu)
  const double bulk = volumetric * (1 + nu);      // tau_v (1 + nu)
  const double denominator = 3 * nu * nu * (bulk + 2 * shear);
  if (denominator == 0) return 0.0; // no viscosity at all
  return (1 - nu) * (bulk - shear) * (bulk - shear) / denominator;
}

} // namespace

double kuwabara_kono_dissipative_constant(double poisson_ratio, double deviatoric_retardation_time,
                                          double volumetric_retardation_time) {
  return body_constant("", poisson_ratio, deviatoric_retardation_time, volumetric_retardation_time);
}

double kuwabara_kono_dissipative_constant(const KelvinVoigtBody& first,
                                          const KelvinVoigtBody& second) {
  require_positive("first.youngs_modulus", first.youngs_modulus);
  require_positive("second.youngs_modulus", second.youngs_modulus);
  const double a1 = body_constant("first.", first.poisson_ratio, first.deviatoric_retardation_time,
                                  first.volumetric_retardation_time);
  const double a2 =
      body_constant("second.", second.poisson_ratio, second.deviatoric_retardation_time,
                    second.volumetric_retardation_time);
  const double k1 = (1 - first.poisson_ratio * first.poisson_ratio) / first.youngs_modulus;
  const double k2 = (1 - second.poisson_ratio * second.poisson_ratio) / second.youngs_modulus;
  return (k1 * a1 + k2 * a2) / (k1 + k2);
}

} // namespace impact::reduced
