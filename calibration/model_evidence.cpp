#include "calibration/model_evidence.hpp"

#include "calibration/detail/independence_sampler.hpp"
#include "formats/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace rbcal::calibration {

namespace {

constexpr double kDegreesOfFreedom = 4.0;

// f at every point, in parallel (the results in the points' order).
std::vector<double> evaluate_all(const LogDensityFunction& f, const std::vector<Eigen::VectorXd>& points, int threads) {
  std::vector<double> values(points.size());
  formats::parallel_for(static_cast<std::ptrdiff_t>(points.size()), threads,
                        [&](std::ptrdiff_t k) { values[static_cast<std::size_t>(k)] = f(points[static_cast<std::size_t>(k)]); });
  return values;
}

// Central-difference Hessian of f at x with steps h (f0 = f(x)).
Eigen::MatrixXd hessian(const LogDensityFunction& f, const Eigen::VectorXd& x, double f0, const Eigen::VectorXd& h,
                        int threads) {
  const Eigen::Index d = x.size();
  std::vector<Eigen::VectorXd> points;
  for (Eigen::Index i = 0; i < d; ++i) {
    for (const double s : {1.0, -1.0}) {
      points.push_back(x);
      points.back()(i) += s * h(i);
    }
    for (Eigen::Index j = 0; j < i; ++j)
      for (const double si : {1.0, -1.0})
        for (const double sj : {1.0, -1.0}) {
          points.push_back(x);
          points.back()(i) += si * h(i), points.back()(j) += sj * h(j);
        }
  }
  const std::vector<double> v = evaluate_all(f, points, threads);
  Eigen::MatrixXd H(d, d);
  std::size_t k = 0;
  for (Eigen::Index i = 0; i < d; ++i) {
    H(i, i) = (v[k] - 2.0 * f0 + v[k + 1]) / (h(i) * h(i));
    k += 2;
    for (Eigen::Index j = 0; j < i; ++j, k += 4)  // (++) - (+-) - (-+) + (--)
      H(i, j) = H(j, i) = (v[k] - v[k + 1] - v[k + 2] + v[k + 3]) / (4.0 * h(i) * h(j));
  }
  return H;
}

Eigen::VectorXd gradient(const LogDensityFunction& f, const Eigen::VectorXd& x, const Eigen::VectorXd& h, int threads) {
  std::vector<Eigen::VectorXd> points;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    for (const double s : {1.0, -1.0}) {
      points.push_back(x);
      points.back()(i) += s * h(i);
    }
  const std::vector<double> v = evaluate_all(f, points, threads);
  Eigen::VectorXd g(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) g(i) = (v[2 * i] - v[2 * i + 1]) / (2.0 * h(i));
  return g;
}

// ln Z from log importance weights: ln of their mean, its Monte Carlo sd (delta method) and
// the weights' effective sample size; false when no weight is positive.
bool importance_estimate(const std::vector<double>& log_w, ModelEvidence& out) {
  const double top = log_w.empty() ? -std::numeric_limits<double>::infinity() : *std::max_element(log_w.begin(), log_w.end());
  if (!std::isfinite(top)) return false;
  double sum = 0.0, sum_sq = 0.0;
  for (double lw : log_w) {
    const double w = std::exp(lw - top);
    sum += w, sum_sq += w * w;
  }
  const double K = static_cast<double>(log_w.size());
  const double mean_w = sum / K;
  const double var_w = std::max(0.0, sum_sq / K - mean_w * mean_w);
  out.importance = top + std::log(mean_w);
  out.importance_error = std::sqrt(var_w / K) / mean_w;
  out.effective_samples = sum * sum / sum_sq;
  out.samples = static_cast<int>(log_w.size());
  return true;
}

}  // namespace

std::string ModelEvidence::line() const {
  char laplace_text[32] = "none";
  if (laplace_ok) std::snprintf(laplace_text, sizeof laplace_text, "%.4g", laplace);
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "ln Z %s (Laplace), %.4g +- %.2g (importance sampling, %d draws of %s, ESS %.0f)",
                laplace_text, importance, importance_error, samples, importance_source.c_str(), effective_samples);
  return buffer;
}

nlohmann::json ModelEvidence::to_json() const {
  nlohmann::json j = {{"importance_sampling", importance},
                      {"importance_sampling_error", importance_error},
                      {"importance_effective_samples", effective_samples},
                      {"importance_draws", samples},
                      {"importance_source", importance_source}};
  j["laplace"] = laplace_ok ? nlohmann::json(laplace) : nlohmann::json(nullptr);
  return j;
}

