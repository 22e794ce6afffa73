#pragma once
// Direct fit of ln G_s (optionally ln lambda) to all eta_re(phi, gamma_dot) points inside the
// model's range by generalised least squares (Ceres): the residuals are whitened with the joint
// covariance of measurement and model errors (joint_likelihood.hpp; the model's errors are
// correlated between points), and the likelihood's normalisation is kept, so that the fit is the
// posterior's mode (posterior.hpp). With a robust loss the points are taken as independent and
// the normalisation is left out. Laplace (Gauss-Newton) covariance.
// eta0 is by default a nuisance parameter ln eta0 with the plateau estimate as a Gaussian prior
// (a prior residual (ln eta0 - ln eta0_hat) / (se / eta0_hat)), so that its error, common to all
// points, reaches G_s's interval. A model's nuisance parameters (a surrogate family's offset c;
// viscosity_model.hpp) enter the same way: each a parameter with its
// prior as a residual (v - mean) / sd, bounded to its prior's support.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration/parameter_layout.hpp"
#include "calibration/calibration_input.hpp"
#include "calibration/model_setup.hpp"
#include "calibration/quantiles.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

enum class RobustLoss { none, huber, cauchy };

// The most nuisance parameters a model may have (viscosity_model.hpp; the family has one).
inline constexpr int kMaxModelNuisances = 2;

// The message of a fit whose set of points inside the model's range did not settle.
inline constexpr const char* kPointSetUnsettled =
    "the set of points inside the model's range still changed after the last refit";

// A model nuisance parameter's estimate with its interval (clipped to the prior's support).
struct NuisanceEstimate {
  surrogate::ModelNuisance prior;
  double value = 0.0;
  Interval interval;
};

struct DirectFitOptions {
  ModelSetup setup;  // a, lambda (fixed, or the start when fit_lambda)
  // Fit ln eta0 with its plateau prior when the sample allows it (plasma standard error > 0 and
  // absolute viscosities on every point); otherwise eta0 is fixed and its error is in eta_re_sd.
  bool plasma_viscosity_as_parameter = true;
  // Fit the model's nuisance parameters with their priors; false: the model at their means.
  bool model_nuisances_as_parameters = true;
  double shear_modulus_min = 1e-8;  // bounds on G_s [N/m]; ln lambda is bounded by the model's range
  double shear_modulus_max = 1e-3;
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 2.0;  // in units of the weighted residual (standard deviations)
  double interval_level = 0.95;
  int start_grid_points = 41;   // ln-uniform scan of G_s for the starting point
  int max_selection_rounds = 5;  // refits while the set of points inside the model's range changes
  // Hold the largest set of points that one G_s can keep inside the model's Ca range (every
  // point whose phi it covers, when their shear rates span less than ca_max / ca_min), and
  // bound G_s to keep them there, instead of fitting whichever points lie inside at the
  // optimum: a fit may then not shed points that a model of the wrong shape fails to fit.
  // Where the bound holds G_s, the fit is a limit (model_edge). It errs the other way where the
  // data reach beyond the model's Ca range at the true G_s (stiff cells at the lowest shear
  // rates): the bound then holds G_s away from the truth. false (the default): the points
  // inside at the optimum, refitted while that set changes (max_selection_rounds), and
  // coverable_points says when that left out points one G_s could have kept.
  bool hold_coverable_points = false;
  // Multiply the covariance by chi^2 / dof (when the stated errors are not trusted).
  bool scale_covariance_by_reduced_chi_square = false;
};

struct FittedPoint {
  RelativeViscosityPoint point;
  bool used = false;
  std::string reason;              // why not used
  double capillary_number = 0.0;   // at the estimate
  double predicted_eta_re = 0.0;   // model at the estimate
  double predicted_sd = 0.0;       // model's predictive sd at the estimate
  // (eta_re - predicted) / sqrt(eta_re_sd^2 + predicted_sd^2): the point on its own, as plotted
  double weighted_residual = 0.0;
};

// Where an edge fit (a fit that would leave the model's Ca range with every point) holds G_s.
enum class ModelEdge { none, largest_ca, smallest_ca };
// What G_s is at that edge: an "upper" (largest_ca) or "lower" (smallest_ca) limit; "" for none.
inline const char* limit_kind(ModelEdge edge) {
  return edge == ModelEdge::largest_ca ? "upper" : edge == ModelEdge::smallest_ca ? "lower" : "";
}

struct DirectFitResult {
  std::vector<std::string> parameter_names;  // "ln_G_s", then when fitted "ln_lambda", "ln_eta0", the model's nuisances
  Eigen::VectorXd estimate;                  // in that order
  Eigen::MatrixXd covariance;                // Laplace covariance of the estimate
  bool covariance_ok = false;                // false: Covariance::Compute failed (rank deficient)
  double shear_modulus = 0.0;                // exp(ln G_s) [N/m]
  double ln_shear_modulus_sd = 0.0;
  Interval shear_modulus_interval;           // exp of the normal interval on ln G_s [N/m]
  double lambda = 0.0;                       // fitted or fixed
  Interval lambda_interval;                  // when fitted
  bool at_bound = false;                     // an estimate sits on a bound: interval unreliable
  // Not none: G_s is held at the model's Ca edge (largest_ca: an upper limit on G_s, the data
  // lie below the model; smallest_ca: a lower limit); messages say so.
  ModelEdge model_edge = ModelEdge::none;
  std::string model_edge_reason;  // the message that says so, empty when none
  // G_s's interval is an estimate's: a covariance was computed and G_s is not held at an edge
  // (where the interval is a limit).
  bool has_interval_estimate() const { return covariance_ok && model_edge == ModelEdge::none; }
  bool converged = false;
  // Over the used points: the squared whitened residuals (without a robust loss), else the
  // squared weighted residuals.
  double chi_square = 0.0;
  int degrees_of_freedom = 0;
  double plasma_viscosity = 0.0;   // eta0 at the estimate [Pa s] (the plateau value when fixed)
  bool plasma_viscosity_fitted = false;
  std::vector<NuisanceEstimate> nuisances;  // the model's nuisance parameters, as fitted
  std::vector<FittedPoint> points;
  bool point_set_settled = true;  // false: kPointSetUnsettled (also in messages)
  // The most points one G_s keeps inside the model's range together; more than the used points:
  // the fit left out points that another G_s would have kept (a shed set, not a forced one).
  int coverable_points = 0;
  std::vector<std::string> messages;
  std::string solver_report;  // Ceres' brief report of the last solve

  // The points the fit used (those inside the model's range at the estimate's last round).
  std::vector<RelativeViscosityPoint> used_points() const {
    std::vector<RelativeViscosityPoint> used;
    for (const auto& f : points)
      if (f.used) used.push_back(f.point);
    return used;
  }

  // Index of a parameter in estimate and covariance, -1 when not fitted.
  int index_of(const std::string& name) const { return index_in(parameter_names, name); }
};

// Throws std::invalid_argument when fewer points than parameters lie in the model's range at the
// start. A fit that then carries every point out of the range becomes an edge fit (model_edge).
DirectFitResult fit_direct(const SampleData& sample, const surrogate::ViscosityModel& model,
                           const DirectFitOptions& options = {});

}  // namespace rbcal::calibration
