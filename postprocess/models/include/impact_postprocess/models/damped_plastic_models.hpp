#pragma once
/// @file
/// Damping on an elastic-plastic spring: the comparison models that carry both losses of a
/// viscoelastic body that yields (the viscous loss below the yield velocity, the plastic one
/// above it), for the calibration (contact_models.hpp) and the report.
///
/// Hunt–Crossley damping on the spring (reduced/hunt_crossley_elastic_plastic.hpp):
///     F = F_s(x) (1 + b x'),
/// F_s the loading branch of an elastic-plastic law while x grows, then its Hertzian unloading
/// branch from x_max; closed form (Lambert W) for x_max and e, quadratures for the times.
/// Below yield it is Hunt–Crossley's law, with b = 0 the rate-independent plastic law.
///
/// Models (dissipation parameters in the order ContactModel::damping takes them; the first is
/// the spring's yield parameter, as for the plastic models, plastic_models.hpp):
///   - "hunt-crossley-thornton": Thornton's spring (c, x_y [m]; p_y = 3 c sqrt(x_y) /
///     (2 pi R)) with a constant b [s/m]: (x_y, b).
///   - "hunt-crossley-jackson-green": Jackson–Green's spring (c, Y [Pa], with R and nu of the
///     scenario) with a constant b: (Y, b). Needs the scenario (needs_scenario).
///   - "hunt-crossley-thornton-from-a", "hunt-crossley-jackson-green-from-a": the same springs
///     with b from a dissipative constant A [s] at each impact velocity V,
///         b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5)      (matched_hunt_crossley_damping):
///     (x_y, A) and (Y, A). With A from the materials' retardation times these are the
///     reference models "hunt-crossley-thornton-material" and
///     "hunt-crossley-jackson-green-material" (nothing fitted); fitted, b falls as V^(-4/5).
///
/// Why b(V) from A. The Hunt–Crossley b is not a material constant: with a constant b the
/// viscous loss of an elastic impact grows as 1 - e = (2/3) b V (Hunt & Crossley, J. Appl.
/// Mech. 42 (1975) 440, from the work of the damping force along the elastic trajectory, any
/// n), while the viscoelastic sphere's grows as 1 - e = gamma_1 A (c/m)^(2/5) V^(1/5)
/// (Kuwabara & Kono 1987, Brilliantov et al. 1996; gamma_1 = (6/5) (5/4)^(3/5) B(3/5, 3/2) =
/// 1.730173, Schwager & Pöschel, Phys. Rev. E 57 (1998) 650, whose constant carries a factor
/// 3/2: reduced::brilliantov_gamma1). Equal first-order losses at V give the b above: the
/// law then loses what the viscoelastic sphere loses below yield (to first order in the loss),
/// and its spring adds the plastic loss above. c is the elastic (Hertz) stiffness of the
/// spring, m the mass.
///
/// The stiffness c: the calibration holds it at the Hertz value of the runs' materials when
/// the runs record them, and fits it otherwise (calibrate, calibration.hpp). c is known from
/// E* and R; the yield parameter moves the knee of the loading curve, so a free c trades
/// against it (a stiffer c with an earlier yield gives nearly the same loading curve).
///
/// Kuwabara–Kono damping on the same springs (reduced/kuwabara_kono_elastic_plastic.hpp):
///     F = F_s(x) + A k_t(x) x',   k_t = dF_s/dx of the current branch,
/// the viscoelastic sphere's damping (2 E* a x' A on Hertz's spring) carried onto the
/// elastic-plastic contact's stiffness; no closed form (integrated by the library).
///   - "kuwabara-kono-thornton": Thornton's spring with A [s] free: (x_y, A).
///   - "kuwabara-kono-jackson-green": Jackson–Green's spring: (Y, A). Needs the scenario.
/// With A from the materials' retardation times (scenario_materials, the formula of
/// "Kuwabara–Kono from the material") these are "kuwabara-kono-thornton-material" and
/// "kuwabara-kono-jackson-green-material". The two dampings differ above yield: Hunt–Crossley's
/// force scales with F_s, Kuwabara–Kono's with the stiffness dF_s/dx of the branch.

#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <impact_reduced/impact_figures.hpp>
#include <impact_reduced/impact_ode.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The damped elastic-plastic models' names (above), in the order the calibration fits them.
const std::vector<std::string>& damped_plastic_model_names();

