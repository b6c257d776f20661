#pragma once
/// @file
/// Calibration of Hunt–Crossley (and of the comparison laws) from FEM impact runs.
///
/// Per run (HC: F = c x^n (1 + b x')):
///   - restitution: b = k^-1(e) / V through the library's exact inverse of k(beta);
///   - loading: c, n from the loading branch (first contact to peak approach) of the
///     force–approach curve, F = c x^n (1 + b v(x)), with b from the restitution and v(x) the
///     model's own approach rate (closed form), so that no measured rate is differentiated;
///   - history: c, n, b together, by fitting the simulated impact's force F(t) to the measured
///     force history from first contact to shortly after separation.
/// Over a campaign, each model is fitted to all runs at once:
///   - Hunt–Crossley to the force histories (`hunt_crossley`), to the force histories and the
///     energy loss 1 - e^2 of every run (`hunt_crossley_energy`, weight energy_weight), with n
///     held at 3/2 (`hunt_crossley_hertz_exponent`, c in N/m^1.5 comparable with Hertz), and
///     with b(V) = b_1 V^-q (`hunt_crossley_velocity_damping`, histories and energy loss);
///   - each comparison law to the force histories.
/// With at least three velocities every campaign model is fitted again once per velocity
/// with that velocity left out: its prediction there is out of sample, and the spread of
/// the left-out fits gives jackknife intervals that hold when the model itself is wrong.
/// Residuals are force differences divided by the run's peak force. The covariance intervals
/// s^2 (J^T J)^-1 are conditional on the model (they take the residuals as independent
/// noise); postprocess/README.md gives the details.

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/problem.hpp"
#include "impact_postprocess/impact_quantities.hpp"
#include "impact_postprocess/models/plastic_models.hpp"

#include <impact_reduced/comparison_laws.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// A fitted value with its standard error and confidence interval (NaN where not available,
/// e.g. for a parameter held fixed).
struct Estimate {
  double value;
  double standard_error;
  double lower;
  double upper;
};

/// Agreement of a model force history with a run's: RMS of (F_model - F) / F_max over the
/// fitted samples, and R^2 = 1 - sum (F_model - F)^2 / sum (F - mean F)^2.
struct FitQuality {
  double rms_residual;
  double r_squared;
  std::size_t samples;
};

/// A further dissipation parameter with its estimate (the q of b(V)).
struct NamedEstimate {
  std::string name;
  std::string unit;
  Estimate estimate;
};

/// The result of one least-squares fit of a model.
struct ModelFit {
  std::string model;          ///< ContactModel::name
  std::string parameter_name; ///< "b", "A", "e", "b_1", ...
  std::string parameter_unit;
  Estimate stiffness;               ///< c [N/m^n]
  Estimate exponent;                ///< n
  Estimate parameter;               ///< p (see ContactModel)
  std::vector<NamedEstimate> extra; ///< further dissipation parameters (b(V): q)
  bool stiffness_fixed = false;     ///< c held (a damped elastic-plastic model at Hertz's c)
  bool exponent_fixed = false;
  bool parameter_fixed = false;
  /// Correlations and covariance of (c, n, p, extra...) in their units, row-major k x k
  /// (NaN for a fixed parameter).
  std::vector<double> correlation;
  std::vector<double> covariance;
  double reference_approach;   ///< x_ref [m] of the internal parametrisation
  Estimate force_at_reference; ///< F_ref = c x_ref^n [N], nearly uncorrelated with n
  FitQuality quality;          ///< over all fitted force samples
  bool converged = false;
  std::string solver_message;
  int iterations = 0;

  /// p, then the extra parameters: what ContactModel::damping takes.
  std::vector<double> dissipation() const;
  /// c, n, p, extra... (the order of covariance and of the jackknife).
  std::vector<double> parameter_values() const;
  /// The names in that order: "c", "n", p's name, the extra names.
  std::vector<std::string> parameter_names() const;
  /// Parameters fitted (not held fixed).
  std::size_t free_parameters() const;
};

/// One run's share of a campaign fit.
struct RunResidual {
  std::string source;
  double velocity;
  FitQuality quality;
  ImpactPrediction prediction;                   ///< by the fit to all runs (in sample)
  std::optional<ImpactPrediction> out_of_sample; ///< by the fit without this velocity
};

