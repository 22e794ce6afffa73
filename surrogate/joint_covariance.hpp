#pragma once
// The joint covariance of a model's errors at n points, kept in the form that makes a
// likelihood cheap:
//   Sigma = full + diag(diagonal) + factor factor^T.
// Each part may be absent (zero size). A Gaussian-process surrogate gives the exact n x n
// matrix (full) for a few points; for many it gives a diagonal plus a factor of rank at most
// its number of runs plus its mean terms (gaussian_process.hpp, latent_covariance_factor), so
// that a likelihood costs O(n r^2) instead of O(n^3) (calibration/joint_likelihood.cpp).
#include <Eigen/Core>

namespace rbcal::surrogate {

// Which form a model gives: automatic (exact up to kExactJointCovarianceLimit points, low rank
// beyond), one of the two forced (to compare them), or none: each point's own variance only
// (the diagonal), for point-wise use.
enum class CovarianceForm { automatic, exact, low_rank, none };

struct JointCovariance {
  Eigen::MatrixXd full;      // n x n, or empty
  Eigen::VectorXd diagonal;  // n, or empty
  Eigen::MatrixXd factor;    // n x r, or empty

  static JointCovariance diagonal_only(Eigen::VectorXd variances);

  Eigen::Index size() const;
  // The rank of the low-rank part (0 without one).
  Eigen::Index rank() const { return factor.cols(); }
  // Whether Sigma is better handled as one dense matrix: it has a full part, or a factor of
  // rank not below n.
  bool dense_is_cheaper() const;

  Eigen::VectorXd variances() const;  // diag(Sigma)
  Eigen::MatrixXd dense() const;      // Sigma as one n x n matrix
  Eigen::VectorXd times(const Eigen::VectorXd& x) const;  // Sigma x

  // Sigma -> S Sigma S with S = diag(s).
  void scale(const Eigen::VectorXd& s);
  // Sigma -> Sigma + weight * other (weight >= 0; the factors are stacked side by side).
  void add(const JointCovariance& other, double weight);
  // Sigma -> Sigma + variance g g^T.
  void add_rank_one(const Eigen::VectorXd& g, double variance);
  void add_diagonal(const Eigen::VectorXd& variances);
};

// The correlation matrix of Sigma in the same form: S^-1 Sigma S^-1 with S = sqrt(diag Sigma),
// except that a point with zero (or negative) variance is uncorrelated with unit variance.
JointCovariance correlation_of(const JointCovariance& sigma);

}  // namespace rbcal::surrogate
