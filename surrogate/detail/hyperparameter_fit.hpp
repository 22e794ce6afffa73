#pragma once
// Type-II maximum likelihood for the Gaussian-process hyper-parameters (Rasmussen &
// Williams 2006, section 5.4.1): maximise the restricted log marginal likelihood
// (GaussianProcess::log_marginal_likelihood) over the packed log-parameters with Ceres'
// line-search L-BFGS and the analytic gradient, from a few deterministic starting points,
// keeping the best. Parameters may be held fixed (e.g. the length scale of an input that
// is constant over the library). Soft bounds: outside [lower, upper] a quadratic penalty
// 50 (excess)^2 is added to -log L, which leaves the likelihood untouched inside the box
// and stops flat directions (nugget -> 0, length -> infinity) from drifting.
#include <string>
#include <vector>

#include "surrogate/gaussian_process.hpp"

namespace rbcal::surrogate {

struct HyperparameterFitOptions {
  Eigen::VectorXd lower;                 // packed log-parameters
  Eigen::VectorXd upper;
  std::vector<bool> free;                // false: held at its value in each start
  std::vector<Eigen::VectorXd> starts;   // packed starting points, tried in order
  int max_iterations = 300;
};

struct HyperparameterFitResult {
  GaussianProcessHyperparameters hyperparameters;
  double log_marginal_likelihood = 0.0;
  int starts_tried = 0;
  int starts_converged = 0;  // Ceres reported CONVERGENCE
  std::string summary;       // one line per start
};

// Default options for inputs spanning `input_ranges` (max - min per dimension; a zero range
// fixes that length scale at 1) and targets of variance `target_variance`: length scales
// bounded to [0.05, 20] x range, started at {0.3, 1, 3} x range; signal variance bounded to
// [1e-10, 1e3], started at max(target_variance, 1e-6); nugget bounded to [1e-12, 1] (sd 1e-6
// to 1 in y), started at 1e-6.
HyperparameterFitOptions default_hyperparameter_fit_options(const Eigen::VectorXd& input_ranges, double target_variance);

// Throws std::runtime_error if no start gives a finite likelihood.
HyperparameterFitResult fit_hyperparameters(const GaussianProcessData& data, const HyperparameterFitOptions& options);

}  // namespace rbcal::surrogate
