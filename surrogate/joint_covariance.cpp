#include "surrogate/joint_covariance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbcal::surrogate {

JointCovariance JointCovariance::diagonal_only(Eigen::VectorXd variances) {
  JointCovariance c;
  c.diagonal = std::move(variances);
  return c;
}

Eigen::Index JointCovariance::size() const {
  return std::max({full.rows(), diagonal.size(), factor.rows()});
}

bool JointCovariance::dense_is_cheaper() const { return full.size() > 0 || rank() >= size(); }

Eigen::VectorXd JointCovariance::variances() const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size());
  if (full.size() > 0) v += full.diagonal();
  if (diagonal.size() > 0) v += diagonal;
  if (factor.size() > 0) v += factor.rowwise().squaredNorm();
  return v;
}

Eigen::MatrixXd JointCovariance::dense() const {
  const Eigen::Index n = size();
  Eigen::MatrixXd sigma = full.size() > 0 ? full : Eigen::MatrixXd::Zero(n, n);
  if (diagonal.size() > 0) sigma.diagonal() += diagonal;
  if (factor.size() > 0) sigma.selfadjointView<Eigen::Lower>().rankUpdate(factor);
  if (factor.size() > 0) sigma.triangularView<Eigen::StrictlyUpper>() = sigma.transpose();
  return sigma;
}

Eigen::VectorXd JointCovariance::times(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(size());
  if (full.size() > 0) y += full * x;
  if (diagonal.size() > 0) y += diagonal.cwiseProduct(x);
  if (factor.size() > 0) y += factor * (factor.transpose() * x);
  return y;
}

void JointCovariance::scale(const Eigen::VectorXd& s) {
  if (full.size() > 0) full = s.asDiagonal() * full * s.asDiagonal();
  if (diagonal.size() > 0) diagonal = diagonal.cwiseProduct(s.cwiseProduct(s));
  if (factor.size() > 0) factor = s.asDiagonal() * factor;
}

void JointCovariance::add(const JointCovariance& other, double weight) {
  if (!(weight >= 0.0)) throw std::invalid_argument("JointCovariance: a negative weight");
  const Eigen::Index n = size() > 0 ? size() : other.size();
  if (other.size() != n) throw std::invalid_argument("JointCovariance: the two covariances differ in size");
  if (other.full.size() > 0) {
    if (full.size() == 0) full = Eigen::MatrixXd::Zero(n, n);
    full += weight * other.full;
  }
  if (other.diagonal.size() > 0) {
    if (diagonal.size() == 0) diagonal = Eigen::VectorXd::Zero(n);
    diagonal += weight * other.diagonal;
  }
  if (other.factor.size() > 0) {
    Eigen::MatrixXd stacked(n, factor.cols() + other.factor.cols());
    if (factor.size() > 0) stacked.leftCols(factor.cols()) = factor;
    stacked.rightCols(other.factor.cols()) = std::sqrt(weight) * other.factor;
    factor = std::move(stacked);
  }
}

void JointCovariance::add_rank_one(const Eigen::VectorXd& g, double variance) {
  JointCovariance one;
  one.factor = std::sqrt(variance) * g;
  add(one, 1.0);
}

void JointCovariance::add_diagonal(const Eigen::VectorXd& variances) { add(diagonal_only(variances), 1.0); }

JointCovariance correlation_of(const JointCovariance& sigma) {
  const Eigen::VectorXd v = sigma.variances();
  const Eigen::Index n = v.size();
  Eigen::VectorXd inverse_sd(n), uncorrelated = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    inverse_sd(i) = v(i) > 0.0 ? 1.0 / std::sqrt(v(i)) : 0.0;
    if (!(v(i) > 0.0)) uncorrelated(i) = 1.0;
  }
  JointCovariance c = sigma;
  c.scale(inverse_sd);
  if (c.full.size() > 0) c.full.diagonal() = Eigen::VectorXd::Ones(n) - (c.variances() - c.full.diagonal());
  else c.add_diagonal(uncorrelated);
  return c;
}

}  // namespace rbcal::surrogate
