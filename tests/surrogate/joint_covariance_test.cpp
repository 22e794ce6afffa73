// The joint covariance's parts (full, diagonal, low-rank factor) against the same operations on
// the dense matrices they stand for.
#include "surrogate/joint_covariance.hpp"

#include <gtest/gtest.h>

#include <random>

namespace rbcal::surrogate {
namespace {

JointCovariance random_parts(Eigen::Index n, Eigen::Index rank, bool with_full, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  const auto random_matrix = [&](Eigen::Index rows, Eigen::Index cols) {
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index i = 0; i < m.size(); ++i) m(i) = normal(rng);
    return m;
  };
  JointCovariance c;
  c.factor = random_matrix(n, rank);
  c.diagonal = random_matrix(n, 1).col(0).cwiseAbs();
  if (with_full) {
    const Eigen::MatrixXd a = random_matrix(n, n);
    c.full = a * a.transpose();
  }
  return c;
}

TEST(JointCovariance, DenseIsTheSumOfItsParts) {
  const JointCovariance c = random_parts(7, 3, true, 1);
  const Eigen::MatrixXd expected = c.full + Eigen::MatrixXd(c.diagonal.asDiagonal()) + c.factor * c.factor.transpose();
  EXPECT_LT((c.dense() - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((c.variances() - expected.diagonal()).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(7, -1.0, 2.0);
  EXPECT_LT((c.times(x) - expected * x).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_TRUE(c.dense_is_cheaper());
  EXPECT_FALSE(random_parts(7, 3, false, 1).dense_is_cheaper());
  EXPECT_TRUE(random_parts(7, 7, false, 1).dense_is_cheaper());
}

TEST(JointCovariance, ScaleAddAndRankOneActOnTheMatrix) {
  for (bool full : {false, true}) {
    JointCovariance a = random_parts(6, 2, full, 2);
    const JointCovariance b = random_parts(6, 3, false, 3);
    Eigen::MatrixXd expected = a.dense();
    const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(6, 0.5, 3.0);
    const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(6, -1.0, 1.0);
    a.scale(s);
    expected = s.asDiagonal() * expected * s.asDiagonal();
    a.add(b, 0.3);
    expected += 0.3 * b.dense();
    a.add_rank_one(g, 0.25);
    expected += 0.25 * g * g.transpose();
    a.add_diagonal(s);
    expected += Eigen::MatrixXd(s.asDiagonal());
    EXPECT_LT((a.dense() - expected).cwiseAbs().maxCoeff(), 1e-12) << "with a full part: " << full;
    EXPECT_EQ(a.rank(), 2 + 3 + 1);
  }
  JointCovariance a = random_parts(4, 1, false, 4);
  EXPECT_THROW(a.add(random_parts(5, 1, false, 5), 1.0), std::invalid_argument);
  EXPECT_THROW(a.add(random_parts(4, 1, false, 5), -1.0), std::invalid_argument);
}

TEST(JointCovariance, CorrelationHasUnitDiagonalAndTheMatrixsCorrelations) {
  for (bool full : {false, true}) {
    JointCovariance c = random_parts(5, 2, full, 6);
    if (full) c.full.row(3).setZero(), c.full.col(3).setZero();
    if (!full) c.factor.row(3).setZero(), c.diagonal(3) = 0.0;  // a point the model is sure of
    if (full) c.factor.row(3).setZero(), c.diagonal(3) = 0.0;
    const Eigen::MatrixXd sigma = c.dense();
    const Eigen::MatrixXd r = correlation_of(c).dense();
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        const double expected = i == j ? 1.0 : (i == 3 || j == 3) ? 0.0 : sigma(i, j) / std::sqrt(sigma(i, i) * sigma(j, j));
        EXPECT_NEAR(r(i, j), expected, 1e-12) << i << " " << j << " full " << full;
      }
  }
}

}  // namespace
}  // namespace rbcal::surrogate
