#pragma once
// The model at a set of points for evenly thinned posterior draws: one batched prediction per
// draw (the model's predict_many at the draw's nuisance values), the draws in parallel. What
// the predictive bands and the posterior predictive check draw their noise around.
#include <vector>

#include <Eigen/Dense>

#include "calibration/calibration_input.hpp"
#include "calibration/posterior.hpp"

namespace rbcal::calibration {

// Row k of all.row(k * all.rows() / count) for k < count: the thinned draws, in order.
Eigen::VectorXd thinned_draw(const Eigen::MatrixXd& all, Eigen::Index k, Eigen::Index count);

// [k][i]: the model at points[i] for thinned draw k (k < count).
std::vector<std::vector<surrogate::ViscosityPrediction>> predictions_at_draws(
    const LogPosterior& posterior, const Eigen::MatrixXd& all, Eigen::Index count,
    const std::vector<RelativeViscosityPoint>& points);

}  // namespace rbcal::calibration
