#include "calibration/detail/draw_predictions.hpp"

#include <cmath>

#include "formats/parallel_for.hpp"

namespace rbcal::calibration {

Eigen::VectorXd thinned_draw(const Eigen::MatrixXd& all, Eigen::Index k, Eigen::Index count) {
  return all.row(k * all.rows() / count).transpose();
}

std::vector<std::vector<surrogate::ViscosityPrediction>> predictions_at_draws(
    const LogPosterior& posterior, const Eigen::MatrixXd& all, Eigen::Index count,
    const std::vector<RelativeViscosityPoint>& points) {
  std::vector<std::vector<surrogate::ViscosityPrediction>> out(static_cast<std::size_t>(count));
  formats::parallel_for(count, 0, [&](std::ptrdiff_t k) {
    const Eigen::VectorXd theta = thinned_draw(all, k, count);
    out[static_cast<std::size_t>(k)] =
        posterior.observation_at(theta).predict_many(points, std::exp(theta(0)), posterior.lambda(theta));
  });
  return out;
}

}  // namespace rbcal::calibration
