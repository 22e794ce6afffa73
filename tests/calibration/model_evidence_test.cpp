// The evidence on a conjugate Gaussian model, where it is known exactly: theta ~ N(0, tau^2 I)
// in d dimensions, y_i ~ N(A_i theta, sigma^2), so that y ~ N(0, sigma^2 I + tau^2 A A^T).
// Laplace is exact for this Gaussian posterior; importance sampling must agree within its
// Monte Carlo error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "calibration/model_evidence.hpp"

using namespace rbcal::calibration;

TEST(ModelEvidence, ExactOnAConjugateGaussianModel) {
  const int d = 3, m = 12;
  const double tau = 2.0, sigma = 0.3;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd A(m, d);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < d; ++j) A(i, j) = normal(rng);
  Eigen::VectorXd truth(d);
  truth << 0.5, -1.0, 1.5;
  Eigen::VectorXd y = A * truth;
  for (int i = 0; i < m; ++i) y(i) += sigma * normal(rng);

  const double ln_2pi = std::log(2.0 * std::numbers::pi);
  const LogDensityFunction log_density = [&](const Eigen::VectorXd& theta) {
    const double prior = -0.5 * theta.squaredNorm() / (tau * tau) - d * std::log(tau) - 0.5 * d * ln_2pi;
    const double like = -0.5 * (y - A * theta).squaredNorm() / (sigma * sigma) - m * std::log(sigma) - 0.5 * m * ln_2pi;
    return prior + like;
  };
  // Exact: ln N(y; 0, sigma^2 I + tau^2 A A^T).
  const Eigen::MatrixXd C = sigma * sigma * Eigen::MatrixXd::Identity(m, m) + tau * tau * A * A.transpose();
  const Eigen::LLT<Eigen::MatrixXd> llt(C);
  const Eigen::MatrixXd L = llt.matrixL();
  const double exact = -0.5 * y.dot(llt.solve(y)) - L.diagonal().array().log().sum() - 0.5 * m * ln_2pi;

  // Posterior draws (what the MCMC would give): N(mu, Sigma) of the conjugate update.
  const Eigen::MatrixXd precision = A.transpose() * A / (sigma * sigma) + Eigen::MatrixXd::Identity(d, d) / (tau * tau);
  const Eigen::MatrixXd Sigma = precision.inverse();
  const Eigen::VectorXd mu = Sigma * A.transpose() * y / (sigma * sigma);
  const Eigen::MatrixXd S = Sigma.llt().matrixL();
  Eigen::MatrixXd draws(4000, d);
  for (int k = 0; k < draws.rows(); ++k) {
    Eigen::VectorXd z(d);
    for (int j = 0; j < d; ++j) z(j) = normal(rng);
    draws.row(k) = (mu + S * z).transpose();
  }
  const ModelEvidence e = model_evidence(log_density, draws);
  ASSERT_TRUE(e.laplace_ok);
  EXPECT_NEAR(e.laplace, exact, 1e-5) << e.line();
  EXPECT_NEAR(e.importance, exact, std::max(4.0 * e.importance_error, 1e-3)) << e.line();
  EXPECT_LT(e.importance_error, 0.05);
  EXPECT_GT(e.effective_samples, 1000.0);
  // A model that explains the data worse (a prior far off the truth) has a smaller evidence.
  const LogDensityFunction shifted = [&](const Eigen::VectorXd& theta) {
    return log_density(theta) - 0.5 * (theta - Eigen::VectorXd::Constant(d, 5.0)).squaredNorm() +
           0.5 * theta.squaredNorm() / (tau * tau) - 0.5 * d * ln_2pi + d * std::log(tau) + 0.5 * d * ln_2pi;
  };
  EXPECT_LT(model_evidence(shifted, draws).laplace, e.laplace);
}
