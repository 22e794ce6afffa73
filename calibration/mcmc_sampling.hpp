#pragma once
// Running several independent groups of walkers ("chains") until the diagnostics of the first
// parameter say stop (rank-normalised split R-hat < target and bulk ESS >= target) or a step limit
// is reached; summaries of every parameter. Two samplers:
//   ensemble:     the stretch move (ensemble_sampler.hpp) throughout;
//   independence: independence Metropolis-Hastings with a multivariate t proposal
//                 (independence_sampler.hpp), about the start's centre with its Laplace covariance
//                 when the start has one; without one, or when that proposal is accepted too
//                 rarely, a short stretch-move pilot first and a t fitted to its second half; if
//                 that proposal too is accepted too rarely, the pilot ensembles go on instead.
// R-hat compares the independent groups (each group's draws pooled over its walkers, split
// in halves by step): walkers of one ensemble are not independent chains. ESS and the
// autocorrelation time use one series per walker (the within-walker autocorrelation, averaged over
// walkers as emcee does, Foreman-Mackey et al. 2013), with the multi-chain estimator.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration/ensemble_sampler.hpp"
#include "calibration/quantiles.hpp"

namespace rbcal::calibration {

enum class SamplerKind { Ensemble, Independence };
std::string to_string(SamplerKind kind);
SamplerKind sampler_from_string(const std::string& name);  // "ensemble" or "independence"

struct McmcOptions {
  SamplerKind sampler = SamplerKind::Independence;
  int chains = 4;              // independent groups of walkers
  int walkers = 16;            // per group (at least 2 x dimension recommended; calibrate_mcmc: 0 = auto)
  double stretch_scale = 2.0;  // a of the stretch move (Goodman & Weare 2010)
  std::uint64_t seed = 20240601;
  // First check after this many steps per walker, later checks every check_interval steps
  // (0: the sampler's default, 500 and 250 for the ensemble, 40 and 8 for the independence
  // stage, whose draws are nearly independent: ESS 1000 takes some 1500 draws, about 50 steps
  // of 4 x 8 walkers). Steps of the pilot do not count here.
  int min_steps = 0;
  int check_interval = 0;
  int max_steps = 20000;  // stop here even if not converged (per walker, the pilot included)
  double rhat_target = 1.01;
  double ess_target = 1000.0;
  int threads = 0;  // OpenMP threads over chains (0: OpenMP's default); the log density must be thread-safe
  double interval_level = 0.95;
  double initial_spread = 3.0;  // walkers start at center + spread * scale * N(0, 1) (over-dispersed)
  // Fraction of the steps discarded as warm-up at every check (BDA3's default: the first half).
  // Starting near the MAP a smaller fraction (0.25) saves steps when each prediction is costly.
  // Negative: the sampler's default, 0.5 for the ensemble and 0.1 for the independence stage
  // (after a pilot, which is discarded whole, its walkers start near the posterior; from the
  // proposal's draws, a walker is at the posterior once it has accepted a move, within a
  // few steps at the acceptance the stage requires).
  double burn_in_fraction = -1.0;
  // Independence sampler: stretch-move steps of the pilot (the proposal is fitted to their
  // second half), the proposal's degrees of freedom, and the acceptance fraction at the first
  // check below which the pilot ensembles take over.
  int pilot_steps = 100;
  double proposal_dof = 4.0;
  double min_acceptance = 0.2;
  // Walkers per chain of the independence stage. Each is a chain of its own, so fewer, longer
  // series cost the same per draw and give the ESS estimate (per-walker autocorrelations) more
  // to go on; after a pilot the first of its walkers go on.
  int independence_walkers = 8;
};

// Where walkers start: around center with per-parameter scale (e.g. MAP and Laplace sd).
// covariance, when given (d x d, e.g. the Laplace covariance of a fit that found the mode inside
// the support), lets the independence sampler start without a pilot.
struct McmcStart {
  Eigen::VectorXd center;
  Eigen::VectorXd scale;
  Eigen::MatrixXd covariance;  // optional
};

struct ParameterSummary {
  std::string name;
  double mean = 0.0, sd = 0.0, median = 0.0;
  Interval interval;       // central credible interval at options.interval_level
  double rhat = 0.0;          // rank-normalised split R-hat over ensembles (Vehtari et al. 2021)
  double classic_rhat = 0.0;  // split R-hat over ensembles (BDA3)
  double bulk_ess = 0.0;
  double tail_ess = 0.0;
  double autocorrelation_time = 0.0;  // integrated, in steps of one walker
};

struct McmcResult {
  std::vector<std::string> parameter_names;
  std::string sampler;                // what sampled the chains, in words
  int pilot_steps = 0;                // stretch-move steps before `chains` (independence sampler)
  long long evaluations = 0;          // of the log density, all stages and tries included
  // Independence stage: ln p - ln q of every proposal, q the normalised proposal density (an
  // importance sample of the evidence, model_evidence.hpp); empty for the ensemble.
  std::vector<double> proposal_log_weights;
  std::vector<EnsembleChain> chains;  // full history after the pilot, burn-in included
  int steps = 0;                      // per walker, in `chains`
  int burn_in_steps = 0;              // burn_in_fraction of the steps, discarded by summaries and draws()
  bool converged = false;
  std::string stop_reason;
  double acceptance_fraction = 0.0;
  std::vector<ParameterSummary> parameters;
  double seconds = 0.0;

  // Post-burn-in draws: one row per draw (chain, then step, then walker), one column per parameter.
  Eigen::MatrixXd draws() const;
  Eigen::VectorXd draw_log_densities() const;  // the log density of each row of draws()
  std::vector<double> parameter_draws(int parameter) const;
  // Chain sets for diagnostics, post-burn-in: one series per walker of every ensemble ...
  std::vector<std::vector<double>> walker_series(int parameter) const;
  // ... and one series per ensemble, its walkers' draws pooled step by step.
  std::vector<std::vector<double>> ensemble_series(int parameter) const;
};

McmcResult sample_posterior(const LogDensity& log_density, const std::vector<std::string>& parameter_names,
                            const McmcStart& start, const McmcOptions& options = {});

}  // namespace rbcal::calibration
