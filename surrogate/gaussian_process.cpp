#include "surrogate/gaussian_process.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rbcal::surrogate {

Eigen::VectorXd GaussianProcessHyperparameters::packed() const {
  const Eigen::Index d = log_length_scales.size();
  Eigen::VectorXd p(d + 2);
  p(0) = log_signal_variance;
  p.segment(1, d) = log_length_scales;
  p(d + 1) = log_nugget_variance;
  return p;
}

GaussianProcessHyperparameters GaussianProcessHyperparameters::unpacked(const Eigen::VectorXd& p) {
  if (p.size() < 3) throw std::invalid_argument("GaussianProcessHyperparameters: packed vector too short");
  const Eigen::Index d = p.size() - 2;
  return {p(0), p.segment(1, d), p(d + 1)};
}

Matern52Kernel GaussianProcessHyperparameters::kernel() const {
  return {std::exp(log_signal_variance), log_length_scales.array().exp().matrix()};
}

GaussianProcess::GaussianProcess(GaussianProcessData data, GaussianProcessHyperparameters hyperparameters)
    : data_(std::move(data)), hyperparameters_(std::move(hyperparameters)), kernel_(hyperparameters_.kernel()) {
  const Eigen::Index n = data_.inputs.rows(), d = data_.inputs.cols(), m = data_.basis.cols();
  if (n == 0 || data_.targets.size() != n || data_.noise_variances.size() != n || data_.basis.rows() != n)
    throw std::invalid_argument("GaussianProcess: inputs, targets, noise variances and basis differ in length");
  if (hyperparameters_.log_length_scales.size() != d)
    throw std::invalid_argument("GaussianProcess: one length scale per input dimension needed");
  if (m > n) throw std::invalid_argument("GaussianProcess: more mean basis functions than points");

  Eigen::MatrixXd k(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < i; ++j) k(i, j) = k(j, i) = kernel_(data_.inputs.row(i).transpose(), data_.inputs.row(j).transpose());
    k(i, i) = kernel_.signal_variance + total_noise_variance(i);
  }
  scaled_points_ = data_.inputs.transpose();
  for (Eigen::Index j = 0; j < d; ++j) scaled_points_.row(j) /= kernel_.length_scales(j);
  scaled_points_by_dimension_ = scaled_points_.transpose();
  k_cholesky_.compute(k);
  if (k_cholesky_.info() != Eigen::Success) throw std::runtime_error("GaussianProcess: covariance matrix not positive definite");
  k_inverse_basis_ = k_cholesky_.solve(data_.basis);
  a_cholesky_.compute(data_.basis.transpose() * k_inverse_basis_);
  if (a_cholesky_.info() != Eigen::Success)
    throw std::runtime_error("GaussianProcess: mean basis is rank deficient on the training inputs");
  const Eigen::VectorXd k_inverse_y = k_cholesky_.solve(data_.targets);
  beta_ = a_cholesky_.solve(data_.basis.transpose() * k_inverse_y);  // GLS, eq. 2.42's beta-bar
  alpha_ = k_inverse_y - k_inverse_basis_ * beta_;                    // P y
}

double GaussianProcess::total_noise_variance(Eigen::Index i) const {
  return data_.noise_variances(i) + std::exp(hyperparameters_.log_nugget_variance) + kGaussianProcessJitterVariance;
}

namespace {

// Squared scaled distance between the scaled query z and column i of the scaled points.
double scaled_distance_squared(const Eigen::VectorXd& z, const Eigen::MatrixXd& points, Eigen::Index i) {
  double r2 = 0.0;
  for (Eigen::Index j = 0; j < z.size(); ++j) {
    const double t = z(j) - points(j, i);
    r2 += t * t;
  }
  return r2;
}

// k between each row of a and each row of b (|a| x |b|), both scaled by the length scales, as
// vectorised array operations; derivative_factor, if given, receives the derivative factor.
Eigen::MatrixXd kernel_between(const Matern52Kernel& kernel, const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                               Eigen::MatrixXd* derivative_factor) {
  Eigen::MatrixXd k(a.rows(), b.rows());
  if (derivative_factor) derivative_factor->resize(a.rows(), b.rows());
  Eigen::ArrayXd r2(a.rows()), u(a.rows()), e(a.rows());
  const double root5 = std::sqrt(5.0);
  for (Eigen::Index j = 0; j < b.rows(); ++j) {
    r2.setZero();
    for (Eigen::Index d = 0; d < a.cols(); ++d) r2 += (a.col(d).array() - b(j, d)).square();
    u = root5 * r2.sqrt();
    e = (-u).exp();
    k.col(j) = kernel.value_from(u, e).matrix();
    if (derivative_factor) derivative_factor->col(j) = kernel.derivative_factor_from(u, e).matrix();
  }
  return k;
}

}  // namespace