/// A campaign fit with this run's velocity left out (leave-one-velocity-out).
struct HeldOutFit {
  double velocity;                ///< the velocity left out
  std::vector<double> parameters; ///< c, n, p, extra... of the fit to the other runs
  bool converged;
};

struct CampaignModelFit {
  /// Unique within the calibration: "hunt-crossley", "hunt-crossley-energy",
  /// "hunt-crossley-hertz-exponent", "hunt-crossley-velocity-damping" or the law's name.
  std::string key;
  std::string label; ///< what it is, in words
  ModelFit fit;      ///< to all runs; its intervals are conditional on the model
  std::string formula;
  std::string reference;
  std::string damping_name; ///< the law's damping constant (reported per run)
  std::string damping_unit;
  double energy_weight = 0; ///< of the energy-loss residuals; 0: force histories only
  std::vector<RunResidual> runs;
  std::vector<HeldOutFit> held_out; ///< one per velocity (empty below three velocities)
  /// Jackknife estimates over the held-out fits, in the order of parameter_values(): value of
  /// the full fit, standard error sqrt((g - 1)/g sum (theta_i - mean)^2), interval with
  /// Student t at g - 1 degrees of freedom (g velocities). Empty without held-out fits.
  std::vector<Estimate> jackknife;
};

/// A model whose parameters come from the material or the literature: nothing is fitted, so
/// its predictions are out of sample by construction.
struct ReferenceModel {
  std::string key; ///< "hertz", "hunt-crossley-published", "kuwabara-kono-material", ...
  std::string label;
  std::string model;               ///< ContactModel name
  std::string basis;               ///< where its parameters come from
  double stiffness;                ///< c [N/m^n]
  double exponent;                 ///< n
  std::vector<double> dissipation; ///< ContactModel::damping's parameters
  std::string parameter_name;      ///< of dissipation[0]
  std::string parameter_unit;
  std::vector<RunResidual> runs; ///< predictions and force-history agreement
  /// Names and units of dissipation[1], ... (a damped elastic-plastic model: its A).
  std::vector<std::string> extra_names;
  std::vector<std::string> extra_units;
};

/// A restitution-parametrised law as its users apply it: c from Hertz, n = 3/2, and the
/// FEM's e at each run as the target of the law's map.
struct RestitutionMapRun {
  std::string source;
  double velocity;
  double target;               ///< the FEM's e
  ImpactPrediction prediction; ///< what the law with the mapped damping really gives
};
struct RestitutionMapEvaluation {
  std::string law;
  std::string formula;
  std::vector<RestitutionMapRun> runs;
};

/// A model's place in the ranking: by the RMS of its relative errors in the verdict
/// quantities (energy loss, t_c, F_max, x_max) over all runs, out of sample where the
/// campaign allows it.
struct RankedModel {
  std::string key;
  std::size_t free_parameters;
  double score;           ///< RMS relative error used for the rank
  bool out_of_sample;     ///< score from out-of-sample predictions (else in sample)
  double worst_error;     ///< largest |relative error| in the same set
  double in_sample_score; ///< the same RMS with the in-sample predictions
  double rms_residual;    ///< of the force histories (in sample)
  bool converged;
  /// Models with the same predictions, ranked as one: the restitution-parametrised laws
  /// (their fits give one force history; key is the first of them).
  std::vector<std::string> family;
};

