#include "calibration/mcmc_sampling.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <random>
#include <stdexcept>

#include "calibration/chain_diagnostics.hpp"
#include "calibration/detail/independence_sampler.hpp"
#include "formats/short_number.hpp"

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

std::string to_string(SamplerKind kind) { return kind == SamplerKind::Ensemble ? "ensemble" : "independence"; }

SamplerKind sampler_from_string(const std::string& name) {
  if (name == "ensemble") return SamplerKind::Ensemble;
  if (name == "independence") return SamplerKind::Independence;
  throw std::invalid_argument("unknown sampler '" + name + "' (expected ensemble or independence)");
}

namespace {

// Mean and covariance of the walkers' positions over steps [first, steps()) of all chains.
MultivariateT proposal_from(const std::vector<EnsembleSampler>& samplers, int first, double dof) {
  const int d = samplers.front().chain().dimension();
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
  Eigen::MatrixXd second = Eigen::MatrixXd::Zero(d, d);
  double n = 0.0;
  Eigen::VectorXd x(d);
  for (const auto& s : samplers)
    for (int step = first; step < s.chain().steps(); ++step)
      for (int w = 0; w < s.chain().walkers(); ++w) {
        for (int p = 0; p < d; ++p) x(p) = s.chain().value(step, w, p);
        mean += x;
        second += x * x.transpose();
        n += 1.0;
      }
  mean /= n;
  const Eigen::MatrixXd covariance = (second - n * mean * mean.transpose()) / (n - 1.0);
  // A t with dof > 2 and this scale has dof / (dof - 2) times the pilot's covariance: wider
  // than the posterior, with heavier tails, as an independence proposal must be.
  return MultivariateT(mean, covariance, dof);
}

// Advances every sampler by `steps` in parallel over chains; the first exception wins.
template <class Sampler>
void advance_all(std::vector<Sampler>& samplers, int steps, int threads) {
  std::exception_ptr failure;
#pragma omp parallel for num_threads(threads) schedule(static, 1)
  for (int c = 0; c < static_cast<int>(samplers.size()); ++c) {
    try {
      samplers[c].advance(steps);
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

// The acceptance fraction averaged over the samplers.
template <class Sampler>
double mean_acceptance(const std::vector<Sampler>& samplers) {
  double sum = 0.0;
  for (const auto& s : samplers) sum += s.acceptance_fraction();
  return sum / samplers.size();
}

// Runs the samplers, checking the first parameter's R-hat and ESS, until converged or
// max_steps; fills result's steps, burn-in, convergence, chains and acceptance.
template <class Sampler>
void run_until_converged(std::vector<Sampler>& samplers, const McmcOptions& options, int first_check,
                         int check_interval, double burn_in_fraction, int max_steps, int threads,
                         McmcResult& result) {
  const std::string& name = result.parameter_names[0];
  int next_check = std::max(first_check, 8);
  while (true) {
    const int done = samplers.front().chain().steps();
    const int target = std::min(std::max(next_check, done), max_steps);
    if (target > done) advance_all(samplers, target - done, threads);
    result.steps = samplers.front().chain().steps();
    next_check = result.steps + check_interval;
    result.burn_in_steps = static_cast<int>(burn_in_fraction * result.steps);
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
      result.stop_reason = "R-hat " + std::to_string(rhat) + " and bulk ESS " + std::to_string(ess) + " of " +
                           name + " reached the targets";
      break;
    }
    if (result.steps >= max_steps) {
      result.stop_reason = "step limit " + std::to_string(options.max_steps) + " reached with R-hat " +
                           std::to_string(rhat) + " and bulk ESS " + std::to_string(ess) + " of " + name;
      break;
    }
  }
  result.chains.clear();
  for (const auto& s : samplers) result.chains.push_back(s.chain());
  result.acceptance_fraction = mean_acceptance(samplers);
}

}  // namespace

McmcResult sample_posterior(const LogDensity& log_density, const std::vector<std::string>& parameter_names,
                            const McmcStart& start, const McmcOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const int d = static_cast<int>(parameter_names.size());
  if (start.center.size() != d || start.scale.size() != d)
    throw std::invalid_argument("MCMC: start point and scale must have one entry per parameter");
  if (options.chains < 1 || options.walkers < 2 || options.max_steps < 8)
    throw std::invalid_argument("MCMC: need chains >= 1, walkers >= 2 and max_steps >= 8");
  if (!(options.burn_in_fraction <= 0.9))
    throw std::invalid_argument("MCMC: burn_in_fraction must not exceed 0.9");
  const bool independence = options.sampler == SamplerKind::Independence;
  if (independence && (options.pilot_steps < 8 || !(options.proposal_dof > 2.0)))
    throw std::invalid_argument("MCMC: the independence sampler needs pilot_steps >= 8 and proposal_dof > 2");

  std::vector<EnsembleSampler> ensembles;
  for (int c = 0; c < options.chains; ++c)
    ensembles.emplace_back(log_density, initial_walkers(log_density, start, options, c),
                           derived_seed(options.seed, c, 2), options.stretch_scale);

  McmcResult result;
  result.parameter_names = parameter_names;
  const int threads =
#ifdef _OPENMP
      options.threads > 0 ? options.threads : omp_get_max_threads();
#else
      1;
#endif
  // Options left at 0 (steps) or below 0 (burn-in) take the sampler's default.
  auto steps_or = [](int given, int fallback) { return given > 0 ? given : fallback; };
  auto burn_in_or = [&](double fallback) { return options.burn_in_fraction >= 0.0 ? options.burn_in_fraction : fallback; };
  const auto run_ensembles = [&] {
    result.sampler = "ensemble (stretch move, a = " + formats::short_number(options.stretch_scale) + ")";
    run_until_converged(ensembles, options, steps_or(options.min_steps, 500), steps_or(options.check_interval, 250),
                        burn_in_or(0.5), options.max_steps, threads, result);
  };
  const int pilot = std::min(options.pilot_steps, options.max_steps / 2);
  if (!independence || pilot < 8) {
    run_ensembles();
  } else {
    advance_all(ensembles, pilot, threads);
    std::vector<IndependenceSampler> samplers;
    std::string unfit;  // why the independence stage did not run
    try {
      const MultivariateT proposal = proposal_from(ensembles, pilot / 2, options.proposal_dof);
      for (int c = 0; c < options.chains; ++c) {
        Eigen::MatrixXd last(d, options.walkers);
        for (int w = 0; w < options.walkers; ++w)
          for (int p = 0; p < d; ++p) last(p, w) = ensembles[c].chain().value(pilot - 1, w, p);
        samplers.emplace_back(log_density, last, proposal, derived_seed(options.seed, c, 3));
      }
    } catch (const std::invalid_argument& e) {
      unfit = std::string("no proposal could be fitted to the pilot (") + e.what() + ")";
    }
    const int first_check = steps_or(options.min_steps, 100);
    if (unfit.empty()) {
      // The first check's acceptance says whether the proposal fits; if not, the pilot goes on.
      advance_all(samplers, std::max(8, std::min(first_check, options.max_steps - pilot)), threads);
      const double acceptance = mean_acceptance(samplers);
      if (acceptance < options.min_acceptance)
        unfit = "the independence proposal was accepted in only " + formats::short_number(acceptance, 2) +
                " of its first draws";
    }
    if (!unfit.empty()) {
      run_ensembles();
      result.sampler += "; " + unfit + ", so the pilot ensembles went on";
    } else {
      result.pilot_steps = pilot;
      run_until_converged(samplers, options, first_check, steps_or(options.check_interval, 50), burn_in_or(0.1),
                          options.max_steps - pilot, threads, result);
      result.sampler = "independence Metropolis-Hastings (multivariate t, " + formats::short_number(options.proposal_dof) +
                       " dof, fitted to a " + std::to_string(pilot) + "-step stretch-move pilot)";
    }
  }
  for (int p = 0; p < d; ++p) result.parameters.push_back(summarise(result, p, options.interval_level));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace rbcal::calibration