Eigen::VectorXd GaussianProcess::cross_covariance(const Eigen::VectorXd& x) const {
  const Eigen::Index n = scaled_points_.cols();
  const Eigen::VectorXd z = x.cwiseQuotient(kernel_.length_scales);
  Eigen::VectorXd k_star(n);
  for (Eigen::Index i = 0; i < n; ++i) k_star(i) = kernel_.of_scaled_distance(std::sqrt(scaled_distance_squared(z, scaled_points_, i)));
  return k_star;
}

double GaussianProcess::variance_given(const Eigen::VectorXd& k_star, const Eigen::VectorXd& h_at_x) const {
  const Eigen::VectorXd v = k_cholesky_.matrixL().solve(k_star);
  const Eigen::VectorXd r = h_at_x - k_inverse_basis_.transpose() * k_star;  // R = h* - H^T K^-1 k*
  // eq. 2.42: cov = k** - k*^T K^-1 k* + R^T A^-1 R
  const double variance = kernel_.signal_variance - v.squaredNorm() + r.dot(a_cholesky_.solve(r));
  return std::max(variance, 0.0);
}

double GaussianProcess::latent_variance(const Eigen::VectorXd& x, const Eigen::VectorXd& h_at_x) const {
  return variance_given(cross_covariance(x), h_at_x);
}

GaussianProcessPredictions GaussianProcess::predict_many(const Eigen::MatrixXd& x_rows, const Eigen::MatrixXd& h_rows,
                                                         LatentCovariance covariance) const {
  const Eigen::Index q = x_rows.rows(), d = x_rows.cols();
  if (h_rows.rows() != q) throw std::invalid_argument("GaussianProcess: one basis row per query point needed");
  const Eigen::MatrixXd scaled = x_rows * kernel_.length_scales.cwiseInverse().asDiagonal();
  Eigen::MatrixXd factor;
  const Eigen::MatrixXd k_star = kernel_between(kernel_, scaled_points_by_dimension_, scaled, &factor);  // n x q
  GaussianProcessPredictions p;
  p.mean = h_rows * beta_ + k_star.transpose() * alpha_;  // eq. 2.41
  // d k_i / d x_j = -factor_i (z_j - p_ij) / l_j: sum_i alpha_i factor_i (z_j - p_ij), scaled by -1/l_j.
  const Eigen::VectorXd weight = factor.transpose() * alpha_;
  p.kernel_gradient.resize(q, d);
  for (Eigen::Index j = 0; j < d; ++j) {
    const Eigen::VectorXd weighted_point = factor.transpose() * alpha_.cwiseProduct(scaled_points_by_dimension_.col(j));
    p.kernel_gradient.col(j) = -(scaled.col(j).cwiseProduct(weight) - weighted_point) / kernel_.length_scales(j);
  }
  const Eigen::MatrixXd v = k_cholesky_.matrixL().solve(k_star);
  const Eigen::MatrixXd r = h_rows.transpose() - k_inverse_basis_.transpose() * k_star;  // R = h* - H^T K^-1 k*
  const Eigen::MatrixXd mean_part = a_cholesky_.matrixL().solve(r);                      // A = L_A L_A^T
  // eq. 2.42 at each point: k** - k*^T K^-1 k* + R^T A^-1 R
  const Eigen::VectorXd exact_variance =
      (kernel_.signal_variance - v.colwise().squaredNorm().array() + mean_part.colwise().squaredNorm().array())
          .matrix()
          .transpose();
  p.variance = exact_variance.cwiseMax(0.0);
  if (covariance == LatentCovariance::exact) {  // eq. 2.42 for every pair
    p.covariance.full = kernel_between(kernel_, scaled, scaled, nullptr);
    p.covariance.full.noalias() -= v.transpose() * v;
    p.covariance.full.noalias() += mean_part.transpose() * mean_part;
  } else if (covariance == LatentCovariance::low_rank) {
    // Pivoted Cholesky of eq. 2.42's matrix, one column at a time where the unexplained variance
    // is largest (Harbrecht, Peters & Schneider 2012, Appl. Numer. Math. 62:428), until none
    // exceeds kLowRankTolerance; the rest is kept on the diagonal.
    Eigen::VectorXd remaining = exact_variance.cwiseMax(0.0);
    const Eigen::Index most = std::min<Eigen::Index>(q, kLowRankMaxColumns);
    Eigen::MatrixXd g(q, most);
    Eigen::Index k = 0;
    for (; k < most; ++k) {
      Eigen::Index pivot = 0;
      const double largest = remaining.maxCoeff(&pivot);
      if (!(largest > kLowRankTolerance)) break;
      Eigen::VectorXd column = kernel_between(kernel_, scaled, scaled.row(pivot), nullptr);
      column.noalias() -= v.transpose() * v.col(pivot);
      column.noalias() += mean_part.transpose() * mean_part.col(pivot);
      column.noalias() -= g.leftCols(k) * g.row(pivot).head(k).transpose();
      g.col(k) = column / std::sqrt(largest);
      remaining -= g.col(k).cwiseAbs2();
      remaining(pivot) = 0.0;
    }
    p.covariance.factor = g.leftCols(k);
    p.covariance.diagonal = remaining.cwiseMax(0.0);
  }
  return p;
}

