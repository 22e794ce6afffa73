#include "calibration/joint_likelihood.hpp"

#include <cmath>
#include <limits>
#include <numbers>

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
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto measured =
        observed_relative_viscosity(points[static_cast<std::size_t>(i)], plasma_viscosity_is_parameter, at.plasma_viscosity);
    const double predicted = model.points[static_cast<std::size_t>(i)].eta_re;
    out.residual(i) = measured.eta_re - predicted;
    out.covariance(i, i) += measured.sd * measured.sd + std::pow(relative_discrepancy * predicted, 2);
  }
  return out;
}

double WhitenedResiduals::log_likelihood() const {
  if (!ok) return -std::numeric_limits<double>::infinity();
  const double result = -0.5 * (whitened.squaredNorm() + log_determinant +
                                static_cast<double>(whitened.size()) * std::log(2.0 * std::numbers::pi));
  return std::isfinite(result) ? result : -std::numeric_limits<double>::infinity();
}

WhitenedResiduals whiten(const JointResiduals& joint) {
  WhitenedResiduals out;
  if (!joint.covariance.allFinite() || !joint.residual.allFinite() || joint.residual.size() == 0) return out;
  Eigen::LLT<Eigen::MatrixXd> llt(joint.covariance);
  if (llt.info() != Eigen::Success) {
    Eigen::MatrixXd sigma = joint.covariance;
    const double jitter = 1e-12 * sigma.diagonal().mean();
    sigma.diagonal().array() += jitter > 0.0 ? jitter : 1e-300;
    llt.compute(sigma);
    if (llt.info() != Eigen::Success) return out;
  }
  out.whitened = llt.matrixL().solve(joint.residual);
  out.log_determinant = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
  out.ok = out.whitened.allFinite() && std::isfinite(out.log_determinant);
  return out;
}

}  // namespace rbcal::calibration
