#include "calibration/posterior.hpp"

#include "calibration/joint_likelihood.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace rbcal::calibration {

LogPosterior::LogPosterior(const surrogate::ViscosityModel& model, double plasma_viscosity,
                           std::vector<RelativeViscosityPoint> points, const PosteriorOptions& options,
                           double plasma_viscosity_standard_error)
    : observation_{&model, plasma_viscosity, options.setup.cell_radius, {}},
      points_(std::move(points)),
      options_(options),
      plasma_viscosity_standard_error_(plasma_viscosity_standard_error) {
  if (points_.empty()) throw std::invalid_argument("posterior needs at least one data point");
  if (!(options_.shear_modulus_min > 0.0 && options_.shear_modulus_max > options_.shear_modulus_min))
    throw std::invalid_argument("posterior: need 0 < shear_modulus_min < shear_modulus_max");
  if (options_.setup.fit_lambda) {
    const surrogate::ParameterRange range = model.range();
    if (options_.lambda_min <= 0.0) options_.lambda_min = range.lambda_min;
    if (options_.lambda_max <= 0.0) options_.lambda_max = range.lambda_max;
    if (!(options_.lambda_min > 0.0 && options_.lambda_max > options_.lambda_min))
      throw std::invalid_argument("posterior: lambda prior range must satisfy 0 < min < max");
  }
  SampleData as_sample;
  as_sample.plasma.eta0 = plasma_viscosity;
  as_sample.plasma.standard_error = plasma_viscosity_standard_error;
  as_sample.points = points_;
  const bool eta0 = options_.plasma_viscosity_as_parameter && plasma_viscosity_can_be_parameter(as_sample);
  if (options_.model_nuisances_as_parameters) nuisances_ = model.nuisances();
  layout_ = ParameterLayout(options_.setup.fit_lambda, options_.fit_discrepancy, eta0, nuisances_);
}

double lambda_log_prior(double x, const PosteriorOptions& options) {
  const double lo = std::log(options.lambda_min), hi = std::log(options.lambda_max);
  if (!(x >= lo && x <= hi)) return -std::numeric_limits<double>::infinity();
  const double s = options.setup.lambda_prior_log_sd;
  if (!(s > 0.0)) return -std::log(hi - lo);
  // Normal in ln lambda about the setup's lambda (the normaliser of the truncation is a
  // constant and left out).
  const double z = (x - std::log(options.setup.lambda)) / s;
  return -0.5 * z * z - std::log(s) - 0.5 * std::log(2.0 * std::numbers::pi);
}

double normal_log_prior(double x, double mean, double sd) {
  const double z = (x - mean) / sd;
  if (!std::isfinite(z)) return -std::numeric_limits<double>::infinity();
  return -0.5 * z * z - std::log(sd) - 0.5 * std::log(2.0 * std::numbers::pi);
}

double nuisance_log_prior(double v, const surrogate::ModelNuisance& n) {
  if (!(v >= n.min && v <= n.max)) return -std::numeric_limits<double>::infinity();
  // Truncated normal: ln(sd sqrt(2 pi) (Phi(b) - Phi(a))) normalises it.
  const auto cdf = [](double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); };
  const double mass = cdf((n.max - n.mean) / n.sd) - cdf((n.min - n.mean) / n.sd);
  const double z = (v - n.mean) / n.sd;
  return -0.5 * z * z - std::log(n.sd * std::sqrt(2.0 * std::numbers::pi) * mass);
}

surrogate::NuisanceValues LogPosterior::nuisance_values(const Eigen::VectorXd& theta) const {
  surrogate::NuisanceValues values;
  for (std::size_t k = 0; k < nuisances_.size(); ++k)
    values.set(nuisances_[k].name, theta(layout_.nuisance + static_cast<int>(k)));
  return values;
}

ViscosityObservation LogPosterior::observation_at(const Eigen::VectorXd& theta) const {
  ViscosityObservation at = observation_;
  at.plasma_viscosity = plasma_viscosity(theta);
  at.nuisance = nuisance_values(theta);
  return at;
}

double LogPosterior::plasma_viscosity(const Eigen::VectorXd& theta) const {
  return layout_.plasma_viscosity >= 0 ? std::exp(theta(layout_.plasma_viscosity)) : observation_.plasma_viscosity;
}

double LogPosterior::lambda(const Eigen::VectorXd& theta) const {
  return layout_.lambda >= 0 ? std::exp(theta(layout_.lambda)) : options_.setup.lambda;
}

double LogPosterior::discrepancy(const Eigen::VectorXd& theta) const {
  return layout_.discrepancy >= 0 ? std::exp(theta(layout_.discrepancy)) : 0.0;
}

double LogPosterior::log_prior(const Eigen::VectorXd& theta) const {
  constexpr double minus_infinity = -std::numeric_limits<double>::infinity();
  const double ln_lo = std::log(options_.shear_modulus_min), ln_hi = std::log(options_.shear_modulus_max);
  if (!(theta(0) >= ln_lo && theta(0) <= ln_hi)) return minus_infinity;
  double log_p = -std::log(ln_hi - ln_lo);
  if (layout_.lambda >= 0) log_p += lambda_log_prior(theta(layout_.lambda), options_);
  if (layout_.discrepancy >= 0)
    log_p += normal_log_prior(theta(layout_.discrepancy), std::log(options_.discrepancy_prior_median),
                              options_.discrepancy_prior_log_sd);
  if (layout_.plasma_viscosity >= 0)
    log_p += normal_log_prior(theta(layout_.plasma_viscosity), std::log(observation_.plasma_viscosity),
                              plasma_viscosity_standard_error_ / observation_.plasma_viscosity);
  for (std::size_t k = 0; k < nuisances_.size(); ++k)
    log_p += nuisance_log_prior(theta(layout_.nuisance + static_cast<int>(k)), nuisances_[k]);
  return log_p;
}

double LogPosterior::log_likelihood(const Eigen::VectorXd& theta) const {
  const double shear_modulus = std::exp(theta(0));
  const double lambda_value = lambda(theta);
  const double sigma_d = discrepancy(theta);
  const ViscosityObservation at = observation_at(theta);
  if (options_.reject_outside_model_range)
    for (const auto& point : points_)
      if (!at.inside_range(point, shear_modulus, lambda_value)) return -std::numeric_limits<double>::infinity();
  return joint_log_likelihood(
      joint_residuals(at, points_, shear_modulus, lambda_value, layout_.plasma_viscosity >= 0, sigma_d));
}

double LogPosterior::operator()(const Eigen::VectorXd& theta) const {
  const double prior = log_prior(theta);
  if (!std::isfinite(prior)) return prior;
  return prior + log_likelihood(theta);
}

}  // namespace rbcal::calibration
