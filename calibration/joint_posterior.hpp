#pragma once
// One posterior over several samples of a file (donors, before and after a treatment, fresh and
// stored cells): each sample has its own G_s and eta0 (and lambda, unless shared), while the
// model's nuisance parameters (the immersed boundary's offset c) are the model's and so are
// shared, and the model's errors are correlated across the samples' points as within one
// sample's (joint_likelihood.hpp). Calibrated one at a time, each sample would draw its own
// offset, and a ratio of two samples' G_s would carry the offset's uncertainty twice over where
// it largely cancels. Optionally hierarchical: ln G_s,i ~ N(mu, tau^2), with mu flat over the
// G_s prior range and ln tau flat over [ln 0.01, ln 3] (a factor of 1.01 to 20 between donors),
// sampled as ln G_s,i = mu + tau z_i with z_i ~ N(0, 1) (the non-centred form: where the samples
// agree and tau is small, ln G_s,i and tau form a funnel that no sampler crosses well).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration/calibration_input.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_sampling.hpp"
#include "calibration/posterior.hpp"
#include "calibration/quantiles.hpp"
#include "calibration/sample_comparison.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct JointPosteriorOptions {
  PosteriorOptions posterior;  // setup (lambda fitted or fixed, its prior), bounds, range truncation
  bool shared_lambda = false;  // with lambda fitted: one lambda for all samples instead of one each
  bool hierarchical = false;   // ln G_s,i ~ N(mu, tau^2)
};

// One sample in the joint posterior: its points (those its direct fit used) and eta0.
struct JointSample {
  std::string name;
  std::vector<RelativeViscosityPoint> points;
  double plasma_viscosity = 0.0;                 // eta0's plateau estimate [Pa s]
  double plasma_viscosity_standard_error = 0.0;  // [Pa s]
};

class JointLogPosterior {
 public:
  JointLogPosterior(const surrogate::ViscosityModel& model, std::vector<JointSample> samples,
                    const JointPosteriorOptions& options);

  int dimension() const { return static_cast<int>(names_.size()); }
  // ln_G_s[NAME] per sample (z_G_s[NAME] when hierarchical), then ln_lambda (shared) or
  // ln_lambda[NAME], ln_eta0[NAME] where eta0 is a parameter, the model's nuisances, and
  // mu_ln_G_s, ln_tau when hierarchical.
  const std::vector<std::string>& parameter_names() const { return names_; }
  int samples() const { return static_cast<int>(samples_.size()); }
  const JointSample& sample(int i) const { return samples_[static_cast<std::size_t>(i)]; }
  int shear_modulus_index(int sample) const { return sample; }  // ln G_s, or z when hierarchical
  double ln_shear_modulus(const Eigen::VectorXd& theta, int sample) const;
  int lambda_index(int sample) const;            // -1 with lambda fixed
  int plasma_viscosity_index(int sample) const;  // -1 with eta0 fixed
  int nuisance_index() const { return nuisance_index_; }  // first nuisance, -1 without
  const std::vector<surrogate::ModelNuisance>& nuisances() const { return nuisances_; }
  int mu_index() const { return mu_index_; }    // -1 unless hierarchical
  int tau_index() const { return tau_index_; }  // ln tau; -1 unless hierarchical

  double log_prior(const Eigen::VectorXd& theta) const;
  double log_likelihood(const Eigen::VectorXd& theta) const;
  double operator()(const Eigen::VectorXd& theta) const;

 private:
  double lambda_at(const Eigen::VectorXd& theta, int sample) const;
  double plasma_viscosity_at(const Eigen::VectorXd& theta, int sample) const;

  const surrogate::ViscosityModel* model_;
  std::vector<JointSample> samples_;
  JointPosteriorOptions options_;
  std::vector<std::string> names_;
  std::vector<int> lambda_index_, plasma_index_;
  int nuisance_index_ = -1, mu_index_ = -1, tau_index_ = -1;
  std::vector<surrogate::ModelNuisance> nuisances_;
};

struct JointSampleEstimate {
  std::string name;
  double shear_modulus_median = 0.0;  // [N/m]
  Interval shear_modulus_interval;    // [N/m]
  std::vector<double> shear_modulus_draws;  // [N/m]
};

struct JointCalibration {
  std::vector<std::string> parameter_names;
  McmcResult mcmc;
  std::vector<JointSampleEstimate> samples;
  std::vector<NuisanceEstimate> nuisances;  // shared: median and interval
  bool hierarchical = false;
  double mu_median = 0.0;  // exp(mu) [N/m], the population's median G_s
  Interval mu_interval;    // [N/m]
  double tau_median = 0.0;  // sd of ln G_s between samples
  Interval tau_interval;
  // G_s of sample a over sample b, draw by draw (the same draws: what they share cancels).
  ShearModulusRatio ratio(int a, int b, double level = 0.95) const;
  int index_of(const std::string& sample) const;  // -1 when absent
};

// fits: each sample's direct fit (its estimate starts the chains; its used points are the
// sample's points here).
JointCalibration calibrate_joint(const std::vector<JointSample>& samples, const std::vector<DirectFitResult>& fits,
                                 const surrogate::ViscosityModel& model, const JointPosteriorOptions& options,
                                 const McmcOptions& sampler);

}  // namespace rbcal::calibration
