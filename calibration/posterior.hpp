#pragma once
// Log posterior of theta = (ln G_s [, ln lambda] [, ln sigma_d]) for one sample.
//
// Likelihood (independent Gaussian errors on eta_re):
//   eta_re_i ~ N(m_i, v_i),  m_i = model eta_re(phi_i, Ca_i(G_s), lambda),
//   v_i = eta_re_sd_i^2 + model sd_i^2 + (sigma_d * m_i)^2,
// where sigma_d is a relative model-discrepancy scale (what neither the measurement error nor
// the model's own uncertainty explains).
// Priors (independent):
//   ln G_s     ~ uniform on [ln G_s_min, ln G_s_max]  (scale-invariant over the stated range)
//   ln lambda  ~ uniform on [ln lambda_min, ln lambda_max], by default the model's lambda range
//   ln sigma_d ~ normal(ln discrepancy_prior_median, discrepancy_prior_log_sd)  (weakly informative)
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration/calibration_input.hpp"
#include "calibration/viscosity_observation.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct PosteriorOptions {
  double cell_radius = kDefaultCellRadius;  // a [m]
  double lambda = 5.0;                      // fixed viscosity ratio when not fitted
  bool fit_lambda = false;
  bool fit_discrepancy = false;       // add ln sigma_d
  double shear_modulus_min = 1e-8;    // prior range of G_s [N/m]
  double shear_modulus_max = 1e-3;
  double lambda_min = 0.0;            // prior range of lambda; 0 = the model's range
  double lambda_max = 0.0;
  double discrepancy_prior_median = 0.05;  // sigma_d's prior median (5 % relative error)
  double discrepancy_prior_log_sd = 1.0;   // sd of ln sigma_d's prior
  // true: theta where any point's (phi, Ca, lambda) leaves the model's range has zero posterior
  // (the posterior is truncated to where the model was built); false: the model is trusted to
  // widen its own predictive sd outside its range.
  bool reject_outside_model_range = false;
};

class LogPosterior {
 public:
  LogPosterior(const surrogate::ViscosityModel& model, double plasma_viscosity,
               std::vector<RelativeViscosityPoint> points, const PosteriorOptions& options = {});

  int dimension() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& parameter_names() const { return names_; }
  int lambda_index() const { return lambda_index_; }            // -1 when lambda is fixed
  int discrepancy_index() const { return discrepancy_index_; }  // -1 without sigma_d

  double lambda(const Eigen::VectorXd& theta) const;
  double discrepancy(const Eigen::VectorXd& theta) const;  // sigma_d (0 without it)

  double log_prior(const Eigen::VectorXd& theta) const;       // -inf outside the support
  double log_likelihood(const Eigen::VectorXd& theta) const;  // Gaussian, normalising constants kept
  double operator()(const Eigen::VectorXd& theta) const;      // log prior + log likelihood

  const ViscosityObservation& observation() const { return observation_; }
  const std::vector<RelativeViscosityPoint>& points() const { return points_; }
  const PosteriorOptions& options() const { return options_; }

 private:
  ViscosityObservation observation_;
  std::vector<RelativeViscosityPoint> points_;
  PosteriorOptions options_;
  std::vector<std::string> names_;
  int lambda_index_ = -1;
  int discrepancy_index_ = -1;
};

}  // namespace rbcal::calibration
