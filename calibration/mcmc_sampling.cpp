#include "calibration/mcmc_sampling.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>

#include "calibration/chain_diagnostics.hpp"
#include "calibration/detail/independence_sampler.hpp"
#include "formats/parallel_for.hpp"
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

namespace {

// The positions of steps [first_step, steps()) of every chain, one row per draw (chain, then
// step, then walker).
Eigen::MatrixXd stacked_draws(const std::vector<EnsembleChain>& chains, int first_step) {
  const int d = chains.empty() ? 0 : chains.front().dimension();
  Eigen::Index rows = 0;
  for (const auto& chain : chains) rows += static_cast<Eigen::Index>(chain.steps() - first_step) * chain.walkers();
  Eigen::MatrixXd out(rows, d);
  Eigen::Index r = 0;
  for (const auto& chain : chains)
    for (int s = first_step; s < chain.steps(); ++s)
      for (int w = 0; w < chain.walkers(); ++w, ++r)
        for (int p = 0; p < d; ++p) out(r, p) = chain.value(s, w, p);
  return out;
}

}  // namespace

Eigen::MatrixXd McmcResult::draws() const { return stacked_draws(chains, burn_in_steps); }

Eigen::VectorXd McmcResult::draw_log_densities() const {
  Eigen::Index rows = 0;
  for (const auto& chain : chains) rows += static_cast<Eigen::Index>(chain.steps() - burn_in_steps) * chain.walkers();
  Eigen::VectorXd out(rows);
  Eigen::Index r = 0;
  for (const auto& chain : chains)
    for (int s = burn_in_steps; s < chain.steps(); ++s)
      for (int w = 0; w < chain.walkers(); ++w, ++r) out(r) = chain.log_density(s, w);
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
  formats::parallel_for(static_cast<std::ptrdiff_t>(samplers.size()), threads,
                        [&](std::ptrdiff_t c) { samplers[static_cast<std::size_t>(c)].advance(steps); });
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
  result.converged = false;
  int next_check = std::max(first_check, 8);
  while (true) {
    const int done = samplers.front().chain().steps();
    const int target = std::min(std::max(next_check, done), max_steps);
    if (target > done) advance_all(samplers, target - done, threads);
    result.steps = samplers.front().chain().steps();
    // Every check_interval steps, or every eighth of the steps so far when that is more: the
    // diagnostics cost grows with the draws, and a slow chain is not checked quadratically often.
    next_check = result.steps + std::max(check_interval, result.steps / 8);
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

// An independence proposal must be wider than the posterior in every direction. A t fitted to
// a pilot's draws is, by construction; one about a mode with its Laplace covariance need not be
// (a posterior wider than its curvature at the mode says): its draws then spread as far as the
// proposal reaches and no farther, and no chain diagnostic shows it. The largest variance of the
// draws relative to the proposal's, over all directions (the top generalised eigenvalue): a
// Gaussian posterior under a 4-dof t with its covariance as scale gives 0.5.
constexpr double kMaxSpreadRatio = 0.8;

double spread_ratio(const Eigen::MatrixXd& draws, const MultivariateT& proposal) {
  const Eigen::RowVectorXd mean = draws.colwise().mean();
  const Eigen::MatrixXd centred = draws.rowwise() - mean;
  const Eigen::MatrixXd covariance = centred.transpose() * centred / static_cast<double>(draws.rows() - 1);
  const Eigen::LLT<Eigen::MatrixXd> llt(proposal.covariance());
  const Eigen::MatrixXd whitened =
      llt.matrixL().solve(llt.matrixL().solve(covariance).transpose());  // L^-1 C L^-T (C symmetric)
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (whitened + whitened.transpose()), Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

// Where the walkers of one chain start: dimension x walkers, and their log densities.
struct WalkerStart {
  Eigen::MatrixXd positions;
  Eigen::VectorXd log_density;
};

// Walkers drawn from the proposal, each with a finite log density.
WalkerStart walkers_from(const MultivariateT& proposal, const LogDensity& log_density, int walkers, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  WalkerStart out{Eigen::MatrixXd(proposal.dimension(), walkers), Eigen::VectorXd(walkers)};
  for (int w = 0; w < walkers; ++w)
    for (int tries = 0;; ++tries) {
      out.positions.col(w) = proposal.draw(rng);
      out.log_density(w) = log_density(out.positions.col(w));
      if (std::isfinite(out.log_density(w))) break;
      if (tries > 10000) throw std::invalid_argument("no draw of the proposal with a finite log density in 10000 tries");
    }
  return out;
}

}  // namespace

McmcResult sample_posterior(const LogDensity& uncounted_log_density, const std::vector<std::string>& parameter_names,
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

  std::atomic<long long> evaluations{0};
  const LogDensity log_density = [&](const Eigen::VectorXd& theta) {
    evaluations.fetch_add(1, std::memory_order_relaxed);
    return uncounted_log_density(theta);
  };

  std::vector<EnsembleSampler> ensembles;  // started when needed: the pilot, or the ensemble sampler
  const auto start_ensembles = [&] {
    if (!ensembles.empty()) return;
    for (int c = 0; c < options.chains; ++c)
      ensembles.emplace_back(log_density, initial_walkers(log_density, start, options, c),
                             derived_seed(options.seed, c, 2), options.stretch_scale);
  };

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
    start_ensembles();
    result.sampler = "ensemble (stretch move, a = " + formats::short_number(options.stretch_scale) + ")";
    run_until_converged(ensembles, options, steps_or(options.min_steps, 500), steps_or(options.check_interval, 250),
                        burn_in_or(0.5), options.max_steps, threads, result);
  };
  const int first_check = steps_or(options.min_steps, 40);
  const int stage_walkers = std::min(options.walkers, std::max(2, options.independence_walkers));
  // The independence stage with this proposal from these walkers, if its first check accepts
  // often enough; otherwise why not.
  const auto try_independence = [&](const MultivariateT& proposal, const std::vector<WalkerStart>& initial,
                                    int steps_left, double burn_in, bool check_spread) -> std::string {
    std::vector<IndependenceSampler> samplers;
    for (int c = 0; c < options.chains; ++c) {
      const WalkerStart& w = initial[static_cast<std::size_t>(c)];
      samplers.emplace_back(log_density, w.positions, w.log_density, proposal, derived_seed(options.seed, c, 3));
    }
    advance_all(samplers, std::max(8, std::min(first_check, steps_left)), threads);
    const double acceptance = mean_acceptance(samplers);
    if (acceptance < options.min_acceptance)
      return "the independence proposal was accepted in only " + formats::short_number(acceptance, 2) +
             " of its first draws";
    // The spread, at the first check and at the end.
    const auto too_narrow = [&](const Eigen::MatrixXd& draws) -> std::string {
      const double ratio = check_spread ? spread_ratio(draws, proposal) : 0.0;
      if (ratio <= kMaxSpreadRatio) return "";
      return "the posterior reached " + formats::short_number(ratio, 2) +
             " of the proposal's variance in one direction: a proposal too narrow to trust";
    };
    std::vector<EnsembleChain> first;
    for (const auto& sampler : samplers) first.push_back(sampler.chain());
    if (std::string why = too_narrow(stacked_draws(first, 0)); !why.empty()) return why;
    run_until_converged(samplers, options, first_check, steps_or(options.check_interval, 8), burn_in_or(burn_in),
                        steps_left, threads, result);
    if (std::string why = too_narrow(result.draws()); !why.empty()) return why;
    result.proposal_log_weights.clear();
    for (const auto& sampler : samplers)
      result.proposal_log_weights.insert(result.proposal_log_weights.end(), sampler.proposal_log_weights().begin(),
                                         sampler.proposal_log_weights().end());
    return "";
  };
  std::string without_pilot;  // why the start's covariance did not serve
  if (independence && start.covariance.size() > 0) {
    try {
      // A t with dof > 2 and this scale has dof / (dof - 2) times the Laplace covariance.
      const MultivariateT proposal(start.center, start.covariance, options.proposal_dof);
      std::vector<WalkerStart> initial(static_cast<std::size_t>(options.chains));
      formats::parallel_for(options.chains, threads, [&](std::ptrdiff_t c) {
        initial[static_cast<std::size_t>(c)] =
            walkers_from(proposal, log_density, stage_walkers, derived_seed(options.seed, static_cast<int>(c), 4));
      });
      without_pilot = try_independence(proposal, initial, options.max_steps, 0.1, true);
    } catch (const std::invalid_argument& e) {
      without_pilot = std::string("no proposal from the start's covariance (") + e.what() + ")";
    }
    if (without_pilot.empty())
      result.sampler = "independence Metropolis-Hastings (multivariate t, " + formats::short_number(options.proposal_dof) +
                       " dof, about the start with its Laplace covariance)";
  }
  const int pilot = std::min(options.pilot_steps, options.max_steps / 2);
  if (independence && start.covariance.size() > 0 && without_pilot.empty()) {
    // done
  } else if (!independence || pilot < 8) {
    run_ensembles();
  } else {
    start_ensembles();
    advance_all(ensembles, pilot, threads);
    std::string unfit;  // why the independence stage did not run
    try {
      const MultivariateT proposal = proposal_from(ensembles, pilot / 2, options.proposal_dof);
      std::vector<WalkerStart> initial;
      for (int c = 0; c < options.chains; ++c) {
        WalkerStart last{Eigen::MatrixXd(d, stage_walkers), Eigen::VectorXd(stage_walkers)};
        for (int w = 0; w < stage_walkers; ++w) {
          for (int p = 0; p < d; ++p) last.positions(p, w) = ensembles[c].chain().value(pilot - 1, w, p);
          last.log_density(w) = ensembles[c].chain().log_density(pilot - 1, w);
        }
        initial.push_back(std::move(last));
      }
      // The first check's acceptance says whether the proposal fits; if not, the pilot goes on.
      unfit = try_independence(proposal, initial, options.max_steps - pilot, 0.1, false);
    } catch (const std::invalid_argument& e) {
      unfit = std::string("no proposal could be fitted to the pilot (") + e.what() + ")";
    }
    if (!unfit.empty()) {
      run_ensembles();
      result.sampler += "; " + unfit + ", so the pilot ensembles went on";
    } else {
      result.pilot_steps = pilot;
      result.sampler = "independence Metropolis-Hastings (multivariate t, " + formats::short_number(options.proposal_dof) +
                       " dof, fitted to a " + std::to_string(pilot) + "-step stretch-move pilot)";
    }
    if (!without_pilot.empty()) result.sampler += "; without a pilot " + without_pilot;
  }
  for (int p = 0; p < d; ++p) result.parameters.push_back(summarise(result, p, options.interval_level));
  result.evaluations = evaluations.load();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace rbcal::calibration
