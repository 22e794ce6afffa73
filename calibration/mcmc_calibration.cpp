#include "calibration/mcmc_calibration.hpp"

#include <algorithm>
#include <cmath>

namespace rbcal::calibration {

namespace {

Interval exp_interval(const Interval& i) { return {std::exp(i.lower), std::exp(i.upper), i.level}; }

}  // namespace

std::vector<double> McmcCalibration::shear_modulus_draws() const {
  std::vector<double> draws = mcmc.parameter_draws(0);
  for (double& x : draws) x = std::exp(x);
  return draws;
}

int automatic_walkers(int parameters) { return std::max(16, 8 * parameters); }

McmcCalibration calibrate_mcmc(const SampleData& sample, const surrogate::ViscosityModel& model,
                               const McmcCalibrationOptions& options) {
  McmcCalibration out;
  out.plasma_viscosity = sample.plasma.eta0;
  out.plasma_viscosity_standard_error = sample.plasma.standard_error;
  DirectFitOptions fit_options = options.start_fit;
  fit_options.setup = options.posterior.setup;
  fit_options.plasma_viscosity_as_parameter = options.posterior.plasma_viscosity_as_parameter;
  fit_options.model_nuisances_as_parameters = options.posterior.model_nuisances_as_parameters;
  fit_options.shear_modulus_min = options.posterior.shear_modulus_min;
  fit_options.shear_modulus_max = options.posterior.shear_modulus_max;
  out.start_fit = options.fitted_start ? *options.fitted_start : fit_direct(sample, model, fit_options);
  out.points = out.start_fit.used_points();

  // The posterior is truncated to the model's range by default (posterior.hpp). After an edge fit
  // the likelihood's optimum lies outside it, and the interval is a limit like the fit's
  // (start_fit.model_edge_reason).
  const LogPosterior posterior(model, sample.plasma.eta0, out.points, options.posterior,
                               sample.plasma.standard_error);
  out.posterior = posterior.options();
  const int d = posterior.dimension();
  McmcStart start{Eigen::VectorXd::Zero(d), Eigen::VectorXd::Constant(d, 0.1), {}};
  start.center(0) = out.start_fit.estimate(0);
  if (out.start_fit.covariance_ok) start.scale(0) = std::sqrt(out.start_fit.covariance(0, 0));
  if (posterior.lambda_index() >= 0) {
    start.center(posterior.lambda_index()) = out.start_fit.estimate(1);
    if (out.start_fit.covariance_ok) start.scale(posterior.lambda_index()) = std::sqrt(out.start_fit.covariance(1, 1));
  }
  if (posterior.plasma_viscosity_index() >= 0) {
    const int k = out.start_fit.index_of("ln_eta0");
    start.center(posterior.plasma_viscosity_index()) = std::log(out.start_fit.plasma_viscosity);
    if (k >= 0 && out.start_fit.covariance_ok)
      start.scale(posterior.plasma_viscosity_index()) = std::sqrt(out.start_fit.covariance(k, k));
    else
      start.scale(posterior.plasma_viscosity_index()) = sample.plasma.standard_error / sample.plasma.eta0;
  }
  if (posterior.discrepancy_index() >= 0) {
    start.center(posterior.discrepancy_index()) = std::log(options.posterior.discrepancy_prior_median);
    start.scale(posterior.discrepancy_index()) = 0.3 * options.posterior.discrepancy_prior_log_sd;
  }
  for (std::size_t k = 0; k < posterior.nuisances().size(); ++k) {
    const surrogate::ModelNuisance& n = posterior.nuisances()[k];
    const int p = posterior.nuisance_index() + static_cast<int>(k);
    const int i = out.start_fit.index_of(n.name);
    start.center(p) = i >= 0 ? out.start_fit.estimate(i) : n.mean;
    start.scale(p) = i >= 0 && out.start_fit.covariance_ok ? std::sqrt(out.start_fit.covariance(i, i)) : 0.3 * n.sd;
  }
  for (int p = 0; p < d; ++p)
    if (!(start.scale(p) > 0.0) || !std::isfinite(start.scale(p))) start.scale(p) = 0.1;
  // A fit that found its optimum inside the support gives the sampler its Laplace covariance
  // (parameters it did not fit keep their start scale, uncorrelated), so that the independence
  // sampler can start without a pilot; after an edge or bound fit the pilot finds the shape.
  const DirectFitResult& fit = out.start_fit;
  if (fit.covariance_ok && !fit.at_bound && fit.model_edge == ModelEdge::none) {
    std::vector<int> in_fit(static_cast<std::size_t>(d));
    for (int p = 0; p < d; ++p) in_fit[static_cast<std::size_t>(p)] = fit.index_of(posterior.parameter_names()[p]);
    start.covariance = start.scale.array().square().matrix().asDiagonal();
    for (int p = 0; p < d; ++p)
      for (int q = 0; q < d; ++q) {
        const int i = in_fit[static_cast<std::size_t>(p)], j = in_fit[static_cast<std::size_t>(q)];
        if (i >= 0 && j >= 0) start.covariance(p, q) = fit.covariance(i, j);
      }
  }
  McmcOptions sampler = options.sampler;
  if (sampler.walkers == 0) sampler.walkers = automatic_walkers(d);
  out.mcmc = sample_posterior([&posterior](const Eigen::VectorXd& theta) { return posterior(theta); },
                              posterior.parameter_names(), start, sampler);

  const auto& summaries = out.mcmc.parameters;
  out.shear_modulus_median = std::exp(summaries[0].median);
  out.shear_modulus_interval = exp_interval(summaries[0].interval);
  if (posterior.lambda_index() >= 0) {
    out.lambda_median = std::exp(summaries[posterior.lambda_index()].median);
    out.lambda_interval = exp_interval(summaries[posterior.lambda_index()].interval);
  } else {
    out.lambda_median = options.posterior.setup.lambda;
    out.lambda_interval = {out.lambda_median, out.lambda_median, options.sampler.interval_level};
  }
  if (posterior.discrepancy_index() >= 0) {
    out.discrepancy_median = std::exp(summaries[posterior.discrepancy_index()].median);
    out.discrepancy_interval = exp_interval(summaries[posterior.discrepancy_index()].interval);
  }
  if (posterior.plasma_viscosity_index() >= 0) {
    out.plasma_viscosity_median = std::exp(summaries[posterior.plasma_viscosity_index()].median);
    out.plasma_viscosity_interval = exp_interval(summaries[posterior.plasma_viscosity_index()].interval);
  } else {
    out.plasma_viscosity_median = sample.plasma.eta0;
    out.plasma_viscosity_interval = {sample.plasma.eta0, sample.plasma.eta0, options.sampler.interval_level};
  }
  for (std::size_t k = 0; k < posterior.nuisances().size(); ++k) {
    const ParameterSummary& p = summaries[posterior.nuisance_index() + static_cast<int>(k)];
    out.nuisances.push_back({posterior.nuisances()[k], p.median, p.interval});
  }
  return out;
}

}  // namespace rbcal::calibration
