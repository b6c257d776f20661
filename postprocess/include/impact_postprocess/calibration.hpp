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
/// Over a campaign: one (c, n, p) per model fitted to the force histories of all runs, and
/// Hunt–Crossley once more with n held at the Hertz value 3/2 (c, b free), whose c is in
/// N/m^1.5 and so comparable with the Hertz stiffness.
/// Residuals are force differences divided by the run's peak force; 95 % intervals from
/// the covariance s^2 (J^T J)^-1 (postprocess/README.md gives the details).

#include "impact_postprocess/contact_models.hpp"
#include "impact_postprocess/fem_run.hpp"

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

/// What the fitted model predicts for a run (closed form for HC, integration otherwise).
struct ImpactPrediction {
  double damping;          ///< the law's damping constant at this velocity
  double restitution;
  double contact_time;     ///< s
  double force_max;        ///< N
  double time_force_max;   ///< s since first contact
  double approach_max;     ///< m
};

/// The result of one least-squares fit of a model.
struct ModelFit {
  std::string model;                ///< ContactModel::name
  std::string parameter_name;       ///< "b", "A", "e", ...
  std::string parameter_unit;
  Estimate stiffness;               ///< c [N/m^n]
  Estimate exponent;                ///< n
  Estimate parameter;               ///< p (see ContactModel)
  bool exponent_fixed = false;
  bool parameter_fixed = false;
  /// Correlations of (c, n, p), row-major 3 x 3 (NaN for a fixed parameter).
  std::array<double, 9> correlation;
  /// Covariance of (c, n, p) in their units, row-major 3 x 3.
  std::array<double, 9> covariance;
  double reference_approach;        ///< x_ref [m] of the internal parametrisation
  Estimate force_at_reference;      ///< F_ref = c x_ref^n [N], nearly uncorrelated with n
  FitQuality quality;               ///< over all fitted samples
  bool converged = false;
  std::string solver_message;
  int iterations = 0;
};

/// One run's share of a campaign fit.
struct RunResidual {
  std::string source;
  double velocity;
  FitQuality quality;
  ImpactPrediction prediction;
};

struct CampaignModelFit {
  ModelFit fit;
  std::string formula;
  std::string reference;
  std::string damping_name;   ///< the law's damping constant (reported per run)
  std::string damping_unit;
  std::vector<RunResidual> runs;
};

/// The measured figures of a run (FEM), for comparison with the predictions.
struct MeasuredImpact {
  double restitution;
  double contact_time;     ///< s
  double force_max;        ///< N
  double time_force_max;   ///< s since first contact
  double approach_max;     ///< m
};

struct RunCalibration {
  std::string source;
  double velocity;             ///< m/s at first contact
  double mass;                 ///< kg
  MeasuredImpact measured;
  double damping_from_restitution;   ///< b [s/m] (0 for e >= 1)
  double impact_parameter;           ///< beta = b V
  std::optional<ModelFit> loading;   ///< c, n (b fixed)
  std::optional<ModelFit> history;   ///< c, n, b
  std::optional<ImpactPrediction> history_prediction;
};

struct CampaignCalibration {
  bool fitted = false;
  std::string reason;                       ///< why not, when not fitted
  std::vector<double> velocities;
  std::optional<CampaignModelFit> hunt_crossley;
  /// Hunt–Crossley with n fixed at hertz_exponent (c, b free): the c to compare with the
  /// Hertz stiffness (the free fit's c is in N/m^n and correlates with n).
  std::optional<CampaignModelFit> hunt_crossley_hertz_exponent;
  std::vector<CampaignModelFit> comparison_laws;
};

/// The Hertz exponent, at which the fixed-exponent Hunt–Crossley campaign fit holds n.
inline constexpr double hertz_exponent = 1.5;

/// A problem met while calibrating (input or solver), kept for the JSON.
struct CalibrationProblem {
  std::string source;    ///< run, directory or model concerned
  std::string kind;      ///< "input" or "convergence"
  std::string message;
};

struct Calibration {
  double confidence_level;
  std::vector<RunCalibration> runs;
  CampaignCalibration campaign;
  std::vector<CalibrationProblem> problems;
};

struct CalibrationOptions {
  /// Comparison laws fitted over the campaign (names of reduced::comparison_law_names()).
  std::vector<std::string> laws = reduced::comparison_law_names();
  int max_iterations = 100;          ///< per least-squares fit
  double confidence_level = 0.95;    ///< of the intervals, in (0, 1)
  double ode_tolerance = 1e-10;      ///< of the simulated impacts (integrate_impact_history)
  int threads = 2;                   ///< for the campaign fits
  std::function<void(const std::string&)> progress; ///< called with one line per step
};

/// Calibrates every run and, with at least two distinct velocities, the campaign. Problems
/// (a fit that does not converge, too few velocities) are recorded in the result, never
/// thrown. Throws reduced::InvalidInput for an unknown law name or invalid options.
Calibration calibrate(const std::vector<FemRun>& runs, const CalibrationOptions& options = {});

} // namespace impact::postprocess
