#pragma once
// Log posterior of theta = (ln G_s [, ln lambda] [, ln sigma_d] [, ln eta0] [, model nuisances])
// for one sample.
//
// Likelihood (Gaussian, calibration/joint_likelihood.hpp):
//   eta_re ~ N(m, Sigma),  m_i = model eta_re(phi_i, Ca_i(G_s), lambda),
//   Sigma = diag(eta_re_sd_i^2 + (sigma_d * m_i)^2) + C,
// C the model's joint predictive covariance at the points (its errors are correlated between
// points; the diagonal is each point's model sd^2), and sigma_d a relative model-discrepancy
// scale (what neither the measurement error nor the model's own uncertainty explains). With eta0 a parameter, eta_re_i = eta_i / eta0 with
// sd se(eta_i) / eta0 and Ca_i uses that eta0: eta0's error, common to every point, is then
// carried by its prior instead of being folded into each point as if independent.
// Priors (independent):
//   ln G_s     ~ uniform on [ln G_s_min, ln G_s_max]  (scale-invariant over the stated range)
//   ln lambda  ~ normal(ln setup.lambda, setup.lambda_prior_log_sd) truncated to [ln lambda_min,
//                ln lambda_max], by default the model's lambda range (uniform there with sd 0)
//   ln sigma_d ~ normal(ln discrepancy_prior_median, discrepancy_prior_log_sd)  (weakly informative)
//   ln eta0    ~ normal(ln eta0_hat, se(eta0_hat) / eta0_hat)  (the plasma plateau's estimate)
//   each of the model's nuisance parameters (surrogate/viscosity_model.hpp; a surrogate family's
//                offset c) ~ its prior, normal(mean, sd) truncated to
//                [min, max]: one number common to every point, so its error reaches G_s in full
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration/calibration_input.hpp"
#include "calibration/model_setup.hpp"
#include "calibration/parameter_layout.hpp"
#include "calibration/viscosity_observation.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct PosteriorOptions {
  ModelSetup setup;  // a, lambda (fixed when not fitted)
  bool fit_discrepancy = false;       // add ln sigma_d
  double shear_modulus_min = 1e-8;    // prior range of G_s [N/m]
  double shear_modulus_max = 1e-3;
  double lambda_min = 0.0;            // prior range of lambda; 0 = the model's range
  double lambda_max = 0.0;
  double discrepancy_prior_median = 0.05;  // sigma_d's prior median (5 % relative error)
  double discrepancy_prior_log_sd = 1.0;   // sd of ln sigma_d's prior
  // true (the default): theta where any point's (phi, Ca,
  // lambda) leaves the model's range has zero posterior (the posterior is truncated to where
  // the model was built); false: the model is trusted to widen its own predictive sd outside
  // its range. The surrogate's extrapolation was measured: the default of 69 runs predicted new
  // runs at Ca 5.6-18 14-47 % too low, 5-13 of its sd (studies/library-v2-development/README.md,
  // "The high-Ca tier at C 10").
  bool reject_outside_model_range = true;
  // Add ln eta0 when possible: eta0's standard error > 0 and every point has its viscosity.
  bool plasma_viscosity_as_parameter = true;
  // Add the model's nuisance parameters; false: the model predicts at their means.
  bool model_nuisances_as_parameters = true;
};

// The prior terms every posterior shares, as ln densities (-inf outside the support).
// ln lambda: normal about the setup's lambda with sd lambda_prior_log_sd, truncated to
// [ln min, ln max] (the truncation's normaliser left out), or uniform there when that sd is 0.
double lambda_log_prior(double ln_lambda, const PosteriorOptions& options);
// A normal prior on x (mean, sd), normalised.
double normal_log_prior(double x, double mean, double sd);
// A model nuisance's truncated normal prior, normalised over its truncation.
double nuisance_log_prior(double value, const surrogate::ModelNuisance& nuisance);

class LogPosterior {
 public:
  // plasma_viscosity: the plateau estimate eta0_hat [Pa s], with its standard error.
  LogPosterior(const surrogate::ViscosityModel& model, double plasma_viscosity,
               std::vector<RelativeViscosityPoint> points, const PosteriorOptions& options = {},
               double plasma_viscosity_standard_error = 0.0);

  int dimension() const { return layout_.dimension(); }
  const std::vector<std::string>& parameter_names() const { return layout_.names; }
  const ParameterLayout& layout() const { return layout_; }
  int lambda_index() const { return layout_.lambda; }            // -1 when lambda is fixed
  int discrepancy_index() const { return layout_.discrepancy; }  // -1 without sigma_d
  int plasma_viscosity_index() const { return layout_.plasma_viscosity; }  // -1 with eta0 fixed
  // Index of the first model nuisance (they follow in the model's order), -1 without them.
  int nuisance_index() const { return layout_.nuisance; }
  const std::vector<surrogate::ModelNuisance>& nuisances() const { return nuisances_; }

  double lambda(const Eigen::VectorXd& theta) const;
  double discrepancy(const Eigen::VectorXd& theta) const;  // sigma_d (0 without it)
  double plasma_viscosity(const Eigen::VectorXd& theta) const;  // eta0 [Pa s]
  surrogate::NuisanceValues nuisance_values(const Eigen::VectorXd& theta) const;  // empty without them
  // The observation at theta: eta0 and the model's nuisance values set.
  ViscosityObservation observation_at(const Eigen::VectorXd& theta) const;

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
  ParameterLayout layout_;
  std::vector<surrogate::ModelNuisance> nuisances_;
  double plasma_viscosity_standard_error_ = 0.0;
};

}  // namespace rbcal::calibration
