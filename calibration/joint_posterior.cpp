#include "calibration/joint_posterior.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "calibration/capillary_number.hpp"
#include "calibration/joint_likelihood.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/viscosity_observation.hpp"

namespace rbcal::calibration {

namespace {

constexpr double kTauMin = 0.01, kTauMax = 3.0;  // the hierarchical sd's flat range (of ln tau)

}  // namespace

JointLogPosterior::JointLogPosterior(const surrogate::ViscosityModel& model, std::vector<JointSample> joint_samples,
                                     const JointPosteriorOptions& options)
    : model_(&model), samples_(std::move(joint_samples)), options_(options) {
  if (samples_.size() < 2) throw std::invalid_argument("joint posterior: needs at least two samples");
  PosteriorOptions& p = options_.posterior;
  if (!(p.shear_modulus_min > 0.0 && p.shear_modulus_max > p.shear_modulus_min))
    throw std::invalid_argument("joint posterior: need 0 < shear_modulus_min < shear_modulus_max");
  for (const JointSample& s : samples_) {
    if (s.points.empty()) throw std::invalid_argument("joint posterior: sample " + s.name + " has no points");
    names_.push_back((options_.hierarchical ? "z_G_s[" : "ln_G_s[") + s.name + "]");
  }
  const int n = samples();
  lambda_index_.assign(static_cast<std::size_t>(n), -1);
  plasma_index_.assign(static_cast<std::size_t>(n), -1);
  if (p.setup.fit_lambda) {
    const surrogate::ParameterRange range = model.range();
    if (p.lambda_min <= 0.0) p.lambda_min = range.lambda_min;
    if (p.lambda_max <= 0.0) p.lambda_max = range.lambda_max;
    for (int i = 0; i < n; ++i) {
      if (options_.shared_lambda && i > 0) {
        lambda_index_[static_cast<std::size_t>(i)] = lambda_index_[0];
        continue;
      }
      lambda_index_[static_cast<std::size_t>(i)] = dimension();
      names_.push_back(options_.shared_lambda ? "ln_lambda" : "ln_lambda[" + samples_[static_cast<std::size_t>(i)].name + "]");
    }
  }
  for (int i = 0; i < n; ++i) {
    const JointSample& s = samples_[static_cast<std::size_t>(i)];
    SampleData as_sample;
    as_sample.plasma.eta0 = s.plasma_viscosity;
    as_sample.plasma.standard_error = s.plasma_viscosity_standard_error;
    as_sample.points = s.points;
    if (p.plasma_viscosity_as_parameter && plasma_viscosity_can_be_parameter(as_sample)) {
      plasma_index_[static_cast<std::size_t>(i)] = dimension();
      names_.push_back("ln_eta0[" + s.name + "]");
    }
  }
  if (p.model_nuisances_as_parameters) nuisances_ = model.nuisances();
  if (!nuisances_.empty()) nuisance_index_ = dimension();
  for (const auto& nuisance : nuisances_) names_.push_back(nuisance.name);
  if (options_.hierarchical) {
    mu_index_ = dimension();
    names_.push_back("mu_ln_G_s");
    tau_index_ = dimension();
    names_.push_back("ln_tau");
  }
}

double JointLogPosterior::ln_shear_modulus(const Eigen::VectorXd& theta, int sample) const {
  const double x = theta(shear_modulus_index(sample));
  return options_.hierarchical ? theta(mu_index_) + std::exp(theta(tau_index_)) * x : x;
}

int JointLogPosterior::lambda_index(int sample) const { return lambda_index_[static_cast<std::size_t>(sample)]; }

int JointLogPosterior::plasma_viscosity_index(int sample) const {
  return plasma_index_[static_cast<std::size_t>(sample)];
}

double JointLogPosterior::lambda_at(const Eigen::VectorXd& theta, int sample) const {
  const int k = lambda_index(sample);
  return k >= 0 ? std::exp(theta(k)) : options_.posterior.setup.lambda;
}

double JointLogPosterior::plasma_viscosity_at(const Eigen::VectorXd& theta, int sample) const {
  const int k = plasma_viscosity_index(sample);
  return k >= 0 ? std::exp(theta(k)) : samples_[static_cast<std::size_t>(sample)].plasma_viscosity;
}

double JointLogPosterior::log_prior(const Eigen::VectorXd& theta) const {
  constexpr double minus_infinity = -std::numeric_limits<double>::infinity();
  const PosteriorOptions& p = options_.posterior;
  const double ln_lo = std::log(p.shear_modulus_min), ln_hi = std::log(p.shear_modulus_max);
  double log_p = 0.0;
  if (options_.hierarchical) {
    const double mu = theta(mu_index_), ln_tau = theta(tau_index_);
    if (!(mu >= ln_lo && mu <= ln_hi)) return minus_infinity;
    if (!(ln_tau >= std::log(kTauMin) && ln_tau <= std::log(kTauMax))) return minus_infinity;
    log_p += -std::log(ln_hi - ln_lo) - std::log(std::log(kTauMax) - std::log(kTauMin));
  }
  for (int i = 0; i < samples(); ++i) {
    const double x = ln_shear_modulus(theta, i);
    if (!(x >= ln_lo && x <= ln_hi)) return minus_infinity;
    // Hierarchical: z ~ N(0, 1), i.e. the population's normal in ln G_s, truncated to the
    // bounds (their mass, about 1 for any tau the data allow, left out).
    log_p += options_.hierarchical ? normal_log_prior(theta(shear_modulus_index(i)), 0.0, 1.0) : -std::log(ln_hi - ln_lo);
    if (lambda_index(i) >= 0 && (!options_.shared_lambda || i == 0)) log_p += lambda_log_prior(theta(lambda_index(i)), p);
    if (plasma_viscosity_index(i) >= 0) {
      const JointSample& s = samples_[static_cast<std::size_t>(i)];
      log_p += normal_log_prior(theta(plasma_viscosity_index(i)), std::log(s.plasma_viscosity),
                                s.plasma_viscosity_standard_error / s.plasma_viscosity);
    }
  }
  for (std::size_t k = 0; k < nuisances_.size(); ++k)
    log_p += nuisance_log_prior(theta(nuisance_index_ + static_cast<int>(k)), nuisances_[k]);
  return log_p;
}

double JointLogPosterior::log_likelihood(const Eigen::VectorXd& theta) const {
  const double radius = options_.posterior.setup.cell_radius;
  const surrogate::ParameterRange range = model_->range();
  std::vector<SampleTerms> terms;
  for (int i = 0; i < samples(); ++i) {
    const JointSample& s = samples_[static_cast<std::size_t>(i)];
    const SampleTerms t{&s.points, std::exp(ln_shear_modulus(theta, i)), lambda_at(theta, i),
                        plasma_viscosity_at(theta, i), plasma_viscosity_index(i) >= 0};
    if (options_.posterior.reject_outside_model_range)
      for (const auto& point : s.points)
        if (!range.contains(point.phi, capillary_number(t.plasma_viscosity, point.shear_rate, radius, t.shear_modulus),
                            t.lambda))
          return -std::numeric_limits<double>::infinity();
    terms.push_back(t);
  }
  surrogate::NuisanceValues nuisance;
  for (std::size_t k = 0; k < nuisances_.size(); ++k) nuisance.set(nuisances_[k].name, theta(nuisance_index_ + static_cast<int>(k)));
  return joint_log_likelihood(joint_residuals(*model_, nuisance, radius, terms));
}

double JointLogPosterior::operator()(const Eigen::VectorXd& theta) const {
  const double prior = log_prior(theta);
  if (!std::isfinite(prior)) return prior;
  return prior + log_likelihood(theta);
}

int JointCalibration::index_of(const std::string& sample) const {
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples[i].name == sample) return static_cast<int>(i);
  return -1;
}