/// True for a name of damped_plastic_model_names().
bool is_damped_plastic_model(const std::string& name);

/// How a damped elastic-plastic model damps its spring F_s.
enum class DampedPlasticDamping {
  hunt_crossley,             ///< F = F_s(x) (1 + b x'), b constant
  hunt_crossley_of_velocity, ///< the same with b(V) from the dissipative constant A ("-from-a")
  kuwabara_kono,             ///< F = F_s(x) + A k_t(x) x', k_t = dF_s/dx of the branch
};

/// The damping of the damped model `name` (a name of damped_plastic_model_names()); throws
/// reduced::InvalidInput("model") for another name.
DampedPlasticDamping damped_plastic_damping(const std::string& name);

/// Whether a damped model needs the scenario's sphere radius and Poisson ratio (the
/// Jackson–Green spring).
bool damped_plastic_needs_scenario(const std::string& name);

/// The damped model `name` on the spring of `spring` (the plastic model of its yield
/// parameter: plastic_model("thornton") or jackson_green_model(R, nu)). Throws
/// reduced::InvalidInput("model") for another name.
ContactModel damped_plastic_model(const std::string& name, const ContactModel& spring);

/// The Thornton-based damped model `name`; throws reduced::InvalidInput("model") for a model
/// that needs the scenario (build it with comparison_model(name, runs), plastic_models.hpp).
ContactModel damped_plastic_model(const std::string& name);

/// The Hunt–Crossley b [s/m] whose small-loss restitution at impact velocity V > 0 [m/s]
/// equals that of Kuwabara–Kono's law with dissipative constant A >= 0 [s] on the Hertz
/// spring c [N/m^1.5] for mass m [kg] (setup): b = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5).
/// Throws reduced::InvalidInput naming "dissipative_constant", "velocity", "mass" or
/// "stiffness".
double matched_hunt_crossley_damping(double dissipative_constant, double velocity,
                                     const reduced::ContactSetup& setup);

/// One impact of a damped elastic-plastic model: its figures, where the bodies part, its
/// history, and its force along the history (for fitting).
class DampedPlasticImpact {
public:
  virtual ~DampedPlasticImpact() = default;
  virtual reduced::ImpactFigures figures() const = 0;
  virtual double restitution() const = 0;
  /// The approach at separation [m] (the permanent approach; 0 for an elastic impact).
  virtual double separation_approach() const = 0;
  /// `points` >= 2 states equally spaced in time from first contact to separation.
  virtual std::vector<reduced::ImpactSample> history(std::size_t points) const = 0;
  /// The force at approach x [m] and approach rate v [m/s]: the loading branch while v > 0,
  /// the unloading branch after.
  virtual double force(double approach, double approach_rate) const = 0;
};

/// The impact of `model` (damped_plastic()) for a body of `mass` [kg] at `velocity` [m/s],
/// stiffness c and the dissipation parameters. Throws what the library throws, and
/// reduced::InvalidInput("model") for a model that is not damped.
std::unique_ptr<const DampedPlasticImpact> damped_plastic_impact(
    const ContactModel& model, double mass, double velocity, double stiffness,
    const std::vector<double>& dissipation);

/// A damped model from the scenario's material, nothing fitted: the spring of
/// material_thornton or material_jackson_green, b(V) from the dissipative constant A of the
/// materials' retardation times (scenario_materials). None without a yield strength, without
/// an A, or with A = 0 (then the model is the rate-independent one from the material).
struct MaterialDampedPlastic {
  std::string key; ///< "hunt-crossley-thornton-material", ...
  std::string label;
  ContactModel model;              ///< the "-from-a" model
  double stiffness;                ///< c [N/m^1.5]
  std::vector<double> dissipation; ///< (yield parameter, A)
  std::string basis;               ///< where the numbers come from, and the b(V) formula
};
std::optional<MaterialDampedPlastic> material_hunt_crossley_thornton(
    const std::vector<FemRun>& runs);
std::optional<MaterialDampedPlastic> material_hunt_crossley_jackson_green(
    const std::vector<FemRun>& runs);
/// The Kuwabara–Kono laws from the material: the same springs, A of the materials.
std::optional<MaterialDampedPlastic> material_kuwabara_kono_thornton(
    const std::vector<FemRun>& runs);
std::optional<MaterialDampedPlastic> material_kuwabara_kono_jackson_green(
    const std::vector<FemRun>& runs);

} // namespace impact::postprocess
