#include "calibration/ensemble_sampler.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcal::calibration {

std::vector<std::vector<double>> EnsembleChain::walker_series(int parameter, int first_step) const {
  std::vector<std::vector<double>> series(walkers_);
  for (int w = 0; w < walkers_; ++w) {
    series[w].reserve(static_cast<std::size_t>(std::max(0, steps() - first_step)));
    for (int s = first_step; s < steps(); ++s) series[w].push_back(value(s, w, parameter));
  }
  return series;
}

void EnsembleChain::append(const Eigen::MatrixXd& positions, const Eigen::VectorXd& log_density) {
  positions_.insert(positions_.end(), positions.data(), positions.data() + positions.size());
  log_density_.insert(log_density_.end(), log_density.data(), log_density.data() + log_density.size());
}

EnsembleSampler::EnsembleSampler(LogDensity log_density, const Eigen::MatrixXd& initial, std::uint64_t seed,
                                 double stretch_scale)
    : log_density_(std::move(log_density)),
      positions_(initial),
      rng_(seed),
      stretch_scale_(stretch_scale),
      chain_(static_cast<int>(initial.rows()), static_cast<int>(initial.cols())) {
  if (initial.cols() < 2) throw std::invalid_argument("ensemble sampler needs at least two walkers");
  if (!(stretch_scale > 1.0)) throw std::invalid_argument("stretch scale a must exceed 1");
  current_log_density_.resize(initial.cols());
  for (int w = 0; w < initial.cols(); ++w) {
    current_log_density_(w) = log_density_(positions_.col(w));
    if (!std::isfinite(current_log_density_(w)))
      throw std::invalid_argument("ensemble sampler: initial walker " + std::to_string(w) +
                                  " has no finite log density");
  }
}

void EnsembleSampler::advance(int steps) {
  const int walkers = static_cast<int>(positions_.cols());
  const double d = static_cast<double>(positions_.rows());
  const double a = stretch_scale_;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::uniform_int_distribution<int> partner(0, walkers - 2);
  for (int step = 0; step < steps; ++step) {
    for (int k = 0; k < walkers; ++k) {
      int j = partner(rng_);
      if (j >= k) ++j;  // uniform over the other walkers
      // z = ((a - 1) u + 1)^2 / a has density proportional to 1/sqrt(z) on [1/a, a] (GW10 eq. 9).
      const double u = uniform(rng_);
      const double z = std::pow((a - 1.0) * u + 1.0, 2) / a;
      const Eigen::VectorXd proposal = positions_.col(j) + z * (positions_.col(k) - positions_.col(j));
      const double proposal_log_density = log_density_(proposal);
      const double log_accept = (d - 1.0) * std::log(z) + proposal_log_density - current_log_density_(k);
      ++acceptance_.proposed;
      if (std::isfinite(proposal_log_density) && std::log(uniform(rng_)) < log_accept) {
        positions_.col(k) = proposal;
        current_log_density_(k) = proposal_log_density;
        ++acceptance_.accepted;
      }
    }
    chain_.append(positions_, current_log_density_);
  }
}

}  // namespace rbcal::calibration
