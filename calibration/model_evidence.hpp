#pragma once
// The evidence ln Z = ln integral p(data | theta) p(theta) dtheta of a calibration, the number
// that ranks models (lambda fixed against fitted, one level mapping against another) on the
// same data: the larger, the better the model explains them, its flexibility paid for. Two
// estimates of the same integral, so that a user sees when they disagree:
//  - Laplace: ln p at the posterior's mode + (d/2) ln 2 pi + (1/2) ln det Sigma, with Sigma the
//    inverse of the negative Hessian there (finite differences, the mode refined by Newton steps
//    from the best posterior draw); exact for a Gaussian posterior;
//  - importance sampling, with its Monte Carlo error and the weights' effective sample size:
//    of the independence sampler's proposals when the MCMC ran one (draws of a t near the
//    posterior whose densities it evaluated anyway), else from a multivariate t (4 degrees of
//    freedom) fitted to the posterior draws, drawn in batches until that error is small enough
//    (or a cap), each batch evaluated in parallel.
// The log density must be normalised (priors and likelihood with their constants), as
// LogPosterior is.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

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
  std::string importance_source;  // where the importance draws came from, in words
  std::string line() const;
  nlohmann::json to_json() const;
};

struct ModelEvidenceOptions {
  int importance_samples = 4000;  // at most
  int importance_batch = 500;     // drawn, then evaluated together; the stop is checked after each
  // Stop once the Monte Carlo sd of ln Z is below this (0: draw all importance_samples). A few
  // hundredths of a nat is far below the differences in ln Z that rank models.
  double importance_target_error = 0.03;
  int mode_candidates = 400;  // posterior draws searched for the best start of the mode search
  std::uint64_t seed = 13;
  int threads = 0;  // OpenMP threads (0: OpenMP's default); the log density must be thread-safe
};

using LogDensityFunction = std::function<double(const Eigen::VectorXd&)>;

// What a sampler already knows, sparing evaluations: the draws' log densities (no mode
// candidates to evaluate), and an importance sample of the posterior, ln p - ln q of draws of a
// normalised density q (no importance draws to make).
struct SamplerByproducts {
  Eigen::VectorXd draw_log_densities;           // one per row of draws, or empty
  std::vector<double> importance_log_weights;   // or empty
  std::string importance_source;                // what q was, in words
};

// draws: posterior draws, one per row (at least dimension + 2 rows).
ModelEvidence model_evidence(const LogDensityFunction& log_density, const Eigen::MatrixXd& draws,
                             const ModelEvidenceOptions& options = {}, const SamplerByproducts& known = {});

}  // namespace rbcal::calibration