Eigen::MatrixXd GaussianProcess::latent_covariance(const Eigen::MatrixXd& x_rows, const Eigen::MatrixXd& h_rows) const {
  return predict_many(x_rows, h_rows, LatentCovariance::exact).covariance.full;
}

JointCovariance GaussianProcess::latent_covariance_factor(const Eigen::MatrixXd& x_rows, const Eigen::MatrixXd& h_rows) const {
  return predict_many(x_rows, h_rows, LatentCovariance::low_rank).covariance;
}

GaussianProcessPrediction GaussianProcess::predict(const Eigen::VectorXd& x, const Eigen::VectorXd& h_at_x,
                                                   const Eigen::MatrixXd& h_jacobian) const {
  const Eigen::Index n = scaled_points_.cols(), d = x.size();
  const Eigen::VectorXd z = x.cwiseQuotient(kernel_.length_scales);
  Eigen::VectorXd k_star(n);
  // d k / d x_j = -factor(r) (z_j - p_j) / l_j: accumulate sum_i alpha_i (z_j - p_ij) factor_i, scale by -1/l_j.
  Eigen::VectorXd weighted(d);
  weighted.setZero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = std::sqrt(scaled_distance_squared(z, scaled_points_, i));
    k_star(i) = kernel_.of_scaled_distance(r);
    const double w = alpha_(i) * kernel_.derivative_factor(r);
    for (Eigen::Index j = 0; j < d; ++j) weighted(j) += w * (z(j) - scaled_points_(j, i));
  }
  GaussianProcessPrediction p;
  p.mean = h_at_x.dot(beta_) + k_star.dot(alpha_);  // eq. 2.41: h*^T beta + k*^T K^-1 (y - H beta)
  p.variance = variance_given(k_star, h_at_x);
  p.mean_gradient = h_jacobian.transpose() * beta_ - weighted.cwiseQuotient(kernel_.length_scales);
  return p;
}

Eigen::MatrixXd GaussianProcess::mean_coefficient_covariance() const {
  const Eigen::Index m = data_.basis.cols();
  return a_cholesky_.solve(Eigen::MatrixXd::Identity(m, m));
}

Eigen::MatrixXd GaussianProcess::projection() const {
  const Eigen::Index n = data_.inputs.rows();
  const Eigen::MatrixXd k_inverse = k_cholesky_.solve(Eigen::MatrixXd::Identity(n, n));
  return k_inverse - k_inverse_basis_ * a_cholesky_.solve(k_inverse_basis_.transpose());
}

double GaussianProcess::log_marginal_likelihood() const {
  const double n = static_cast<double>(data_.inputs.rows()), m = static_cast<double>(data_.basis.cols());
  const double log_det_k = 2.0 * k_cholesky_.matrixLLT().diagonal().array().log().sum();
  const double log_det_a = 2.0 * a_cholesky_.matrixLLT().diagonal().array().log().sum();
  return -0.5 * data_.targets.dot(alpha_) - 0.5 * log_det_k - 0.5 * log_det_a -
         0.5 * (n - m) * std::log(2.0 * std::numbers::pi);
}

Eigen::VectorXd GaussianProcess::log_marginal_likelihood_gradient() const {
  const Eigen::Index n = data_.inputs.rows(), d = data_.inputs.cols();
  // W = alpha alpha^T - P; gradient_j = 1/2 sum_ab W_ab dK_ab/d theta_j (W and dK symmetric).
  const Eigen::MatrixXd w = alpha_ * alpha_.transpose() - projection();
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(d + 2);
  const double nugget = std::exp(hyperparameters_.log_nugget_variance);
  for (Eigen::Index a = 0; a < n; ++a) {
    gradient(0) += 0.5 * w(a, a) * kernel_.signal_variance;  // dK/d ln s2 = k (diagonal: s2)
    gradient(d + 1) += 0.5 * w(a, a) * nugget;                // dK/d ln nugget = nugget I
    for (Eigen::Index b = 0; b < a; ++b) {
      const Eigen::VectorXd xa = data_.inputs.row(a).transpose(), xb = data_.inputs.row(b).transpose();
      gradient(0) += w(a, b) * kernel_(xa, xb);  // off-diagonal pairs counted twice, times 1/2
      gradient.segment(1, d) += w(a, b) * kernel_.log_length_scale_derivatives(xa, xb);
    }
  }
  return gradient;
}

LeaveOneOutPredictions GaussianProcess::leave_one_out() const {
  const Eigen::VectorXd p_diagonal = projection().diagonal();
  LeaveOneOutPredictions loo;
  loo.variance = p_diagonal.cwiseInverse();                                  // eq. 5.12: 1 / [K^-1]_ii
  loo.mean = data_.targets - alpha_.cwiseQuotient(p_diagonal);               // eq. 5.12: y_i - [K^-1 y]_i / [K^-1]_ii
  return loo;
}

}  // namespace rbcal::surrogate
