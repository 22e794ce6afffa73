#include "calibration/detail/draw_predictions.hpp"

#include <cmath>
#include <exception>

namespace rbcal::calibration {

Eigen::VectorXd thinned_draw(const Eigen::MatrixXd& all, Eigen::Index k, Eigen::Index count) {
  return all.row(k * all.rows() / count).transpose();
}

std::vector<std::vector<surrogate::ViscosityPrediction>> predictions_at_draws(
    const LogPosterior& posterior, const Eigen::MatrixXd& all, Eigen::Index count,
    const std::vector<RelativeViscosityPoint>& points) {
  std::vector<std::vector<surrogate::ViscosityPrediction>> out(static_cast<std::size_t>(count));
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic)
  for (Eigen::Index k = 0; k < count; ++k) {
    try {
      const Eigen::VectorXd theta = thinned_draw(all, k, count);
      out[static_cast<std::size_t>(k)] =
          posterior.observation_at(theta).predict_many(points, std::exp(theta(0)), posterior.lambda(theta));
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace rbcal::calibration
