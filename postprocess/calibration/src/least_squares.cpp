#include "least_squares.hpp"

#include <ceres/ceres.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>

namespace impact::postprocess::detail {

namespace {

// One residual block; each parameter is its own 1-D Ceres parameter block, so that a
// parameter can be held constant (Ceres then asks for no Jacobian column for it). Jacobian by
// central differences, forward where the model cannot be evaluated below the parameter.
class CentralDifferenceCost final : public ceres::CostFunction {
public:
  CentralDifferenceCost(ResidualFunction function, std::size_t residuals, std::vector<double> steps)
      : function_(std::move(function)), steps_(std::move(steps)) {
    set_num_residuals(int(residuals));
    for (std::size_t j = 0; j < steps_.size(); ++j) mutable_parameter_block_sizes()->push_back(1);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const std::size_t p = steps_.size();
    const std::size_t n = std::size_t(num_residuals());
    std::vector<double> theta(p);
    for (std::size_t j = 0; j < p; ++j) theta[j] = parameters[j][0];
    if (!residuals_at(theta, residuals)) return false;
    if (jacobians == nullptr) return true;
    std::vector<double> plus(n), minus(n);
    for (std::size_t j = 0; j < p; ++j) {
      if (jacobians[j] == nullptr) continue;
      // The rank check before the covariance and the covariance itself ask for the same
      // Jacobian at the solution: the second is the first, kept.
      if (cached_column(theta, j, jacobians[j])) continue;
      const double h = steps_[j];
      std::vector<double> shifted = theta;
      shifted[j] = theta[j] + h;
      if (!function_(shifted.data(), plus.data())) return false;
      shifted[j] = theta[j] - h;
      if (function_(shifted.data(), minus.data())) {
        for (std::size_t i = 0; i < n; ++i) jacobians[j][i] = (plus[i] - minus[i]) / (2 * h);
      } else {
        // A parameter at the edge of the model's domain (a damping at its bound 0, where the
        // law is not defined below): the forward difference.
        for (std::size_t i = 0; i < n; ++i) jacobians[j][i] = (plus[i] - residuals[i]) / h;
      }
      keep_column(theta, j, jacobians[j]);
    }
    return true;
  }

private:
  // The residuals at theta. Ceres evaluates the residuals at a step's point and, once the
  // step is accepted, again with the Jacobian there (and the covariance once more at the
  // solution): the last point's residuals are kept and returned for the same theta (the
  // models are deterministic simulations: the same values to the last bit), which spares
  // one simulation of the 2 p + 2 per iteration.
  bool residuals_at(const std::vector<double>& theta, double* residuals) const {
    const std::size_t n = std::size_t(num_residuals());
    const std::size_t bytes = theta.size() * sizeof(double);
    {
      std::lock_guard<std::mutex> lock(cache_mutex_);
      if (cached_theta_.size() == theta.size() &&
          std::memcmp(cached_theta_.data(), theta.data(), bytes) == 0) {
        std::copy(cached_residuals_.begin(), cached_residuals_.end(), residuals);
        return true;
      }
    }
    if (!function_(theta.data(), residuals)) return false;
    std::lock_guard<std::mutex> lock(cache_mutex_);
    cached_theta_ = theta;
    cached_residuals_.assign(residuals, residuals + n);
    return true;
  }

  // Column j of the Jacobian at theta, when the last one computed there is kept.
  bool cached_column(const std::vector<double>& theta, std::size_t j, double* column) const {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    if (j >= jacobian_kept_.size() || !jacobian_kept_[j] || jacobian_theta_ != theta) return false;
    std::copy(cached_jacobian_[j].begin(), cached_jacobian_[j].end(), column);
    return true;
  }

  void keep_column(const std::vector<double>& theta, std::size_t j, const double* column) const {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    if (jacobian_theta_ != theta) {
      jacobian_theta_ = theta;
      jacobian_kept_.assign(steps_.size(), false);
      cached_jacobian_.assign(steps_.size(), {});
    }
    cached_jacobian_[j].assign(column, column + num_residuals());
    jacobian_kept_[j] = true;
  }

