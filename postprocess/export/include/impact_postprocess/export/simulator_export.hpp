#pragma once
/// @file
/// The calibrated contact in the terms of four simulators (impact-export): Simbody's
/// HuntCrossleyForce, MuJoCo's soft contact (solref/solimp), LAMMPS's granular wall and
/// LIGGGHTS' elastic-plastic thornton_ning wall (liggghts.hpp). Each mapping is a pure
/// function of the calibrated parameters, documented with the tool's own force law
/// (postprocess/README.md, "Exports"), and checked by running the tool (tests/consumers). The
/// JSON of impact-calibrate is the source of every number; the LIGGGHTS export also takes the
/// scenario's materials from the runs.

#include "impact_postprocess/export/restitution_table.hpp"
#include "impact_postprocess/impact_quantities.hpp"
#include "impact_postprocess/run/scenario_plastic_contact.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::postprocess {

/// A calibration that cannot be exported (not a campaign calibration, a fit missing or not
/// converged, ...); `what()` names the key or the parameter and what is expected.
class ExportInputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// One run of the campaign as the calibration measured it.
struct CampaignImpact {
  std::string source;
  double velocity;   ///< m/s
  ImpactFigures fem; ///< the exports compare e, t_c and F_max
};

/// A law with c [N/m^1.5] at n = 3/2 and one damping constant, fitted over the campaign.
struct HertzLawFit {
  std::string model;   ///< "hunt-crossley", "kuwabara-kono", "tsuji"
  double stiffness;    ///< c [N/m^1.5]
  double damping;      ///< b [s/m], A [s] or eta [N s/m^(5/4)]
  double rms_residual; ///< of the campaign force-history fit, fraction of the peak force
};

/// What impact-export needs from a calibration and its runs.
struct ExportCampaign {
  std::string calibration_file;
  double mass;                      ///< kg
  double radius;                    ///< sphere radius [m]
  std::vector<CampaignImpact> runs; ///< by velocity
  /// The free Hunt–Crossley fit (the "multibody" block): c [N/m^n], n, b [s/m].
  double free_stiffness, free_exponent, free_damping, free_rms_residual;
  HertzLawFit hunt_crossley; ///< campaign.hunt_crossley_hertz_exponent
  std::optional<HertzLawFit> kuwabara_kono;
  std::optional<HertzLawFit> tsuji;
  /// The plastic contact: the calibration's converged Thornton fit if there is one
  /// (read_export_campaign), else the scenario's material (scenario_plastic_contact,
  /// liggghts.hpp); none: nothing is exported to LIGGGHTS.
  std::optional<PlasticContact> plastic;
  /// The restitution table of a damped elastic-plastic law (restitution_table.hpp), made by
  /// export_run_set when the calibration has such a law; none: no table is written.
  std::optional<RestitutionTable> restitution_table;
};

/// Reads the calibration JSON of impact-calibrate (through calibration_from_json) for the export. The
/// sphere radius [m] comes from the runs (impact-fem's "Scenario/Sphere radius"). Throws
/// ExportInputError when the calibration has no converged campaign fit of Hunt–Crossley with
/// n = 3/2, no kuwabara-kono and no tsuji fit (LAMMPS needs one), or a run without its
/// measured restitution, contact time or peak force.
ExportCampaign read_export_campaign(const nlohmann::json& calibration,
                                    const std::string& calibration_file, double radius);

/// Simbody's HuntCrossleyForce, f = (4/3) sqrt(R) E x^(3/2) (1 + (3/2) c_s v), with
/// E = (k1^(2/3) k2^(2/3) / (k1^(2/3) + k2^(2/3)))^(3/2) and c_s = (c1 k2^(2/3) + c2 k1^(2/3)) /
/// (k1^(2/3) + k2^(2/3)) from the per-surface stiffnesses k1, k2 and dissipations c1, c2
/// (Simbody 3.7, HuntCrossleyForceImpl). With the same k and c_s on both surfaces
/// f = (sqrt(2 R) k / 3) x^(3/2) (1 + (3/2) c_s v), so that k = 3 c / sqrt(2 R) and
/// c_s = 2 b / 3 give F = c x^(3/2) (1 + b v) exactly.
struct SimbodyContact {
  double surface_stiffness;   ///< k [Pa] of setBodyParameters, on both surfaces
  double surface_dissipation; ///< c_s [s/m] of setBodyParameters, on both surfaces
};
SimbodyContact simbody_contact(double stiffness, double damping, double radius);

