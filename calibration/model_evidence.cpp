#include "calibration/model_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace rbcal::calibration {

namespace {

constexpr double kDegreesOfFreedom = 4.0;

// Central-difference Hessian of f at x with steps h.
Eigen::MatrixXd hessian(const LogDensityFunction& f, const Eigen::VectorXd& x, const Eigen::VectorXd& h) {
  const Eigen::Index d = x.size();
  Eigen::MatrixXd H(d, d);
  const double f0 = f(x);
  for (Eigen::Index i = 0; i < d; ++i) {
    Eigen::VectorXd a = x, b = x;
    a(i) += h(i);
    b(i) -= h(i);
    H(i, i) = (f(a) - 2.0 * f0 + f(b)) / (h(i) * h(i));
    for (Eigen::Index j = 0; j < i; ++j) {
      Eigen::VectorXd pp = x, pm = x, mp = x, mm = x;
      pp(i) += h(i), pp(j) += h(j);
      pm(i) += h(i), pm(j) -= h(j);
      mp(i) -= h(i), mp(j) += h(j);
      mm(i) -= h(i), mm(j) -= h(j);
      H(i, j) = H(j, i) = (f(pp) - f(pm) - f(mp) + f(mm)) / (4.0 * h(i) * h(j));
    }
  }
  return H;
}

Eigen::VectorXd gradient(const LogDensityFunction& f, const Eigen::VectorXd& x, const Eigen::VectorXd& h) {
  Eigen::VectorXd g(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd a = x, b = x;
    a(i) += h(i);
    b(i) -= h(i);
    g(i) = (f(a) - f(b)) / (2.0 * h(i));
  }
  return g;
}

}  // namespace

std::string ModelEvidence::line() const {
  char laplace_text[32] = "none";
  if (laplace_ok) std::snprintf(laplace_text, sizeof laplace_text, "%.4g", laplace);
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "ln Z %s (Laplace), %.4g +- %.2g (importance sampling, %d draws, ESS %.0f)",
                laplace_text, importance, importance_error, samples, effective_samples);
  return buffer;
}

nlohmann::json ModelEvidence::to_json() const {
  nlohmann::json j = {{"importance_sampling", importance},
                      {"importance_sampling_error", importance_error},
                      {"importance_effective_samples", effective_samples},
                      {"importance_draws", samples}};
  j["laplace"] = laplace_ok ? nlohmann::json(laplace) : nlohmann::json(nullptr);
  return j;
}

ModelEvidence model_evidence(const LogDensityFunction& log_density, const Eigen::MatrixXd& draws,
                             const ModelEvidenceOptions& options) {
  const Eigen::Index d = draws.cols(), n = draws.rows();
  if (d < 1 || n < d + 2) throw std::invalid_argument("model evidence: need at least dimension + 2 posterior draws");
  const Eigen::RowVectorXd mean = draws.colwise().mean();
  const Eigen::MatrixXd centred = draws.rowwise() - mean;
  const Eigen::MatrixXd covariance = centred.transpose() * centred / static_cast<double>(n - 1);
  const Eigen::VectorXd scale = covariance.diagonal().cwiseSqrt().cwiseMax(1e-12);
  ModelEvidence out;

  // Laplace: the best of a thinned set of draws, refined by damped Newton steps.
  Eigen::VectorXd mode = draws.row(0).transpose();
  double best = -std::numeric_limits<double>::infinity();
  const Eigen::Index candidates = std::min<Eigen::Index>(n, std::max(1, options.mode_candidates));
  for (Eigen::Index k = 0; k < candidates; ++k) {
    const Eigen::VectorXd x = draws.row(k * n / candidates).transpose();
    const double v = log_density(x);
    if (v > best) best = v, mode = x;
  }
  const Eigen::VectorXd h = 1e-3 * scale;
  Eigen::MatrixXd H = hessian(log_density, mode, h);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Eigen::LLT<Eigen::MatrixXd> negative(-H);
    if (negative.info() != Eigen::Success) break;
    const Eigen::VectorXd step = negative.solve(gradient(log_density, mode, h));
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
    H = hessian(log_density, mode, h);
    if (!moved || step.cwiseQuotient(scale).norm() < 1e-6) break;
  }
  const Eigen::LLT<Eigen::MatrixXd> at_mode(-H);
  if (at_mode.info() == Eigen::Success && std::isfinite(best)) {
    const Eigen::MatrixXd L = at_mode.matrixL();
    const double ln_det_precision = 2.0 * L.diagonal().array().log().sum();
    out.laplace = best + 0.5 * static_cast<double>(d) * std::log(2.0 * std::numbers::pi) - 0.5 * ln_det_precision;
    out.laplace_ok = std::isfinite(out.laplace);
  }

  // Importance sampling from a t of the draws' mean and covariance, 1.2 times as wide.
  const double nu = kDegreesOfFreedom;
  const Eigen::MatrixXd shape = covariance * (1.2 * 1.2 * (nu - 2.0) / nu);
  const Eigen::LLT<Eigen::MatrixXd> shape_llt(shape);
  if (shape_llt.info() != Eigen::Success) throw std::invalid_argument("model evidence: the draws' covariance is singular");
  const Eigen::MatrixXd S = shape_llt.matrixL();
  const double ln_det_shape = 2.0 * S.diagonal().array().log().sum();
  const double dd = static_cast<double>(d);
  const double ln_norm = std::lgamma(0.5 * (nu + dd)) - std::lgamma(0.5 * nu) - 0.5 * dd * std::log(nu * std::numbers::pi) -
                         0.5 * ln_det_shape;
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  std::chi_squared_distribution<double> chi2(nu);
  const int k_max = std::max(2, options.importance_samples);
  std::vector<double> log_w;
  log_w.reserve(static_cast<std::size_t>(k_max));
  for (int k = 0; k < k_max; ++k) {
    Eigen::VectorXd z(d);
    for (Eigen::Index i = 0; i < d; ++i) z(i) = normal(rng);
    const double u = chi2(rng);
    const Eigen::VectorXd x = mean.transpose() + S * z * std::sqrt(nu / u);
    const Eigen::VectorXd delta = shape_llt.matrixL().solve(x - mean.transpose());
    const double ln_q = ln_norm - 0.5 * (nu + dd) * std::log1p(delta.squaredNorm() / nu);
    const double ln_p = log_density(x);
    log_w.push_back(std::isfinite(ln_p) ? ln_p - ln_q : -std::numeric_limits<double>::infinity());
  }
  const double top = *std::max_element(log_w.begin(), log_w.end());
  if (!std::isfinite(top)) throw std::invalid_argument("model evidence: no importance draw inside the posterior's support");
  double sum = 0.0, sum_sq = 0.0;
  for (double lw : log_w) {
    const double w = std::exp(lw - top);
    sum += w, sum_sq += w * w;
  }
  const double K = static_cast<double>(k_max);
  const double mean_w = sum / K;
  const double var_w = std::max(0.0, sum_sq / K - mean_w * mean_w);
  out.importance = top + std::log(mean_w);
  out.importance_error = std::sqrt(var_w / K) / mean_w;  // sd of ln(mean w), delta method
  out.effective_samples = sum * sum / sum_sq;
  out.samples = k_max;
  return out;
}

}  // namespace rbcal::calibration
