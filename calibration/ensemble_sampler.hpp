#pragma once
// Affine-invariant ensemble sampler with the stretch move (Goodman & Weare 2010, Comm. App. Math.
// Comp. Sci. 5(1) 65-80): one ensemble of walkers updated in turn; for walker k a partner j != k
// is drawn, Y = X_j + z (X_k - X_j) with z ~ g(z) proportional to 1/sqrt(z) on [1/a, a], accepted
// with probability min(1, z^(d-1) p(Y) / p(X_k)).
// Deterministic for a given seed (std::mt19937_64). Several independent ensembles make the
// "chains" of the convergence diagnostics.
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Dense>

namespace rbcal::calibration {

using LogDensity = std::function<double(const Eigen::VectorXd&)>;

// Proposals made and accepted by a sampler, over all its steps.
struct AcceptanceCount {
  long long accepted = 0;
  long long proposed = 0;
  double fraction() const { return proposed > 0 ? static_cast<double>(accepted) / static_cast<double>(proposed) : 0.0; }
};

// The stored history of one ensemble: positions and log densities per step and walker.
class EnsembleChain {
 public:
  EnsembleChain(int dimension, int walkers) : dimension_(dimension), walkers_(walkers) {}
  int dimension() const { return dimension_; }
  int walkers() const { return walkers_; }
  int steps() const { return static_cast<int>(log_density_.size() / static_cast<std::size_t>(walkers_)); }
  double value(int step, int walker, int parameter) const {
    return positions_[(static_cast<std::size_t>(step) * walkers_ + walker) * dimension_ + parameter];
  }
  double log_density(int step, int walker) const {
    return log_density_[static_cast<std::size_t>(step) * walkers_ + walker];
  }
  // One series per walker of `parameter` over steps [first_step, steps()).
  std::vector<std::vector<double>> walker_series(int parameter, int first_step) const;
  void append(const Eigen::MatrixXd& positions, const Eigen::VectorXd& log_density);  // dimension x walkers

 private:
  int dimension_;
  int walkers_;
  std::vector<double> positions_;
  std::vector<double> log_density_;
};

class EnsembleSampler {
 public:
  // initial: dimension x walkers, all with finite log density; walkers >= 2 * dimension
  // recommended (at least dimension + 1 for the ensemble to span the space).
  EnsembleSampler(LogDensity log_density, const Eigen::MatrixXd& initial, std::uint64_t seed,
                  double stretch_scale = 2.0);
  void advance(int steps);  // appends each step's ensemble to the chain
  const EnsembleChain& chain() const { return chain_; }
  double acceptance_fraction() const { return acceptance_.fraction(); }  // over all steps so far

 private:
  LogDensity log_density_;
  Eigen::MatrixXd positions_;
  Eigen::VectorXd current_log_density_;
  std::mt19937_64 rng_;
  double stretch_scale_;
  EnsembleChain chain_;
  AcceptanceCount acceptance_;
};

}  // namespace rbcal::calibration