ModelEvidence model_evidence(const LogDensityFunction& log_density, const Eigen::MatrixXd& draws,
                             const ModelEvidenceOptions& options, const SamplerByproducts& known) {
  const Eigen::VectorXd& draw_log_densities = known.draw_log_densities;
  const Eigen::Index d = draws.cols(), n = draws.rows();
  if (d < 1 || n < d + 2) throw std::invalid_argument("model evidence: need at least dimension + 2 posterior draws");
  if (draw_log_densities.size() != 0 && draw_log_densities.size() != n)
    throw std::invalid_argument("model evidence: one log density per draw, or none");
  const int threads =
#ifdef _OPENMP
      options.threads > 0 ? options.threads : omp_get_max_threads();
#else
      1;
#endif
  const Eigen::RowVectorXd mean = draws.colwise().mean();
  const Eigen::MatrixXd centred = draws.rowwise() - mean;
  const Eigen::MatrixXd covariance = centred.transpose() * centred / static_cast<double>(n - 1);
  const Eigen::VectorXd scale = covariance.diagonal().cwiseSqrt().cwiseMax(1e-12);
  ModelEvidence out;

  // Laplace: the best draw (of all, when their log densities are known; else of a thinned set),
  // refined by damped Newton steps.
  Eigen::VectorXd mode = draws.row(0).transpose();
  double best = -std::numeric_limits<double>::infinity();
  if (draw_log_densities.size() != 0) {
    for (Eigen::Index k = 0; k < n; ++k)
      if (draw_log_densities(k) > best) best = draw_log_densities(k), mode = draws.row(k).transpose();
  } else {
    const Eigen::Index candidates = std::min<Eigen::Index>(n, std::max(1, options.mode_candidates));
    std::vector<Eigen::VectorXd> points;
    for (Eigen::Index k = 0; k < candidates; ++k) points.push_back(draws.row(k * n / candidates).transpose());
    const std::vector<double> v = evaluate_all(log_density, points, threads);
    for (std::size_t k = 0; k < points.size(); ++k)
      if (v[k] > best) best = v[k], mode = points[k];
  }
  const Eigen::VectorXd h = 1e-3 * scale;
  Eigen::MatrixXd H = hessian(log_density, mode, best, h, threads);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Eigen::LLT<Eigen::MatrixXd> negative(-H);
    if (negative.info() != Eigen::Success) break;
    const Eigen::VectorXd step = negative.solve(gradient(log_density, mode, h, threads));
    double t = 1.0;
    bool moved = false;
    for (int halving = 0; halving < 20; ++halving, t *= 0.5) {
      const Eigen::VectorXd next = mode + t * step;
      const double v = log_density(next);
      if (std::isfinite(v) && v >= best) {
        moved = v > best + 1e-12;
        mode = next, best = v;
        break;
      }
    }
    H = hessian(log_density, mode, best, h, threads);
    if (!moved || step.cwiseQuotient(scale).norm() < 1e-6) break;
  }
  const Eigen::LLT<Eigen::MatrixXd> at_mode(-H);
  if (at_mode.info() == Eigen::Success && std::isfinite(best)) {
    const Eigen::MatrixXd L = at_mode.matrixL();
    const double ln_det_precision = 2.0 * L.diagonal().array().log().sum();
    out.laplace = best + 0.5 * static_cast<double>(d) * std::log(2.0 * std::numbers::pi) - 0.5 * ln_det_precision;
    out.laplace_ok = std::isfinite(out.laplace);
  }

  if (!known.importance_log_weights.empty()) {
    if (!importance_estimate(known.importance_log_weights, out))
      throw std::invalid_argument("model evidence: no importance draw inside the posterior's support");
    out.importance_source = known.importance_source;
    return out;
  }

  // Importance sampling from a t of the draws' mean and covariance, 1.2 times as wide.
  const double nu = kDegreesOfFreedom;
  const Eigen::MatrixXd shape = covariance * (1.2 * 1.2 * (nu - 2.0) / nu);
  if (Eigen::LLT<Eigen::MatrixXd>(shape).info() != Eigen::Success)
    throw std::invalid_argument("model evidence: the draws' covariance is singular");
  const MultivariateT proposal(mean.transpose(), shape, nu);
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  std::chi_squared_distribution<double> chi2(nu);
  const int k_max = std::max(2, options.importance_samples);
  const int batch = std::max(2, options.importance_batch);
  std::vector<double> log_w;
  log_w.reserve(static_cast<std::size_t>(k_max));
  bool any = false;
  while (static_cast<int>(log_w.size()) < k_max) {
    // The batch's points are drawn in order, then evaluated in parallel: the same numbers for
    // any number of threads.
    std::vector<Eigen::VectorXd> points;
    std::vector<double> ln_q;
    for (int k = 0; k < batch && static_cast<int>(log_w.size() + points.size()) < k_max; ++k) {
      Eigen::VectorXd z(d);
      for (Eigen::Index i = 0; i < d; ++i) z(i) = normal(rng);
      points.push_back(proposal.from_standard(z, chi2(rng)));
      ln_q.push_back(proposal.log_normaliser() + proposal.log_density(points.back()));
    }
    const std::vector<double> ln_p = evaluate_all(log_density, points, threads);
    for (std::size_t k = 0; k < points.size(); ++k)
      log_w.push_back(std::isfinite(ln_p[k]) ? ln_p[k] - ln_q[k] : -std::numeric_limits<double>::infinity());
    any = importance_estimate(log_w, out);
    if (any && out.importance_error < options.importance_target_error) break;
  }
  if (!any) throw std::invalid_argument("model evidence: no importance draw inside the posterior's support");
  out.importance_source = "a t fitted to the posterior draws";
  return out;
}

}  // namespace rbcal::calibration
