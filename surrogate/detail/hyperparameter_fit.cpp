#include "surrogate/detail/hyperparameter_fit.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rbcal::surrogate {

namespace {

constexpr double kBoundPenaltyWeight = 50.0;

// -log L (plus the soft-bound penalty) as a function of the free packed parameters.
class NegativeLogMarginalLikelihood final : public ceres::FirstOrderFunction {
 public:
  NegativeLogMarginalLikelihood(const GaussianProcessData& data, const HyperparameterFitOptions& options,
                                Eigen::VectorXd start)
      : data_(data), options_(options), full_(std::move(start)) {
    for (std::size_t i = 0; i < options_.free.size(); ++i)
      if (options_.free[i]) free_index_.push_back(static_cast<Eigen::Index>(i));
  }

  int NumParameters() const override { return static_cast<int>(free_index_.size()); }

  Eigen::VectorXd expand(const double* free_values) const {
    Eigen::VectorXd p = full_;
    for (std::size_t k = 0; k < free_index_.size(); ++k) p(free_index_[k]) = free_values[k];
    return p;
  }

  bool Evaluate(const double* parameters, double* cost, double* gradient) const override {
    const Eigen::VectorXd p = expand(parameters);
    double value = 0.0;
    Eigen::VectorXd full_gradient;
    try {
      const GaussianProcess gp(data_, GaussianProcessHyperparameters::unpacked(p));
      value = -gp.log_marginal_likelihood();
      if (gradient) full_gradient = -gp.log_marginal_likelihood_gradient();
    } catch (const std::runtime_error&) {
      return false;  // not positive definite here: the line search steps back
    }
    if (!std::isfinite(value)) return false;
    for (std::size_t k = 0; k < free_index_.size(); ++k) {
      const Eigen::Index i = free_index_[k];
      const double excess = p(i) > options_.upper(i) ? p(i) - options_.upper(i)
                            : p(i) < options_.lower(i) ? p(i) - options_.lower(i)
                                                       : 0.0;
      value += kBoundPenaltyWeight * excess * excess;
      if (gradient) gradient[k] = full_gradient(i) + 2.0 * kBoundPenaltyWeight * excess;
    }
    *cost = value;
    return true;
  }

 private:
  const GaussianProcessData& data_;
  const HyperparameterFitOptions& options_;
  Eigen::VectorXd full_;
  std::vector<Eigen::Index> free_index_;
};

}  // namespace

HyperparameterFitOptions default_hyperparameter_fit_options(const Eigen::VectorXd& input_ranges, double target_variance) {
  const Eigen::Index d = input_ranges.size(), n = d + 2;
  HyperparameterFitOptions o;
  o.lower = Eigen::VectorXd(n);
  o.upper = Eigen::VectorXd(n);
  o.free.assign(static_cast<std::size_t>(n), true);
  o.lower(0) = std::log(1e-10), o.upper(0) = std::log(1e3);
  o.lower(d + 1) = std::log(1e-12), o.upper(d + 1) = 0.0;
  for (Eigen::Index i = 0; i < d; ++i) {
    const double range = input_ranges(i);
    if (range > 0.0) {
      o.lower(1 + i) = std::log(0.05 * range), o.upper(1 + i) = std::log(20.0 * range);
    } else {
      o.lower(1 + i) = o.upper(1 + i) = 0.0;
      o.free[static_cast<std::size_t>(1 + i)] = false;
    }
  }
  for (double factor : {1.0, 0.3, 3.0}) {
    Eigen::VectorXd s(n);
    s(0) = std::log(std::max(target_variance, 1e-6));
    for (Eigen::Index i = 0; i < d; ++i) s(1 + i) = input_ranges(i) > 0.0 ? std::log(factor * input_ranges(i)) : 0.0;
    s(d + 1) = std::log(1e-6);
    o.starts.push_back(s);
  }
  return o;
}

HyperparameterFitResult fit_hyperparameters(const GaussianProcessData& data, const HyperparameterFitOptions& options) {
  HyperparameterFitResult best;
  best.log_marginal_likelihood = -std::numeric_limits<double>::infinity();
  std::ostringstream summary;
  bool found = false;
  for (const Eigen::VectorXd& start : options.starts) {
    ++best.starts_tried;
    auto* objective = new NegativeLogMarginalLikelihood(data, options, start);  // owned by the problem
    ceres::GradientProblem problem(objective);
    std::vector<double> x;
    for (std::size_t i = 0; i < options.free.size(); ++i)
      if (options.free[i]) x.push_back(start(static_cast<Eigen::Index>(i)));
    ceres::GradientProblemSolver::Options solver_options;
    solver_options.line_search_direction_type = ceres::LBFGS;
    solver_options.max_num_iterations = options.max_iterations;
    solver_options.function_tolerance = 1e-10;
    solver_options.gradient_tolerance = 1e-8;
    solver_options.parameter_tolerance = 1e-10;
    solver_options.logging_type = ceres::SILENT;
    ceres::GradientProblemSolver::Summary solver_summary;
    ceres::Solve(solver_options, problem, x.data(), &solver_summary);
    const Eigen::VectorXd p = objective->expand(x.data());
    summary << "start " << best.starts_tried << ": " << solver_summary.message << " after "
            << solver_summary.iterations.size() << " iterations";
    if (!solver_summary.IsSolutionUsable()) {
      summary << " (unusable)\n";
      continue;
    }
    if (solver_summary.termination_type == ceres::CONVERGENCE) ++best.starts_converged;
    double log_likelihood = -std::numeric_limits<double>::infinity();
    try {
      log_likelihood = GaussianProcess(data, GaussianProcessHyperparameters::unpacked(p)).log_marginal_likelihood();
    } catch (const std::runtime_error&) {
    }
    summary << ", log L = " << log_likelihood << "\n";
    if (std::isfinite(log_likelihood) && log_likelihood > best.log_marginal_likelihood) {
      best.log_marginal_likelihood = log_likelihood;
      best.hyperparameters = GaussianProcessHyperparameters::unpacked(p);
      found = true;
    }
  }
  best.summary = summary.str();
  if (!found) throw std::runtime_error("hyper-parameter fit: no starting point gave a finite marginal likelihood:\n" + best.summary);
  return best;
}

}  // namespace rbcal::surrogate
