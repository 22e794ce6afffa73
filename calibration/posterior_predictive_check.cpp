#include "calibration/posterior_predictive_check.hpp"

#include "calibration/detail/draw_predictions.hpp"


#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "calibration/posterior.hpp"
#include "calibration/quantiles.hpp"
#include "calibration/viscosity_observation.hpp"

namespace rbcal::calibration {

int PredictiveCheck::outside() const {
  return static_cast<int>(std::count_if(points.begin(), points.end(), [](const auto& p) { return p.outside; }));
}

double PredictiveCheck::tail_probability() const {
  const int k = outside();
  if (points.empty() || k == 0) return 1.0;
  const boost::math::binomial_distribution<double> b(static_cast<double>(points.size()), 1.0 - level);
  return boost::math::cdf(boost::math::complement(b, static_cast<double>(k - 1)));
}

std::string PredictiveCheck::line() const {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer,
                "%d of %zu points outside their %.0f %% posterior predictive interval (%.1f expected; P = %.2g)",
                outside(), points.size(), 100.0 * level, expected_outside(), tail_probability());
  return buffer;
}

nlohmann::json PredictiveCheck::to_json() const {
  nlohmann::json j = {{"level", level},
                      {"points_outside", outside()},
                      {"expected_outside", expected_outside()},
                      {"tail_probability", tail_probability()},
                      {"disagrees", disagrees()}};
  j["points"] = nlohmann::json::array();
  for (const auto& p : points)
    j["points"].push_back({{"line", p.point.line},
                           {"phi", p.point.phi},
                           {"shear_rate_per_s", p.point.shear_rate},
                           {"pit", p.pit},
                           {"predicted_eta_re_median", p.predicted_median},
                           {"outside", p.outside}});
  return j;
}

PredictiveCheck posterior_predictive_check(const surrogate::ViscosityModel& model, const McmcCalibration& calibration,
                                           const PredictiveCheckOptions& options) {
  if (!(options.level > 0.0 && options.level < 1.0)) throw std::invalid_argument("predictive check: level in (0, 1)");
  PredictiveCheck out;
  out.level = options.level;
  if (calibration.points.empty()) return out;
  const LogPosterior posterior(model, calibration.plasma_viscosity, calibration.points, calibration.posterior,
                               calibration.plasma_viscosity_standard_error);
  const bool eta0_is_parameter = posterior.plasma_viscosity_index() >= 0;
  const Eigen::MatrixXd all = calibration.mcmc.draws();
  const Eigen::Index n_draws = std::min<Eigen::Index>(all.rows(), std::max(1, options.max_draws));
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> normal;
  const double tail = 0.5 * (1.0 - options.level);
  // The model at every point for each draw, batched; then the draws of the noise in the order
  // of points, then draws.
  const auto at_draw = predictions_at_draws(posterior, all, n_draws, calibration.points);
  for (std::size_t i = 0; i < calibration.points.size(); ++i) {
    const RelativeViscosityPoint& point = calibration.points[i];
    int below = 0;
    std::vector<double> predicted;
    for (Eigen::Index k = 0; k < n_draws; ++k) {
      const Eigen::VectorXd theta = thinned_draw(all, k, n_draws);
      const ViscosityObservation obs = posterior.observation_at(theta);
      const surrogate::ViscosityPrediction& p = at_draw[static_cast<std::size_t>(k)][i];
      const ObservedRelativeViscosity measured =
          observed_relative_viscosity(point, eta0_is_parameter, obs.plasma_viscosity);
      const double noise = predictive_sd(p, posterior.discrepancy(theta), measured.sd);
      const double draw = p.eta_re + noise * normal(rng);
      predicted.push_back(p.eta_re);
      if (draw < measured.eta_re) ++below;
    }
    PredictiveCheckPoint c;
    c.point = point;
    c.pit = static_cast<double>(below) / static_cast<double>(n_draws);
    c.predicted_median = quantile(predicted, 0.5);
    c.outside = c.pit < tail || c.pit > 1.0 - tail;
    out.points.push_back(c);
  }
  return out;
}

}  // namespace rbcal::calibration