struct CampaignCalibration {
  bool fitted = false;
  std::string reason; ///< why not, when not fitted
  std::vector<double> velocities;
  double energy_weight = 0;                             ///< of the combined fits
  std::optional<CampaignModelFit> hunt_crossley;        ///< force histories
  std::optional<CampaignModelFit> hunt_crossley_energy; ///< + energy loss
  /// Hunt–Crossley with n fixed at hertz_exponent (c, b free): the c to compare with the
  /// Hertz stiffness (the free fit's c is in N/m^n and correlates with n).
  std::optional<CampaignModelFit> hunt_crossley_hertz_exponent;
  std::optional<CampaignModelFit> hunt_crossley_velocity_damping; ///< b(V), + energy loss
  std::vector<CampaignModelFit> comparison_laws;
  std::vector<ReferenceModel> reference_models; ///< Hertz, published b, A from the material
  std::vector<RestitutionMapEvaluation> restitution_maps; ///< the e maps as users apply them
  double hertz_stiffness = 0; ///< c_Hertz [N/m^1.5] of the reference models
  std::string hertz_basis;
  std::optional<double> material_dissipative_constant; ///< A [s] from the material
  std::string material_basis;       ///< its formula and inputs, or why there is none
  double published_damping = 0;     ///< b [s/m] of the published example
  std::vector<RankedModel> ranking; ///< every campaign and reference model, best first

  /// Every campaign fit, Hunt–Crossley variants first.
  std::vector<const CampaignModelFit*> models() const;
  const CampaignModelFit* find(const std::string& key) const;
};

/// The Hertz exponent, at which the fixed-exponent Hunt–Crossley campaign fit holds n.
inline constexpr double hertz_exponent = 1.5;

/// The measured figures of a run (FEM), for comparison with the predictions.
using ImpactFigures = ImpactFigures;

struct RunCalibration {
  std::string source;
  double velocity; ///< m/s at first contact
  double mass;     ///< kg
  ImpactFigures measured;
  double damping_from_restitution; ///< b [s/m] (0 for e >= 1)
  double impact_parameter;         ///< beta = b V
  std::optional<ModelFit> loading; ///< c, n (b fixed)
  std::optional<ModelFit> history; ///< c, n, b
  std::optional<ImpactPrediction> history_prediction;
};

struct Calibration {
  double confidence_level;
  std::vector<RunCalibration> runs;
  CampaignCalibration campaign;
  std::vector<Problem> problems;
};

struct CalibrationOptions {
  /// Comparison laws fitted over the campaign (names of comparison_model_names(): the
  /// library's comparison laws and the plastic models).
  std::vector<std::string> laws = comparison_model_names();
  int max_iterations = 100;       ///< per least-squares fit
  double confidence_level = 0.95; ///< of the intervals, in (0, 1)
  double ode_tolerance = 1e-10;   ///< of the simulated impacts (integrate_impact_history)
  /// Weight of the energy-loss residuals of the combined fits: each run adds
  /// w (L_model - L_FEM) / L_FEM with L = 1 - e^2, against its force samples' RMS; so w = 1
  /// makes a 1 % error in the energy loss cost as much as a 1 % RMS force residual. >= 0.
  double energy_weight = 1.0;
  /// b [s/m] of the published Hunt–Crossley example (the reference model
  /// "hunt-crossley-published", with c from Hertz and n = 3/2), >= 0.
  double published_damping = 0.1;
  /// The damped elastic-plastic models (damped_plastic_models.hpp) hold c at the Hertz value
  /// of the runs' materials when they record them; false fits c as well.
  bool damped_plastic_hertz_stiffness = true;
  int threads = 2;                                  ///< for the campaign fits
  std::function<void(const std::string&)> progress; ///< called with one line per step
};

/// Calibrates every run and, with at least two distinct velocities, the campaign. Problems
/// (a fit that does not converge, too few velocities) are recorded in the result, never
/// thrown. Throws reduced::InvalidInput for an unknown law name or invalid options.
Calibration calibrate(const std::vector<FemRun>& runs, const CalibrationOptions& options = {});

/// The ranking score of a set of predictions against the measured figures: RMS and largest
/// |relative error| over the runs and the verdict quantities (NaN entries skipped; NaN
/// score when none is finite).
struct RankingScore {
  double rms;
  double worst;
};
RankingScore ranking_score(const std::vector<ImpactFigures>& predicted,
                           const std::vector<ImpactFigures>& measured);

/// Orders models best first: the fitted models scored in sample (out_of_sample false, free
/// parameters > 0) after all others, each part by score; scores within `tie` (absolute, in
/// relative error) of the best of a group count as equal, and among equals fewer free
/// parameters come first (then the given order).
void rank(std::vector<RankedModel>& models, double tie = 1e-4);

} // namespace impact::postprocess