ShearModulusRatio JointCalibration::ratio(int a, int b, double level) const {
  return ratio_of_paired_draws(samples.at(static_cast<std::size_t>(a)).shear_modulus_draws,
                               samples.at(static_cast<std::size_t>(b)).shear_modulus_draws, level);
}

JointCalibration calibrate_joint(const std::vector<JointSample>& samples, const std::vector<DirectFitResult>& fits,
                                 const surrogate::ViscosityModel& model, const JointPosteriorOptions& options,
                                 const McmcOptions& sampler_options) {
  if (fits.size() != samples.size()) throw std::invalid_argument("joint calibration: one direct fit per sample");
  const JointLogPosterior posterior(model, samples, options);
  const int d = posterior.dimension(), n = posterior.samples();
  // Start: each sample's direct fit; shared parameters at the mean of the fits' values.
  McmcStart start{Eigen::VectorXd::Zero(d), Eigen::VectorXd::Constant(d, 0.1), {}};
  const auto sd_of = [](const DirectFitResult& f, int k) {
    return k >= 0 && f.covariance_ok ? std::sqrt(f.covariance(k, k)) : 0.1;
  };
  Eigen::VectorXd shared_sum = Eigen::VectorXd::Zero(d), shared_count = Eigen::VectorXd::Zero(d);
  for (int i = 0; i < n; ++i) {
    const DirectFitResult& f = fits[static_cast<std::size_t>(i)];
    start.center(i) = f.estimate(0);
    start.scale(i) = sd_of(f, 0);
    if (posterior.lambda_index(i) >= 0) {
      const int k = f.index_of("ln_lambda");
      shared_sum(posterior.lambda_index(i)) += k >= 0 ? f.estimate(k) : std::log(options.posterior.setup.lambda);
      shared_count(posterior.lambda_index(i)) += 1.0;
      start.scale(posterior.lambda_index(i)) = sd_of(f, k);
    }
    if (posterior.plasma_viscosity_index(i) >= 0) {
      start.center(posterior.plasma_viscosity_index(i)) = std::log(f.plasma_viscosity);
      const JointSample& s = samples[static_cast<std::size_t>(i)];
      start.scale(posterior.plasma_viscosity_index(i)) = s.plasma_viscosity_standard_error / s.plasma_viscosity;
    }
    for (std::size_t k = 0; k < posterior.nuisances().size(); ++k) {
      const int p = posterior.nuisance_index() + static_cast<int>(k);
      const int j = f.index_of(posterior.nuisances()[k].name);
      shared_sum(p) += j >= 0 ? f.estimate(j) : posterior.nuisances()[k].mean;
      shared_count(p) += 1.0;
      start.scale(p) = j >= 0 && f.covariance_ok ? std::sqrt(f.covariance(j, j)) : 0.3 * posterior.nuisances()[k].sd;
    }
  }
  for (int p = 0; p < d; ++p)
    if (shared_count(p) > 0.0) start.center(p) = shared_sum(p) / shared_count(p);
  if (posterior.mu_index() >= 0) {  // z_i = (ln G_s,i - mu) / tau
    const Eigen::VectorXd ln_g = start.center.head(n);
    const double mean = ln_g.mean();
    const double tau = std::clamp(std::sqrt((ln_g.array() - mean).square().sum() / std::max(1, n - 1)), 0.05, 2.0);
    start.center(posterior.mu_index()) = mean;
    start.scale(posterior.mu_index()) = 0.3;
    start.center(posterior.tau_index()) = std::log(tau);
    start.scale(posterior.tau_index()) = 0.5;
    for (int i = 0; i < n; ++i) {
      start.center(i) = (ln_g(i) - mean) / tau;
      start.scale(i) = 0.5;
    }
  }
  for (int p = 0; p < d; ++p)
    if (!(start.scale(p) > 0.0) || !std::isfinite(start.scale(p))) start.scale(p) = 0.1;

  McmcOptions sampler = sampler_options;
  if (sampler.walkers == 0) sampler.walkers = automatic_walkers(d);
  JointCalibration out;
  out.parameter_names = posterior.parameter_names();
  out.mcmc = sample_posterior([&posterior](const Eigen::VectorXd& theta) { return posterior(theta); },
                              posterior.parameter_names(), start, sampler);
  const double level = sampler.interval_level;
  const Eigen::MatrixXd draws = out.mcmc.draws();
  for (int i = 0; i < n; ++i) {
    JointSampleEstimate e;
    e.name = samples[static_cast<std::size_t>(i)].name;
    for (Eigen::Index k = 0; k < draws.rows(); ++k)
      e.shear_modulus_draws.push_back(std::exp(posterior.ln_shear_modulus(draws.row(k).transpose(), i)));
    e.shear_modulus_median = quantile(e.shear_modulus_draws, 0.5);
    e.shear_modulus_interval = central_interval(e.shear_modulus_draws, level);
    out.samples.push_back(std::move(e));
  }
  for (std::size_t k = 0; k < posterior.nuisances().size(); ++k) {
    const ParameterSummary& s = out.mcmc.parameters[static_cast<std::size_t>(posterior.nuisance_index()) + k];
    out.nuisances.push_back({posterior.nuisances()[k], s.median, s.interval});
  }
  if (posterior.mu_index() >= 0) {
    out.hierarchical = true;
    const ParameterSummary& mu = out.mcmc.parameters[static_cast<std::size_t>(posterior.mu_index())];
    const ParameterSummary& tau = out.mcmc.parameters[static_cast<std::size_t>(posterior.tau_index())];
    out.mu_median = std::exp(mu.median);
    out.mu_interval = {std::exp(mu.interval.lower), std::exp(mu.interval.upper), mu.interval.level};
    out.tau_median = std::exp(tau.median);
    out.tau_interval = {std::exp(tau.interval.lower), std::exp(tau.interval.upper), tau.interval.level};
  }
  return out;
}

}  // namespace rbcal::calibration
