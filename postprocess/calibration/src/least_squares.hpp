#pragma once
// Nonlinear least squares on Ceres for models that are evaluated by simulation (no
// automatic derivatives): residual blocks given as functions of the parameter vector,
// Jacobians by central differences, and the covariance s^2 (J^T J)^-1 from ceres::Covariance
// (not asked where J^T J is singular by its own test: the covariance is then not known).

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace impact::postprocess::detail {

struct FitParameter {
  double initial;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool fixed = false;
  double step = 1e-6; ///< central-difference step (the parameters are scaled to O(1))
};

/// Residuals of one block (e.g. one run) for parameters theta; returns false if the model
/// cannot be evaluated there (the solver then shortens the step).
using ResidualFunction = std::function<bool(const double* theta, double* residuals)>;

struct ResidualBlock {
  std::size_t size;
  ResidualFunction residuals;
};

struct SolverSettings {
  int max_iterations = 100;
  int threads = 1;
};

struct LeastSquaresResult {
  std::vector<double> theta;
  /// Covariance of theta, s^2 (J^T J)^-1 with s^2 = sum r^2 / (N - p); row-major p x p,
  /// zero for fixed parameters; empty if J^T J is singular.
  std::vector<double> covariance;
  bool converged = false;
  std::string message; ///< the solver's termination message
  int iterations = 0;
  std::size_t residual_count = 0;
  std::size_t free_parameters = 0;
};

LeastSquaresResult solve_least_squares(const std::vector<FitParameter>& parameters,
                                       const std::vector<ResidualBlock>& blocks,
                                       const SolverSettings& settings);

} // namespace impact::postprocess::detail
