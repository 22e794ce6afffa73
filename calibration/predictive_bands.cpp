#include "calibration/predictive_bands.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>

#include "calibration/detail/draw_predictions.hpp"
#include "calibration/posterior.hpp"
#include "calibration/quantiles.hpp"

namespace rbcal::calibration {

std::vector<PredictiveBand> predictive_bands(const surrogate::ViscosityModel& model,
                                             const McmcCalibration& calibration,
                                             const PredictiveBandOptions& options) {
  if (calibration.points.empty()) throw std::invalid_argument("predictive bands need calibrated points");
  const LogPosterior posterior(model, calibration.plasma_viscosity, calibration.points, calibration.posterior,
                               calibration.plasma_viscosity_standard_error);

  std::vector<double> phis = options.phis;
  if (phis.empty()) {
    std::set<double> distinct;
    for (const auto& p : calibration.points) distinct.insert(p.phi);
    phis.assign(distinct.begin(), distinct.end());
  }
  double lo = options.shear_rate_min, hi = options.shear_rate_max;
  for (const auto& p : calibration.points) {
    if (options.shear_rate_min <= 0.0) lo = lo <= 0.0 ? p.shear_rate : std::min(lo, p.shear_rate);
    if (options.shear_rate_max <= 0.0) hi = std::max(hi, p.shear_rate);
  }
  std::vector<double> rates;
  const int n_rates = std::max(2, options.shear_rate_points);
  for (int i = 0; i < n_rates; ++i) rates.push_back(std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / (n_rates - 1)));

  const Eigen::MatrixXd all = calibration.mcmc.draws();
  const Eigen::Index n_draws = std::min<Eigen::Index>(all.rows(), std::max(1, options.max_draws));
  // The model on the whole grid (phi, then shear rate) for each draw, batched; then the draws
  // of the model error in the order of grid points, then draws.
  std::vector<RelativeViscosityPoint> grid;
  for (double phi : phis)
    for (double rate : rates) {
      RelativeViscosityPoint at;
      at.phi = phi;
      at.shear_rate = rate;
      grid.push_back(at);
    }
  const auto at_draw = predictions_at_draws(posterior, all, n_draws, grid);
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  std::vector<PredictiveBand> bands;
  std::size_t g = 0;
  for (double phi : phis) {
    PredictiveBand band;
    band.phi = phi;
    band.shear_rate = rates;
    for (std::size_t r = 0; r < rates.size(); ++r, ++g) {
      std::vector<double> eta(static_cast<std::size_t>(n_draws));
      for (Eigen::Index k = 0; k < n_draws; ++k) {
        const Eigen::VectorXd theta = thinned_draw(all, k, n_draws);
        const ViscosityObservation obs = posterior.observation_at(theta);
        const surrogate::ViscosityPrediction& p = at_draw[static_cast<std::size_t>(k)][g];
        double eta_re = p.eta_re;
        if (options.include_model_error)
          eta_re += std::hypot(p.sd, posterior.discrepancy(theta) * p.eta_re) * normal(rng);
        eta[static_cast<std::size_t>(k)] = obs.plasma_viscosity * eta_re;
      }
      band.median.push_back(quantile(eta, 0.5));
      const Interval i = central_interval(eta, options.level);
      band.lower.push_back(i.lower);
      band.upper.push_back(i.upper);
    }
    bands.push_back(std::move(band));
  }
  return bands;
}

}  // namespace rbcal::calibration
