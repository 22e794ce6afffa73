#pragma once
// Independence Metropolis-Hastings with a multivariate Student-t proposal (Tierney 1994, Ann.
// Statist. 22(4) 1701-1728; Robert & Casella, Monte Carlo Statistical Methods, 2nd ed., sec. 7.4).
// Every proposal Y is drawn from the same density q, whatever the current state X, and accepted with
// probability min(1, w(Y) / w(X)), w = p / q. When q is close to the posterior p (a t fitted to draws
// of a short ensemble pilot, for the near-Gaussian posteriors of a calibration) almost every
// proposal is an independent draw, several times fewer evaluations per effective sample than the
// stretch move needs; q's heavier-than-Gaussian tails keep w bounded where p is near-Gaussian. A
// poor fit shows as a low acceptance fraction (mcmc_sampling.cpp then goes on with the ensemble).
// Several walkers, each its own chain, advance in turn; the history is stored like an ensemble's.
// Deterministic for a given seed (std::mt19937_64).
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "calibration/ensemble_sampler.hpp"

namespace rbcal::calibration {

// Multivariate t with `dof` degrees of freedom, location `mean` and scale matrix `scale`
// (covariance dof / (dof - 2) x scale for dof > 2).
class MultivariateT {
 public:
  MultivariateT(Eigen::VectorXd mean, const Eigen::MatrixXd& scale, double dof);
  Eigen::VectorXd draw(std::mt19937_64& rng) const;
  // The draw made of z ~ N(0, I) and g ~ chi^2(dof): mean + L z sqrt(dof / g).
  Eigen::VectorXd from_standard(const Eigen::VectorXd& z, double chi_squared) const;
  double log_density(const Eigen::VectorXd& x) const;  // up to an additive constant ...
  double log_normaliser() const;                         // ... which is this
  Eigen::MatrixXd covariance() const;                    // dof / (dof - 2) x scale; dof > 2
  int dimension() const { return static_cast<int>(mean_.size()); }

 private:
  Eigen::VectorXd mean_;
  Eigen::MatrixXd lower_;  // Cholesky factor of the scale matrix
  double dof_;
};

class IndependenceSampler {
 public:
  // initial: dimension x walkers, each with a finite log density; initial_log_density: theirs
  // when known (empty: evaluated here).
  IndependenceSampler(LogDensity log_density, const Eigen::MatrixXd& initial, const Eigen::VectorXd& initial_log_density,
                      MultivariateT proposal, std::uint64_t seed);
  void advance(int steps);  // appends each step's walkers to the chain
  const EnsembleChain& chain() const { return chain_; }
  double acceptance_fraction() const { return acceptance_.fraction(); }
  // ln p - ln q (q normalised) of every proposal so far, in order: draws of q with their
  // importance weights, an importance sample of p's normalising constant.
  const std::vector<double>& proposal_log_weights() const { return proposal_log_weights_; }

 private:
  LogDensity log_density_;
  MultivariateT proposal_;
  std::vector<double> proposal_log_weights_;
  Eigen::MatrixXd positions_;
  Eigen::VectorXd log_weight_;  // ln p - ln q of each walker's current state
  Eigen::VectorXd current_log_density_;
  std::mt19937_64 rng_;
  EnsembleChain chain_;
  AcceptanceCount acceptance_;
};

}  // namespace rbcal::calibration
