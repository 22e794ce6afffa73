#include "calibration/joint_likelihood.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace rbcal::calibration {

JointResiduals joint_residuals(const ViscosityObservation& at, const std::vector<RelativeViscosityPoint>& points,
                               double shear_modulus, double lambda, bool plasma_viscosity_is_parameter,
                               double relative_discrepancy) {
  std::vector<surrogate::ViscosityQuery> queries;
  for (const auto& point : points) queries.push_back({point.phi, at.capillary_number_at(point, shear_modulus), lambda});
  surrogate::JointViscosityPrediction model = at.model->predict_joint(queries, at.nuisance);
  JointResiduals out;
  const auto n = static_cast<Eigen::Index>(points.size());
  out.residual.resize(n);
  out.covariance = std::move(model.covariance);
  Eigen::VectorXd independent(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto measured =
        observed_relative_viscosity(points[static_cast<std::size_t>(i)], plasma_viscosity_is_parameter, at.plasma_viscosity);
    const double predicted = model.points[static_cast<std::size_t>(i)].eta_re;
    out.residual(i) = measured.eta_re - predicted;
    independent(i) = measured.sd * measured.sd + std::pow(relative_discrepancy * predicted, 2);
  }
  out.covariance.add_diagonal(independent);
  return out;
}

double WhitenedResiduals::log_likelihood() const {
  if (!ok) return -std::numeric_limits<double>::infinity();
  const double result = -0.5 * (whitened.squaredNorm() + log_determinant +
                                static_cast<double>(whitened.size()) * std::log(2.0 * std::numbers::pi));
  return std::isfinite(result) ? result : -std::numeric_limits<double>::infinity();
}

namespace {

WhitenedResiduals whiten_dense(const Eigen::MatrixXd& covariance, const Eigen::VectorXd& residual) {
  WhitenedResiduals out;
  Eigen::LLT<Eigen::MatrixXd> llt(covariance);
  if (llt.info() != Eigen::Success) {
    Eigen::MatrixXd sigma = covariance;
    const double jitter = 1e-12 * sigma.diagonal().mean();
    sigma.diagonal().array() += jitter > 0.0 ? jitter : 1e-300;
    llt.compute(sigma);
    if (llt.info() != Eigen::Success) return out;
  }
  out.whitened = llt.matrixL().solve(residual);
  out.log_determinant = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  out.ok = out.whitened.allFinite() && std::isfinite(out.log_determinant);
  return out;
}

// The diagonal D of D + F F^T, with the dense path's jitter where it is not positive (the factor
// alone is singular).
Eigen::VectorXd positive_diagonal(const surrogate::JointCovariance& sigma) {
  Eigen::VectorXd d = sigma.diagonal;
  if (d.size() == 0 || !(d.minCoeff() > 0.0)) {
    const double jitter = 1e-12 * sigma.variances().mean();
    if (d.size() == 0) d = Eigen::VectorXd::Zero(sigma.size());
    d.array() += jitter > 0.0 ? jitter : 1e-300;
  }
  return d;
}

bool finite_input(const JointResiduals& joint) {
  const surrogate::JointCovariance& sigma = joint.covariance;
  return (sigma.full.size() == 0 || sigma.full.allFinite()) &&
         (sigma.diagonal.size() == 0 || sigma.diagonal.allFinite()) &&
         (sigma.factor.size() == 0 || sigma.factor.allFinite()) && joint.residual.allFinite() &&
         joint.residual.size() > 0 && sigma.size() == joint.residual.size();
}

WhitenedResiduals whiten_low_rank(const surrogate::JointCovariance& sigma, const Eigen::VectorXd& residual) {
  WhitenedResiduals out;
  const Eigen::VectorXd d = positive_diagonal(sigma);
  const Eigen::VectorXd inverse_root = d.cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd y = inverse_root.cwiseProduct(residual);
  if (sigma.rank() == 0) {  // independent errors
    out.whitened = y;
    out.log_determinant = d.array().log().sum();
    out.ok = out.whitened.allFinite() && std::isfinite(out.log_determinant);
    return out;
  }
  const Eigen::MatrixXd w = inverse_root.asDiagonal() * sigma.factor;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(w.cols(), w.cols());
  gram.selfadjointView<Eigen::Lower>().rankUpdate(w.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  if (eigen.info() != Eigen::Success) return out;
  const Eigen::VectorXd s2 = eigen.eigenvalues().cwiseMax(0.0);
  Eigen::VectorXd g(s2.size());
  for (Eigen::Index k = 0; k < s2.size(); ++k)  // ((1 + s^2)^-1/2 - 1) / s^2, -1/2 at s = 0
    g(k) = s2(k) > 1e-8 ? (1.0 / std::sqrt(1.0 + s2(k)) - 1.0) / s2(k) : -0.5 + 0.375 * s2(k);
  const Eigen::MatrixXd& v = eigen.eigenvectors();
  out.whitened = y + w * (v * g.cwiseProduct(v.transpose() * (w.transpose() * y)));
  out.log_determinant = d.array().log().sum() + s2.array().log1p().sum();
  out.ok = out.whitened.allFinite() && std::isfinite(out.log_determinant);
  return out;
}

}  // namespace

WhitenedResiduals whiten(const JointResiduals& joint) {
  if (!finite_input(joint)) return {};
  return joint.covariance.dense_is_cheaper() ? whiten_dense(joint.covariance.dense(), joint.residual)
                                             : whiten_low_rank(joint.covariance, joint.residual);
}

double joint_log_likelihood(const JointResiduals& joint) {
  const double minus_infinity = -std::numeric_limits<double>::infinity();
  const surrogate::JointCovariance& sigma = joint.covariance;
  if (!finite_input(joint)) return minus_infinity;
  if (sigma.dense_is_cheaper() || sigma.rank() == 0) return whiten(joint).log_likelihood();
  const Eigen::VectorXd d = positive_diagonal(sigma);
  const Eigen::VectorXd inverse_root = d.cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd y = inverse_root.cwiseProduct(joint.residual);
  const Eigen::MatrixXd w = inverse_root.asDiagonal() * sigma.factor;
  Eigen::MatrixXd capacitance = Eigen::MatrixXd::Identity(w.cols(), w.cols());
  capacitance.selfadjointView<Eigen::Lower>().rankUpdate(w.transpose());
  const Eigen::LLT<Eigen::MatrixXd> llt(capacitance);
  if (llt.info() != Eigen::Success) return minus_infinity;
  const double quadratic = y.squaredNorm() - llt.matrixL().solve(w.transpose() * y).squaredNorm();
  const double log_determinant = d.array().log().sum() + 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  const double result = -0.5 * (quadratic + log_determinant + static_cast<double>(y.size()) * std::log(2.0 * std::numbers::pi));
  return std::isfinite(result) ? result : minus_infinity;
}

}  // namespace rbcal::calibration
