#include "calibration/detail/independence_sampler.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rbcal::calibration {

MultivariateT::MultivariateT(Eigen::VectorXd mean, const Eigen::MatrixXd& scale, double dof)
    : mean_(std::move(mean)), dof_(dof) {
  if (scale.rows() != mean_.size() || scale.cols() != mean_.size())
    throw std::invalid_argument("multivariate t: scale matrix must be dimension x dimension");
  if (!(dof > 0.0)) throw std::invalid_argument("multivariate t: degrees of freedom must be positive");
  const Eigen::LLT<Eigen::MatrixXd> llt(scale);
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument("multivariate t: scale matrix is not positive definite");
  lower_ = llt.matrixL();
}

Eigen::VectorXd MultivariateT::draw(std::mt19937_64& rng) const {
  // Y = mean + L z sqrt(dof / g), z ~ N(0, I), g ~ chi^2(dof).
  std::normal_distribution<double> normal;
  std::chi_squared_distribution<double> chi_squared(dof_);
  Eigen::VectorXd z(mean_.size());
  for (Eigen::Index i = 0; i < z.size(); ++i) z(i) = normal(rng);
  return from_standard(z, chi_squared(rng));
}

Eigen::VectorXd MultivariateT::from_standard(const Eigen::VectorXd& z, double chi_squared) const {
  return mean_ + (lower_ * z) * std::sqrt(dof_ / chi_squared);
}

double MultivariateT::log_density(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd u = lower_.triangularView<Eigen::Lower>().solve(x - mean_);
  return -0.5 * (dof_ + static_cast<double>(mean_.size())) * std::log1p(u.squaredNorm() / dof_);
}

double MultivariateT::log_normaliser() const {
  const double d = static_cast<double>(mean_.size());
  return std::lgamma(0.5 * (dof_ + d)) - std::lgamma(0.5 * dof_) - 0.5 * d * std::log(dof_ * std::numbers::pi) -
         lower_.diagonal().array().log().sum();
}

Eigen::MatrixXd MultivariateT::covariance() const {
  if (!(dof_ > 2.0)) throw std::invalid_argument("multivariate t: no covariance for dof <= 2");
  return dof_ / (dof_ - 2.0) * lower_ * lower_.transpose();
}

IndependenceSampler::IndependenceSampler(LogDensity log_density, const Eigen::MatrixXd& initial,
                                         const Eigen::VectorXd& initial_log_density, MultivariateT proposal,
                                         std::uint64_t seed)
    : log_density_(std::move(log_density)),
      proposal_(std::move(proposal)),
      positions_(initial),
      rng_(seed),
      chain_(static_cast<int>(initial.rows()), static_cast<int>(initial.cols())) {
  if (initial.rows() != proposal_.dimension())
    throw std::invalid_argument("independence sampler: walkers and proposal differ in dimension");
  log_weight_.resize(initial.cols());
  current_log_density_.resize(initial.cols());
  if (initial_log_density.size() != 0 && initial_log_density.size() != initial.cols())
    throw std::invalid_argument("independence sampler: one initial log density per walker, or none");
  for (int w = 0; w < initial.cols(); ++w) {
    current_log_density_(w) =
        initial_log_density.size() != 0 ? initial_log_density(w) : log_density_(positions_.col(w));
    if (!std::isfinite(current_log_density_(w)))
      throw std::invalid_argument("independence sampler: initial walker " + std::to_string(w) +
                                  " has no finite log density");
    log_weight_(w) = current_log_density_(w) - proposal_.log_density(positions_.col(w));
  }
}

void IndependenceSampler::advance(int steps) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int step = 0; step < steps; ++step) {
    for (int k = 0; k < positions_.cols(); ++k) {
      const Eigen::VectorXd proposal = proposal_.draw(rng_);
      const double proposal_log_density = log_density_(proposal);
      const double proposal_log_weight = proposal_log_density - proposal_.log_density(proposal);
      ++acceptance_.proposed;
      proposal_log_weights_.push_back(std::isfinite(proposal_log_density)
                                          ? proposal_log_weight - proposal_.log_normaliser()
                                          : -std::numeric_limits<double>::infinity());
      if (std::isfinite(proposal_log_density) && std::log(uniform(rng_)) < proposal_log_weight - log_weight_(k)) {
        positions_.col(k) = proposal;
        current_log_density_(k) = proposal_log_density;
        log_weight_(k) = proposal_log_weight;
        ++acceptance_.accepted;
      }
    }
    chain_.append(positions_, current_log_density_);
  }
}

}  // namespace rbcal::calibration
