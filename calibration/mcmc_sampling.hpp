#pragma once
// Running several independent ensembles ("chains") of the stretch-move sampler until the
// diagnostics of the first parameter say stop (rank-normalised split R-hat < target and bulk
// ESS >= target) or a step limit is reached; summaries of every parameter.
// R-hat compares the independent ensembles (each ensemble's draws pooled over its walkers, split
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

struct McmcOptions {
  int chains = 4;              // independent ensembles
  int walkers = 16;            // per ensemble (at least 2 x dimension recommended)
  double stretch_scale = 2.0;  // a of the stretch move (Goodman & Weare 2010)
  std::uint64_t seed = 20240601;
  int min_steps = 500;       // first check after this many steps per walker
  int check_interval = 250;  // steps between later checks
  int max_steps = 20000;     // stop here even if not converged
  double rhat_target = 1.01;
  double ess_target = 1000.0;
  int threads = 0;  // OpenMP threads over chains (0: OpenMP's default); the log density must be thread-safe
  double interval_level = 0.95;
  double initial_spread = 3.0;  // walkers start at center + spread * scale * N(0, 1) (over-dispersed)
  // Fraction of the steps discarded as warm-up at every check (BDA3's default: the first half).
  // Starting near the MAP a smaller fraction (0.25) saves steps when each prediction is costly.
  double burn_in_fraction = 0.5;
};

// Where walkers start: around center with per-parameter scale (e.g. MAP and Laplace sd).
struct McmcStart {
  Eigen::VectorXd center;
  Eigen::VectorXd scale;
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
  std::vector<EnsembleChain> chains;  // full history, burn-in included
  int steps = 0;                      // per walker
  int burn_in_steps = 0;              // burn_in_fraction of the steps, discarded by summaries and draws()
  bool converged = false;
  std::string stop_reason;
  double acceptance_fraction = 0.0;
  std::vector<ParameterSummary> parameters;
  double seconds = 0.0;

  // Post-burn-in draws: one row per draw (chain, then step, then walker), one column per parameter.
  Eigen::MatrixXd draws() const;
  std::vector<double> parameter_draws(int parameter) const;
  // Chain sets for diagnostics, post-burn-in: one series per walker of every ensemble ...
  std::vector<std::vector<double>> walker_series(int parameter) const;
  // ... and one series per ensemble, its walkers' draws pooled step by step.
  std::vector<std::vector<double>> ensemble_series(int parameter) const;
};

McmcResult sample_posterior(const LogDensity& log_density, const std::vector<std::string>& parameter_names,
                            const McmcStart& start, const McmcOptions& options = {});

}  // namespace rbcal::calibration
