#include "calibration/mcmc_sampling.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <random>
#include <stdexcept>

#include "calibration/chain_diagnostics.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace rbcal::calibration {

namespace {

std::uint64_t derived_seed(std::uint64_t seed, int chain, std::uint32_t purpose) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(chain), purpose};
  std::uint64_t out[1];
  std::uint32_t words[2];
  sequence.generate(words, words + 2);
  out[0] = (static_cast<std::uint64_t>(words[0]) << 32) | words[1];
  return out[0];
}

Eigen::MatrixXd initial_walkers(const LogDensity& log_density, const McmcStart& start, const McmcOptions& options,
                                int chain) {
  const int d = static_cast<int>(start.center.size());
  std::mt19937_64 rng(derived_seed(options.seed, chain, 1));
  std::normal_distribution<double> normal;
  Eigen::MatrixXd walkers(d, options.walkers);
  for (int w = 0; w < options.walkers; ++w) {
    int tries = 0;
    for (;; ++tries) {
      for (int p = 0; p < d; ++p)
        walkers(p, w) = start.center(p) + options.initial_spread * start.scale(p) * normal(rng);
      if (std::isfinite(log_density(walkers.col(w)))) break;
      if (tries > 10000)
        throw std::runtime_error("MCMC: no finite log density near the start point after 10000 tries");
    }
  }
  return walkers;
}

std::vector<double> pooled_series(const EnsembleChain& chain, int parameter, int first_step) {
  std::vector<double> series;
  for (int s = first_step; s < chain.steps(); ++s)
    for (int w = 0; w < chain.walkers(); ++w) series.push_back(chain.value(s, w, parameter));
  return series;
}

ParameterSummary summarise(const McmcResult& result, int parameter, double level) {
  ParameterSummary s;
  s.name = result.parameter_names[parameter];
  const std::vector<double> draws = result.parameter_draws(parameter);
  double sum = 0.0, squares = 0.0;
  for (double x : draws) sum += x;
  s.mean = sum / draws.size();
  for (double x : draws) squares += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(squares / (draws.size() - 1.0));
  s.median = quantile(draws, 0.5);
  s.interval = central_interval(draws, level);
  const auto ensembles = result.ensemble_series(parameter);
  s.rhat = rank_normalized_split_rhat(ensembles);
  s.classic_rhat = split_rhat(ensembles);
  const auto chains = result.walker_series(parameter);
  s.bulk_ess = bulk_effective_sample_size(chains);
  s.tail_ess = tail_effective_sample_size(chains);
  s.autocorrelation_time = integrated_autocorrelation_time(chains);
  return s;
}

}  // namespace

std::vector<std::vector<double>> McmcResult::walker_series(int parameter) const {
  std::vector<std::vector<double>> all;
  for (const auto& chain : chains) {
    auto series = chain.walker_series(parameter, burn_in_steps);
    all.insert(all.end(), series.begin(), series.end());
  }
  return all;
}

std::vector<std::vector<double>> McmcResult::ensemble_series(int parameter) const {
  std::vector<std::vector<double>> all;
  for (const auto& chain : chains) all.push_back(pooled_series(chain, parameter, burn_in_steps));
  return all;
}

std::vector<double> McmcResult::parameter_draws(int parameter) const {
  std::vector<double> draws;
  for (const auto& chain : chains) {
    const auto series = pooled_series(chain, parameter, burn_in_steps);
    draws.insert(draws.end(), series.begin(), series.end());
  }
  return draws;
}

Eigen::MatrixXd McmcResult::draws() const {
  const int d = static_cast<int>(parameter_names.size());
  Eigen::Index rows = 0;
  for (const auto& chain : chains) rows += static_cast<Eigen::Index>(chain.steps() - burn_in_steps) * chain.walkers();
  Eigen::MatrixXd out(rows, d);
  Eigen::Index r = 0;
  for (const auto& chain : chains)
    for (int s = burn_in_steps; s < chain.steps(); ++s)
      for (int w = 0; w < chain.walkers(); ++w, ++r)
        for (int p = 0; p < d; ++p) out(r, p) = chain.value(s, w, p);
  return out;
}

McmcResult sample_posterior(const LogDensity& log_density, const std::vector<std::string>& parameter_names,
                            const McmcStart& start, const McmcOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const int d = static_cast<int>(parameter_names.size());
  if (start.center.size() != d || start.scale.size() != d)
    throw std::invalid_argument("MCMC: start point and scale must have one entry per parameter");
  if (options.chains < 1 || options.walkers < 2 || options.max_steps < 8)
    throw std::invalid_argument("MCMC: need chains >= 1, walkers >= 2 and max_steps >= 8");
  if (!(options.burn_in_fraction >= 0.0 && options.burn_in_fraction <= 0.9))
    throw std::invalid_argument("MCMC: burn_in_fraction must lie in [0, 0.9]");

  std::vector<EnsembleSampler> samplers;
  for (int c = 0; c < options.chains; ++c)
    samplers.emplace_back(log_density, initial_walkers(log_density, start, options, c),
                          derived_seed(options.seed, c, 2), options.stretch_scale);

  McmcResult result;
  result.parameter_names = parameter_names;
  const int threads =
#ifdef _OPENMP
      options.threads > 0 ? options.threads : omp_get_max_threads();
#else
      1;
#endif
  while (true) {
    const int batch = std::min(result.steps == 0 ? std::max(options.min_steps, 8) : options.check_interval,
                               options.max_steps - result.steps);
    std::exception_ptr failure;
#pragma omp parallel for num_threads(threads) schedule(static, 1)
    for (int c = 0; c < options.chains; ++c) {
      try {
        samplers[c].advance(batch);
      } catch (...) {
#pragma omp critical
        failure = std::current_exception();
      }
    }
    if (failure) std::rethrow_exception(failure);
    result.steps += batch;
    result.burn_in_steps = static_cast<int>(options.burn_in_fraction * result.steps);
    std::vector<std::vector<double>> walkers, ensembles;
    for (const auto& s : samplers) {
      auto series = s.chain().walker_series(0, result.burn_in_steps);
      walkers.insert(walkers.end(), series.begin(), series.end());
      ensembles.push_back(pooled_series(s.chain(), 0, result.burn_in_steps));
    }
    const double rhat = rank_normalized_split_rhat(ensembles);
    const double ess = bulk_effective_sample_size(walkers);
    if (rhat < options.rhat_target && ess >= options.ess_target) {
      result.converged = true;
      result.stop_reason = "R-hat " + std::to_string(rhat) + " and bulk ESS " + std::to_string(ess) +
                           " of " + parameter_names[0] + " reached the targets";
      break;
    }
    if (result.steps >= options.max_steps) {
      result.stop_reason = "step limit " + std::to_string(options.max_steps) + " reached with R-hat " +
                           std::to_string(rhat) + " and bulk ESS " + std::to_string(ess) + " of " +
                           parameter_names[0];
      break;
    }
  }
  double acceptance = 0.0;
  for (const auto& s : samplers) {
    acceptance += s.acceptance_fraction();
    result.chains.push_back(s.chain());
  }
  result.acceptance_fraction = acceptance / options.chains;
  for (int p = 0; p < d; ++p) result.parameters.push_back(summarise(result, p, options.interval_level));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace rbcal::calibration