  ResidualFunction function_;
  std::vector<double> steps_;
  mutable std::mutex cache_mutex_;
  mutable std::vector<double> jacobian_theta_;
  mutable std::vector<bool> jacobian_kept_;
  mutable std::vector<std::vector<double>> cached_jacobian_;
  mutable std::vector<double> cached_theta_; // empty until a successful evaluation
  mutable std::vector<double> cached_residuals_;
};

// Whether J^T J of the free parameters at the solution has a reciprocal condition number of
// at least 1e-14, ceres::Covariance's own test (min_reciprocal_condition_number): a parameter
// without effect there (a damping at its bound 0 on a forward difference, a yield strength
// above every run's stress) makes it singular. Tested here so that ceres::Covariance is not
// asked: it would log an error for a case the fit reports as an interval not known.
bool well_conditioned(ceres::Problem& problem) {
  std::vector<double*> blocks;
  problem.GetParameterBlocks(&blocks);
  ceres::Problem::EvaluateOptions options;
  for (double* block : blocks)
    if (!problem.IsParameterBlockConstant(block)) options.parameter_blocks.push_back(block);
  ceres::CRSMatrix jacobian;
  double cost = 0;
  if (options.parameter_blocks.empty() ||
      !problem.Evaluate(options, &cost, nullptr, nullptr, &jacobian))
    return false;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(jacobian.num_rows, jacobian.num_cols);
  for (int row = 0; row < jacobian.num_rows; ++row)
    for (int k = jacobian.rows[std::size_t(row)]; k < jacobian.rows[std::size_t(row) + 1]; ++k)
      dense(row, jacobian.cols[std::size_t(k)]) = jacobian.values[std::size_t(k)];
  if (!dense.allFinite()) return false;
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(dense).singularValues();
  return sigma.size() > 0 && sigma(0) > 0 &&
         std::pow(sigma(sigma.size() - 1) / sigma(0), 2) >= 1e-14;
}

} // namespace

LeastSquaresResult solve_least_squares(const std::vector<FitParameter>& parameters,
                                       const std::vector<ResidualBlock>& blocks,
                                       const SolverSettings& settings) {
  const std::size_t p = parameters.size();
  LeastSquaresResult result;
  result.theta.resize(p);
  std::vector<double> steps(p);
  for (std::size_t j = 0; j < p; ++j) {
    result.theta[j] = parameters[j].initial;
    steps[j] = parameters[j].step;
  }
  std::vector<double*> blocks_of_theta;
  for (auto& value : result.theta) blocks_of_theta.push_back(&value);

  ceres::Problem problem;
  for (const auto& block : blocks) {
    result.residual_count += block.size;
    problem.AddResidualBlock(new CentralDifferenceCost(block.residuals, block.size, steps), nullptr,
                             blocks_of_theta);
  }
  for (std::size_t j = 0; j < p; ++j) {
    if (parameters[j].fixed) {
      problem.SetParameterBlockConstant(blocks_of_theta[j]);
      continue;
    }
    ++result.free_parameters;
    if (std::isfinite(parameters[j].lower))
      problem.SetParameterLowerBound(blocks_of_theta[j], 0, parameters[j].lower);
    if (std::isfinite(parameters[j].upper))
      problem.SetParameterUpperBound(blocks_of_theta[j], 0, parameters[j].upper);
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = settings.max_iterations;
  options.num_threads = settings.threads;
  options.function_tolerance = 1e-15;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  result.message = summary.message;
  result.iterations = int(summary.iterations.size()) - 1;

  // Covariance of the free parameters, scaled by the residual variance.
  result.covariance.assign(p * p, 0.0);
  const std::size_t degrees_of_freedom = result.residual_count > result.free_parameters
                                             ? result.residual_count - result.free_parameters
                                             : 0;
  ceres::Covariance::Options covariance_options;
  covariance_options.algorithm_type = ceres::DENSE_SVD;
  covariance_options.num_threads = settings.threads;
  ceres::Covariance covariance(covariance_options);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = i; j < p; ++j)
      if (!parameters[i].fixed && !parameters[j].fixed)
        pairs.emplace_back(blocks_of_theta[i], blocks_of_theta[j]);
  // No covariance where the residuals or their Jacobian could not be evaluated: Ceres' dense
  // SVD would work on an undefined Jacobian.
  const bool evaluated =
      summary.termination_type != ceres::FAILURE && std::isfinite(summary.final_cost);
  if (degrees_of_freedom == 0 || pairs.empty() || !evaluated || !well_conditioned(problem) ||
      !covariance.Compute(pairs, &problem)) {
    result.covariance.clear();
    return result;
  }
  const double variance = 2 * summary.final_cost / double(degrees_of_freedom);
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = i; j < p; ++j) {
      if (parameters[i].fixed || parameters[j].fixed) continue;
      double value = 0;
      covariance.GetCovarianceBlock(blocks_of_theta[i], blocks_of_theta[j], &value);
      result.covariance[i * p + j] = result.covariance[j * p + i] = variance * value;
    }
  return result;
}

} // namespace impact::postprocess::detail
