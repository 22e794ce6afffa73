// Whitening a diagonal plus a low-rank factor (Woodbury, determinant lemma) against the dense
// Cholesky path on the same matrix.
#include "calibration/joint_likelihood.hpp"

#include <gtest/gtest.h>

#include <random>

namespace rbcal::calibration {
namespace {

JointResiduals random_low_rank(Eigen::Index n, Eigen::Index rank, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  JointResiduals j;
  j.residual.resize(n);
  j.covariance.diagonal.resize(n);
  j.covariance.factor.resize(n, rank);
  for (Eigen::Index i = 0; i < n; ++i) {
    j.residual(i) = normal(rng);
    j.covariance.diagonal(i) = 0.01 * (1.0 + std::abs(normal(rng)));
    for (Eigen::Index k = 0; k < rank; ++k) j.covariance.factor(i, k) = 0.3 * normal(rng);
  }
  return j;
}

TEST(JointLikelihood, LowRankWhiteningIsTheDenseLikelihood) {
  const JointResiduals low = random_low_rank(60, 12, 1);
  ASSERT_FALSE(low.covariance.dense_is_cheaper());
  JointResiduals dense;
  dense.residual = low.residual;
  dense.covariance.full = low.covariance.dense();
  ASSERT_TRUE(dense.covariance.dense_is_cheaper());
  const WhitenedResiduals a = whiten(low), b = whiten(dense);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_NEAR(a.whitened.squaredNorm(), b.whitened.squaredNorm(), 1e-9 * b.whitened.squaredNorm());
  EXPECT_NEAR(a.log_determinant, b.log_determinant, 1e-9 * std::abs(b.log_determinant));
  EXPECT_NEAR(a.log_likelihood(), b.log_likelihood(), 1e-9 * std::abs(b.log_likelihood()));
  EXPECT_NEAR(joint_log_likelihood(low), b.log_likelihood(), 1e-9 * std::abs(b.log_likelihood()));
  EXPECT_EQ(joint_log_likelihood(dense), b.log_likelihood());
}

// W Sigma W^T = I for the map r -> whitened: the whitened residuals are independent with unit variance.
TEST(JointLikelihood, LowRankWhiteningMapsSigmaToTheIdentity) {
  JointResiduals j = random_low_rank(30, 5, 2);
  const Eigen::Index n = j.residual.size();
  Eigen::MatrixXd w(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    j.residual = Eigen::VectorXd::Unit(n, i);
    w.col(i) = whiten(j).whitened;
  }
  const Eigen::MatrixXd identity = w * j.covariance.dense() * w.transpose();
  EXPECT_LT((identity - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(JointLikelihood, IndependentErrorsAndASingularFactorAreHandled) {
  JointResiduals j = random_low_rank(10, 0, 3);  // a diagonal alone
  const WhitenedResiduals w = whiten(j);
  ASSERT_TRUE(w.ok);
  EXPECT_NEAR(w.whitened(4), j.residual(4) / std::sqrt(j.covariance.diagonal(4)), 1e-14);
  j = random_low_rank(10, 3, 4);
  j.covariance.diagonal.setZero();  // rank 3 < 10: singular without the jitter
  EXPECT_TRUE(whiten(j).ok);
  EXPECT_NEAR(joint_log_likelihood(j), whiten(j).log_likelihood(), 1e-8 * std::abs(whiten(j).log_likelihood()));
  j.covariance.factor(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(whiten(j).ok);
  EXPECT_EQ(joint_log_likelihood(j), -std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace rbcal::calibration
