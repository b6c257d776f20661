#pragma once
// The fit machinery shared by the calibration's files (private): the prepared samples of a
// run, the parametrisation theta = (ln F_ref, n, p / p_scale, ...), a model's force history
// and energy loss as residuals, the estimates of a fit, and the three kinds of fits
// (per run: run_fits.cpp; campaign: campaign_fits.cpp; nothing fitted:
// reference_models.cpp) that calibrate() (calibration.cpp) combines.

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/models/contact_models.hpp"
#include "impact_postprocess/same_value.hpp"
#include "least_squares.hpp"
#include "impact_postprocess/models/simulated_force.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The samples of a run that the fits use.
struct PreparedRun {
  const FemRun* run;
  std::vector<double> times;  // s since first contact: from just before contact to 1.25 t_c
  std::vector<double> forces; // N
  double force_scale;         // N, the run's peak force: residuals are relative to it
  std::vector<double> loading_approach; // m, first contact to peak approach
  std::vector<double> loading_force;    // N
  std::size_t points;                   // samples of the simulated impact
  double energy_loss;                   // 1 - e^2 of the FEM
};

PreparedRun prepare(const FemRun& run);

// theta = (ln F_ref, n, p_1 / scale_1, p_2 / scale_2, ...).
struct Parametrisation {
  double reference_approach;
  std::vector<double> scales; // of the dissipation parameters

  double stiffness(const double* theta) const {
    return std::exp(theta[0] - theta[1] * std::log(reference_approach));
  }
  double exponent(const double* theta) const { return theta[1]; }
  std::vector<double> dissipation(const double* theta) const {
    std::vector<double> values(scales.size());
    for (std::size_t i = 0; i < scales.size(); ++i) values[i] = theta[2 + i] * scales[i];
    return values;
  }
  double log_reference_force(double stiffness, double exponent) const {
    return std::log(stiffness) + exponent * std::log(reference_approach);
  }
  std::size_t size() const { return 2 + scales.size(); }
};

double student_quantile(double level, std::size_t degrees_of_freedom);
Estimate estimate(double value, double variance, double quantile);

struct FitSetup {
  const ContactModel* model;
  Parametrisation parametrisation;
  std::vector<FitParameter> parameters;
};

// ModelFit from the solver's result; quality filled by the caller.
ModelFit to_model_fit(const FitSetup& setup, const LeastSquaresResult& result,
                      double confidence_level);

FitQuality quality_of(const std::vector<double>& model, const std::vector<double>& measured,
                      double scale);

// ---- Force histories and energy loss of a model ---------------------------------------

struct HistoryEvaluator {
  const ContactModel* model;
  const PreparedRun* run;
  Parametrisation map;
  double tolerance;

  bool force(const double* theta, double* force) const {
    const double c = map.stiffness(theta);
    const double n = map.exponent(theta);
    if (!(std::isfinite(c) && c > 0 && n > 0)) return false;
    const std::vector<double> dissipation = map.dissipation(theta);
    for (double p : dissipation)
      if (!std::isfinite(p)) return false;
    const reduced::ContactSetup setup{run->run->mass, c, n};
    if (model->damped_plastic()) try {
        return simulate_damped_plastic_force(*damped_plastic_impact(*model, run->run->mass,
                                                                    run->run->impact_velocity, c,
                                                                    dissipation),
                                             run->run->mass, run->times, run->points, force);
      } catch (const std::exception&) {
        return false;
      }
    double damping;
    try {
      damping = model->damping(dissipation, run->run->impact_velocity, setup);
    } catch (const std::exception&) {
      return false;
    }
    if (model->plastic_contact) try {
        return simulate_plastic_force(*model->plastic_contact(damping, setup), run->run->mass,
                                      run->run->impact_velocity, run->times, run->points, tolerance,
                                      force);
      } catch (const std::exception&) {
        return false;
      }
    if (model->hunt_crossley_force())
      return simulate_hunt_crossley_force(model->force_law(damping, setup), setup, damping,
                                          run->run->impact_velocity, run->times, run->points,
                                          force);
    return simulate_force(model->force_law(damping, setup), run->run->mass,
                          run->run->impact_velocity, run->times, run->points, tolerance,
                          model->contact_end, force);
  }

  bool residuals(const double* theta, double* residual) const {
    if (!force(theta, residual)) return false;
    for (std::size_t i = 0; i < run->forces.size(); ++i)
      residual[i] = (residual[i] - run->forces[i]) / run->force_scale;
    return true;
  }

  FitQuality quality(const double* theta) const {
    std::vector<double> model_force(run->times.size());
    if (!force(theta, model_force.data())) return {nan, nan, run->times.size()};
    return quality_of(model_force, run->forces, run->force_scale);
  }

  // The run's energy-loss residual: weight sqrt(N) (L_model - L_FEM) / L_FEM, so that it
  // counts against the run's N force residuals as a relative error against their RMS.
  bool energy_residual(const double* theta, double weight, double* residual) const {
    const double restitution =
        predict_restitution(*model, run->run->mass, run->run->impact_velocity, map.stiffness(theta),
                            map.exponent(theta), map.dissipation(theta), tolerance);
    if (!std::isfinite(restitution)) return false;
    const double loss = 1 - restitution * restitution;
    *residual = weight * std::sqrt(double(run->times.size())) * (loss - run->energy_loss) /
                run->energy_loss;
    return true;
  }
};

class Progress {
public:
  explicit Progress(const std::function<void(const std::string&)>& sink) : sink_(sink) {}
  void operator()(const std::string& line) const {
    if (sink_) sink_(line);
  }
  void start() { start_ = std::chrono::steady_clock::now(); }
  std::string elapsed() const {
    return significant(
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(),
               6) +
           " s";
  }

private:
  const std::function<void(const std::string&)>& sink_;
  std::chrono::steady_clock::time_point start_;
};

/// The exponent n as a fit parameter (bounded to [0.3, 4]).
FitParameter exponent_parameter(double initial, bool fixed);

double median(std::vector<double> values);
double geometric_mean(const std::vector<double>& values);
inline bool same_velocity(double a, double b) {
  return same_value(a, b);
}

struct CampaignStart {
  double reference_approach;
  double log_reference_force;
  double exponent;
  double restitution; // median measured
  double velocity;    // geometric mean
  double mass;        // median
};

// What distinguishes the campaign fits of one model.
struct CampaignFitRequest {
  std::string key;
  std::string label;
  std::optional<double> exponent; // n held here (else the model's required one, else free)
  double energy_weight = 0;
  double initial_damping = nan; // else from the median restitution
  std::vector<double> initial_extra;
  std::optional<double> stiffness; // c held here [N/m^n] (else free)
};

/// The per-run fits of one run (run_fits.cpp).
RunCalibration calibrate_run(const PreparedRun& run, const CalibrationOptions& options,
                             std::vector<Problem>& problems);

/// The campaign fit of one model, with its held-out fits (campaign_fits.cpp).
CampaignModelFit fit_campaign_model(const ContactModel& model, const CampaignFitRequest& request,
                                    const std::vector<PreparedRun>& runs,
                                    const std::vector<double>& velocities,
                                    const CampaignStart& start, const CalibrationOptions& options,
                                    std::vector<Problem>& problems);

/// The models that fit nothing (reference_models.cpp).
void add_reference_models(CampaignCalibration& campaign, const std::vector<FemRun>& fem_runs,
                          const std::vector<PreparedRun>& runs, const CalibrationOptions& options);

} // namespace impact::postprocess::detail
