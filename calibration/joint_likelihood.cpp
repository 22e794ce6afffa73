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
  return joint_residuals(*at.model, at.nuisance, at.cell_radius,
                         {{&points, shear_modulus, lambda, at.plasma_viscosity, plasma_viscosity_is_parameter}},
                         relative_discrepancy);
}

JointResiduals joint_residuals(const surrogate::ViscosityModel& model, const surrogate::NuisanceValues& nuisance,
                               double cell_radius, const std::vector<SampleTerms>& samples,
                               double relative_discrepancy) {
  std::vector<surrogate::ParameterPoint> queries;
  for (const SampleTerms& s : samples)
    for (const auto& point : *s.points)
      queries.push_back(
          {point.phi, capillary_number(s.plasma_viscosity, point.shear_rate, cell_radius, s.shear_modulus), s.lambda});
  surrogate::JointViscosityPrediction predicted = model.predict_joint(queries, nuisance);
  JointResiduals out;
  const auto n = static_cast<Eigen::Index>(queries.size());
  out.residual.resize(n);
  out.covariance = std::move(predicted.covariance);
  Eigen::VectorXd independent(n);
  Eigen::Index i = 0;
  for (const SampleTerms& s : samples)
    for (const auto& point : *s.points) {
      const auto measured = observed_relative_viscosity(point, s.plasma_viscosity_is_parameter, s.plasma_viscosity);
      const double eta = predicted.points[static_cast<std::size_t>(i)].eta_re;
      out.residual(i) = measured.eta_re - eta;
      independent(i) = measured.sd * measured.sd + std::pow(relative_discrepancy * eta, 2);
      ++i;
    }
  out.covariance.add_diagonal(independent);
  return out;
}

namespace {

// -1/2 (r^T Sigma^-1 r + ln det Sigma + n ln 2 pi); -inf unless finite.
double gaussian_log_likelihood(double quadratic, double log_determinant, Eigen::Index n) {
  const double result = -0.5 * (quadratic + log_determinant + static_cast<double>(n) * std::log(2.0 * std::numbers::pi));
  return std::isfinite(result) ? result : -std::numeric_limits<double>::infinity();
}

}  // namespace

double WhitenedResiduals::log_likelihood() const {
  if (!ok) return -std::numeric_limits<double>::infinity();
  return gaussian_log_likelihood(whitened.squaredNorm(), log_determinant, whitened.size());
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

// D + F F^T scaled by D^-1/2: y = D^-1/2 r, W = D^-1/2 F, and the Gram matrix W^T W (lower half).
struct ScaledLowRank {
  Eigen::VectorXd y;
  Eigen::MatrixXd w;
  Eigen::MatrixXd gram;
  double log_det_diagonal = 0.0;  // sum ln D_i

  ScaledLowRank(const surrogate::JointCovariance& sigma, const Eigen::VectorXd& residual) {
    const Eigen::VectorXd d = positive_diagonal(sigma);
    const Eigen::VectorXd inverse_root = d.cwiseSqrt().cwiseInverse();
    y = inverse_root.cwiseProduct(residual);
    w = inverse_root.asDiagonal() * sigma.factor;
    gram = Eigen::MatrixXd::Zero(w.cols(), w.cols());
    if (w.cols() > 0) gram.selfadjointView<Eigen::Lower>().rankUpdate(w.transpose());
    log_det_diagonal = d.array().log().sum();
  }
};

WhitenedResiduals whiten_low_rank(const surrogate::JointCovariance& sigma, const Eigen::VectorXd& residual) {
  WhitenedResiduals out;
  const ScaledLowRank scaled(sigma, residual);
  const Eigen::VectorXd& y = scaled.y;
  const Eigen::MatrixXd& w = scaled.w;
  if (sigma.rank() == 0) {  // independent errors
    out.whitened = y;
    out.log_determinant = scaled.log_det_diagonal;
    out.ok = out.whitened.allFinite() && std::isfinite(out.log_determinant);
    return out;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled.gram);
  if (eigen.info() != Eigen::Success) return out;
  const Eigen::VectorXd s2 = eigen.eigenvalues().cwiseMax(0.0);
  Eigen::VectorXd g(s2.size());
  for (Eigen::Index k = 0; k < s2.size(); ++k)  // ((1 + s^2)^-1/2 - 1) / s^2, -1/2 at s = 0
    g(k) = s2(k) > 1e-8 ? (1.0 / std::sqrt(1.0 + s2(k)) - 1.0) / s2(k) : -0.5 + 0.375 * s2(k);
  const Eigen::MatrixXd& v = eigen.eigenvectors();
  out.whitened = y + w * (v * g.cwiseProduct(v.transpose() * (w.transpose() * y)));
  out.log_determinant = scaled.log_det_diagonal + s2.array().log1p().sum();
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
  ScaledLowRank scaled(sigma, joint.residual);
  scaled.gram.diagonal().array() += 1.0;  // the capacitance I + W^T W
  const Eigen::LLT<Eigen::MatrixXd> llt(scaled.gram);
  if (llt.info() != Eigen::Success) return minus_infinity;
  const double quadratic = scaled.y.squaredNorm() - llt.matrixL().solve(scaled.w.transpose() * scaled.y).squaredNorm();
  const double log_determinant = scaled.log_det_diagonal + 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  return gaussian_log_likelihood(quadratic, log_determinant, scaled.y.size());
}

}  // namespace rbcal::calibration
