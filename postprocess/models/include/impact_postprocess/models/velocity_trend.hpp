#pragma once
/// @file
/// The velocity trend of the energy loss as physics: the exponent p of 1 - e ∝ V^p, fitted
/// by least squares on (ln V, ln(1 - e)) with a Student-t interval (N - 2 degrees of
/// freedom), and the reference slopes of the model families: Hunt–Crossley with a constant b,
/// 1 - e = (2/3) b V + ..., slope 1 at small b V; the viscoelastic sphere (Kuwabara–Kono,
/// Brilliantov), 1 - e = gamma1 A (c/m)^(2/5) V^(1/5) + ..., slope 1/5; a constant
/// restitution (the e-parametrised maps), slope 0.

#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

struct PowerLawTrend {
  double exponent; ///< p
  double standard_error;
  double lower, upper; ///< interval at the requested level
  double prefactor;    ///< a of 1 - e = a (V / 1 m/s)^p
  std::size_t points;
  double level;
};

/// The fit over the runs with 0 < e < 1 (at least three, at two or more velocities), or none.
std::optional<PowerLawTrend> fit_restitution_trend(const std::vector<double>& velocity,
                                                   const std::vector<double>& restitution,
                                                   double level = 0.95);

struct ReferenceSlope {
  std::string family;
  double slope;
};
/// Hunt–Crossley (1), Kuwabara–Kono / Brilliantov (1/5), constant e (0).
const std::vector<ReferenceSlope>& reference_slopes();

/// The reference slope nearest to the fitted exponent.
const ReferenceSlope& nearest_reference(const PowerLawTrend& trend);

/// The plastic family (Thornton 1997, reduced/thornton.hpp): far above the yield velocity the
/// restitution itself falls as a power of V, e -> 1.185 (V/V_y)^(-1/4) (derived from Thornton's
/// closed forms; the limit and the slope -1/4 are tested in the reduced library), so its
/// reference is the slope of ln e against ln V, -1/4, not a slope of 1 - e. (Johnson's
/// Contact Mechanics, 1985, was not read here.)
inline constexpr double plastic_restitution_slope = -0.25;

/// The power law e = a (V / 1 m/s)^s of the restitution itself, fitted like
/// fit_restitution_trend on (ln V, ln e) (exponent = s), or none.
std::optional<PowerLawTrend> fit_restitution_power_law(const std::vector<double>& velocity,
                                                       const std::vector<double>& restitution,
                                                       double level = 0.95);

/// Whether the restitution's power law follows the plastic family: its exponent is nearer
/// -1/4 than 0 (a constant restitution), the nearest-reference rule of the loss trend.
bool follows_plastic_family(const PowerLawTrend& restitution_trend);

} // namespace impact::postprocess
