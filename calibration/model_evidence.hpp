#pragma once
// The evidence ln Z = ln integral p(data | theta) p(theta) dtheta of a calibration, the number
// that ranks models (lambda fixed against fitted, one level mapping against another) on the
// same data: the larger, the better the model explains them, its flexibility paid for. Two
// estimates of the same integral, so that a user sees when they disagree:
//  - Laplace: ln p at the posterior's mode + (d/2) ln 2 pi + (1/2) ln det Sigma, with Sigma the
//    inverse of the negative Hessian there (finite differences, the mode refined by Newton steps
//    from the best posterior draw); exact for a Gaussian posterior;
//  - importance sampling from a multivariate t (4 degrees of freedom) fitted to the posterior
//    draws, with its Monte Carlo error and the weights' effective sample size.
// The log density must be normalised (priors and likelihood with their constants), as
// LogPosterior is.
#include <cstdint>
#include <functional>
#include <string>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace rbcal::calibration {

struct ModelEvidence {
  double laplace = 0.0;
  bool laplace_ok = false;      // false: no negative-definite Hessian at the mode
  double importance = 0.0;
  double importance_error = 0.0;  // Monte Carlo sd of the importance estimate of ln Z
  double effective_samples = 0.0;  // (sum w)^2 / sum w^2 of the importance weights
  int samples = 0;
  std::string line() const;
  nlohmann::json to_json() const;
};

struct ModelEvidenceOptions {
  int importance_samples = 4000;
  int mode_candidates = 400;  // posterior draws searched for the best start of the mode search
  std::uint64_t seed = 13;
};

using LogDensityFunction = std::function<double(const Eigen::VectorXd&)>;

// draws: posterior draws, one per row (at least dimension + 2 rows).
ModelEvidence model_evidence(const LogDensityFunction& log_density, const Eigen::MatrixXd& draws,
                             const ModelEvidenceOptions& options = {});

}  // namespace rbcal::calibration