/// MuJoCo's contact as the linear spring-damper it is for one free body on a plane with
/// solref = (-K, -B) and a flat solimp (d_min = d_max = d): MuJoCo 2.2.2 uses K / d^2 and
/// B / d with the impedance d, and the constrained acceleration is d times the reference
/// acceleration, so x'' = -(K x + B x') while the contact pushes, and no force once
/// K x + B x' < 0 (the contact cannot pull). K [1/s^2] and B [1/s] are accelerations per
/// penetration and per penetration rate: the force is the body's mass times that.
struct MujocoContact {
  double stiffness;     ///< K [1/s^2], solref[0] = -K
  double damping;       ///< B [1/s], solref[1] = -B
  double damping_ratio; ///< zeta = B / (2 sqrt(K))
  double impedance;     ///< d = solimp[0] = solimp[1]
  double timestep;      ///< s, the MJCF's option timestep (contact time / 1000)
  double reference_velocity;
};

/// The impact of the clamped linear spring-damper x'' = -(K x + B x') (no pull) at velocity
/// V, in closed form: exact for damping ratio in [0, 1); its x_max is NaN (not computed: the
/// exports compare e, t_c and F_max).
ImpactFigures linear_contact_impact(double stiffness, double damping, double mass, double velocity);

/// K, B that make the clamped linear spring-damper give restitution e in (e_min, 1) and
/// contact time t_c > 0 (e_min = exp(-2) = 0.1353, the restitution at damping ratio 1). Throws
/// ExportInputError outside.
MujocoContact mujoco_contact(double restitution, double contact_time, double velocity);

/// LAMMPS (29 Sep 2021, GRANULAR) fix wall/gran granular with normal model hertz,
/// F_ne = k_n a delta with a = sqrt(R delta) (R = sphere radius at a flat wall), and
///   damping viscoelastic: F_d = eta_n0 m a v, so Kuwabara–Kono's (3/2) A c x^(1/2) v is
///     eta_n0 = (3/2) A c / (m sqrt(R));
///   damping tsuji: F_d = alpha(e_in) sqrt(m k_n a) v with LAMMPS's polynomial
///     alpha(e_in) = 1.2728 - 4.2783 e_in + 11.087 e_in^2 - 22.348 e_in^3 + 27.467 e_in^4
///                   - 18.022 e_in^5 + 4.8218 e_in^6,
///     so the Tsuji law's eta x^(1/4) v is alpha(e_in) = eta / sqrt(m c), solved for e_in.
struct LammpsContact {
  std::string model;          ///< "kuwabara-kono" or "tsuji"
  std::string damping_model;  ///< LAMMPS's: "viscoelastic" or "tsuji"
  double normal_stiffness;    ///< k_n [Pa] of "hertz"
  double damping_coefficient; ///< eta_n0 [1/(m s)] (viscoelastic) or e_in [-] (tsuji)
};
LammpsContact lammps_contact(const HertzLawFit& law, double mass, double radius);

/// LAMMPS's Tsuji polynomial alpha(e_in), and its inverse on [0, 1] (it decreases from
/// 1.2728 at 0 to 3e-4 at 1). The inverse throws ExportInputError outside that range.
double lammps_tsuji_alpha(double restitution_input);
double lammps_tsuji_restitution_input(double alpha);

/// The impact of a Hertz-type law of the calibration (hunt-crossley, kuwabara-kono, tsuji)
/// at velocity V, from the reduced library (closed form for Hunt–Crossley, integrate_impact
/// at tolerance 1e-12 otherwise).
ImpactFigures hertz_law_impact(const HertzLawFit& law, double mass, double velocity);

/// Writes the exports into `directory` (replaced as a whole, written atomically):
/// export.json (the manifest, format in postprocess/README.md), simbody/impact_contact.hpp,
/// mujoco/impact_contact.xml, lammps/kuwabara_kono.in and lammps/tsuji.in (those the
/// calibration has), liggghts/thornton_ning.in (when the campaign has a plastic contact),
/// restitution/<law>.csv and restitution/<law>.json (when it has a restitution table).
/// `reference_velocity` (one of the campaign's, m/s) is MuJoCo's; none
/// means the median run (the lower of the two middle ones for an even count). Returns the
/// manifest. Throws ExportInputError for a reference velocity that is not a campaign
/// velocity or a restitution MuJoCo's contact cannot produce.
nlohmann::json write_exports(const ExportCampaign& campaign,
                             std::optional<double> reference_velocity,
                             const std::filesystem::path& directory);

} // namespace impact::postprocess
