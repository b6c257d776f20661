#pragma once
/// @file
/// The contact models that the calibration fits: Hunt–Crossley and the comparison laws of
/// the reduced library (impact_reduced/comparison_laws.hpp), each with three parameters
/// (c, n, p): stiffness c [N/m^n], exponent n (fixed for the laws defined for one n) and a
/// dissipation parameter p that is held constant over a campaign.
///
/// What p is follows how the law is used in a multibody code:
///   - damping: p is the law's damping constant itself, a property of the contact
///     (Hunt–Crossley b [s/m], Kuwabara–Kono A [s], Kelvin–Voigt mu, Tsuji eta);
///   - restitution: p is a coefficient of restitution e, and the law's damping at each impact
///     is its authors' map evaluated at that impact's velocity V (Lankarani–Nikravesh,
///     Flores, Gonthier, Hu–Guo, Zhiying–Qishao: b = map(e) / V). Their force is
///     Hunt–Crossley's, so with p the damping they would fit exactly as Hunt–Crossley; what
///     distinguishes them is this velocity dependence of b.

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// What the model's third parameter is (see the file comment).
enum class DissipationParameter { damping, restitution };

struct ContactModel {
  std::string name;          ///< "hunt-crossley" or a comparison-law name
  std::string formula;       ///< force law and damping map, plain text
  std::string reference;
  std::string damping_name;  ///< symbol of the law's damping constant ("b", "A", ...)
  std::string damping_unit;  ///< its unit ("s/m", "s", ...)
  DissipationParameter parameter;
  std::optional<double> required_exponent; ///< n is fixed to this value
  /// The law's damping constant at impact velocity V [m/s] for parameter p.
  std::function<double(double p, double velocity, const reduced::ContactSetup&)> damping;
  /// The damping constant that the law's own map assigns to restitution e at velocity V
  /// (used for starting values and scales).
  std::function<double(double restitution, double velocity, const reduced::ContactSetup&)>
      damping_for_restitution;
  /// The contact force for a damping constant.
  std::function<reduced::ContactForceLaw(double damping, const reduced::ContactSetup&)> force_law;

  std::string parameter_name() const;  ///< "e" or damping_name
  std::string parameter_unit() const;  ///< "1" or damping_unit
};

/// Hunt–Crossley, F = c x^n (1 + b x'), b constant.
ContactModel hunt_crossley_model();

/// The model of comparison law `name` (a name of reduced::comparison_law_names()); throws
/// reduced::InvalidInput for an unknown name.
ContactModel comparison_model(const std::string& name);

/// The names of the comparison laws whose parameter is a restitution (the rest: a damping).
const std::vector<std::string>& restitution_parametrised_laws();

} // namespace impact::postprocess
