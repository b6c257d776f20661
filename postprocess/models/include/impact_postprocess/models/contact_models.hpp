#pragma once
/// @file
/// The contact models that the calibration fits: Hunt–Crossley, Hunt–Crossley with a
/// velocity-dependent damping, and the comparison laws of the reduced library
/// (impact_reduced/comparison_laws.hpp). Each has a stiffness c [N/m^n], an exponent n
/// (fixed for the laws defined for one n) and one or two dissipation parameters held constant
/// over a campaign: p and, for b(V), the exponent q.
///
/// What p is follows how the law is used in a multibody code:
///   - damping: p is the law's damping constant itself, a property of the contact
///     (Hunt–Crossley b [s/m], Kuwabara–Kono A [s], Kelvin–Voigt mu, Tsuji eta);
///   - restitution: p is a coefficient of restitution e, and the law's damping at each impact
///     is its authors' map evaluated at that impact's velocity V (Lankarani–Nikravesh,
///     Flores, Gonthier, Hu–Guo, Zhiying–Qishao: b = map(e) / V). Their force is
///     Hunt–Crossley's, and with e constant beta = b V = map(e) is constant: the five are one
///     family (Hunt–Crossley with b ∝ 1/V) and differ only in the e they report.

#include "impact_postprocess/impact_quantities.hpp"

#include <impact_reduced/comparison_laws.hpp>
#include <impact_reduced/elastic_plastic_impact.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// What the model's first dissipation parameter is (see the file comment).
enum class DissipationParameter { damping, restitution };

/// A further dissipation parameter of a model (the q of b(V), the damping b of a damped
/// elastic-plastic model).
struct ExtraParameter {
  std::string name;
  std::string unit;
  double initial;
  double lower;
  double upper;
  /// Its typical size in `unit`: the fits work on value / scale, so that their
  /// central-difference step (1e-6) is small against it (> 0).
  double scale = 1.0;
};

/// The rate-dependent term of a damped elastic-plastic model (damped_plastic_models.hpp):
/// none for every other model.
enum class SpringDamping {
  none,
  /// F = F_s(x) (1 + b x'), reduced::HuntCrossleyElasticPlasticImpact.
  hunt_crossley,
  /// F = F_s(x) + A k_t(x) x', k_t = dF_s/dx (reduced::kuwabara_kono_elastic_plastic_impact).
  kuwabara_kono,
};

struct ContactModel {
  std::string name;    ///< "hunt-crossley", "hunt-crossley-velocity-damping" or a law name
  std::string formula; ///< force law and damping map, plain text
  std::string reference;
  std::string damping_name; ///< symbol of the law's damping constant ("b", "A", ...)
  std::string damping_unit; ///< its unit ("s/m", "s", ...)
  DissipationParameter parameter;
  std::vector<ExtraParameter> extra_parameters;
  std::optional<double> required_exponent; ///< n is fixed to this value
  reduced::ContactEnd contact_end = reduced::ContactEnd::zero_approach;
  /// The law's damping constant at impact velocity V [m/s] for the dissipation parameters
  /// (p, then the extra ones).
  std::function<double(const std::vector<double>& dissipation, double velocity,
                       const reduced::ContactSetup&)>
      damping;
  /// The damping constant that the law's own map assigns to restitution e at velocity V
  /// (used for starting values and scales).
  std::function<double(double restitution, double velocity, const reduced::ContactSetup&)>
      damping_for_restitution;
  /// The contact force for a damping constant (none for a plastic model).
  std::function<reduced::ContactForceLaw(double damping, const reduced::ContactSetup&)> force_law;
  /// A rate-independent elastic-plastic model's loading and unloading for the damping
  /// constant (its yield approach) and c (plastic_models.hpp); none for the other models.
  std::function<std::shared_ptr<const reduced::ElasticPlasticContact>(double damping,
                                                                      const reduced::ContactSetup&)>
      plastic_contact;
  /// A damped elastic-plastic model: plastic_contact is its spring (for `damping`, the
  /// spring's yield parameter), and this rate term acts on it, with the constant
  /// spring_damping_constant(dissipation, V, setup) (Hunt–Crossley: b [s/m]).
  SpringDamping spring_damping = SpringDamping::none;
  std::function<double(const std::vector<double>& dissipation, double velocity,
                       const reduced::ContactSetup&)>
      spring_damping_constant;

  std::string parameter_name() const; ///< "e" or damping_name
  std::string parameter_unit() const; ///< "1" or damping_unit
  /// Hunt–Crossley's force (closed forms of the reduced library apply).
  bool hunt_crossley_force() const;
  /// A damped elastic-plastic model (spring_damping is not none).
  bool damped_plastic() const { return spring_damping != SpringDamping::none; }
};

/// Hunt–Crossley, F = c x^n (1 + b x'), b constant.
ContactModel hunt_crossley_model();

/// Hunt–Crossley with b(V) = b_1 (V / 1 m/s)^(-q): one line more in a multibody code
/// (the damping evaluated with the impact's first-contact speed). p = b_1 [s/m], q [1].
ContactModel velocity_damped_hunt_crossley_model();

/// The model of comparison law `name` (a name of reduced::comparison_law_names(), or of
/// plastic_model_names(), plastic_models.hpp); throws reduced::InvalidInput for an unknown
/// name.
ContactModel comparison_model(const std::string& name);

/// Any of the above by name (hunt-crossley, hunt-crossley-velocity-damping, a law name).
ContactModel contact_model(const std::string& name);

/// The names of the comparison laws whose parameter is a restitution (the rest: a damping).
const std::vector<std::string>& restitution_parametrised_laws();

/// What `model` with stiffness c, exponent n and `dissipation` predicts for a body of `mass`
/// [kg] at `velocity` [m/s]: closed form for Hunt–Crossley's force
/// (HuntCrossleyImpact::response), elastic_plastic_impact for a plastic model, the closed
/// form of a damped elastic-plastic model (HuntCrossleyElasticPlasticImpact::response),
/// integrate_impact (at `tolerance`, with the model's end of contact) otherwise. NaN where it cannot be evaluated (the law holds the body, invalid
/// parameters).
ImpactPrediction predict_impact(const ContactModel& model, double mass, double velocity,
                                double stiffness, double exponent,
                                const std::vector<double>& dissipation, double tolerance = 1e-10);

/// The restitution alone (cheap for Hunt–Crossley: k(b V)); NaN where not available.
double predict_restitution(const ContactModel& model, double mass, double velocity,
                           double stiffness, double exponent,
                           const std::vector<double>& dissipation, double tolerance = 1e-10);

/// The time history of the same impact at `points` instants (first contact to separation);
/// throws what the library throws.
std::vector<reduced::ImpactSample> predict_history(const ContactModel& model, double mass,
                                                   double velocity, double stiffness,
                                                   double exponent,
                                                   const std::vector<double>& dissipation,
                                                   std::size_t points);

} // namespace impact::postprocess
