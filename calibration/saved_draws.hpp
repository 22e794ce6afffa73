#pragma once
// The MCMC draws a report keeps, evenly thinned by step (every walker of every chain at each
// kept step), with each draw's log posterior and the log-likelihood of each data point: what
// chains.csv and the ArviZ posterior file (calibration/detail/posterior_netcdf.hpp) hold.
//
// The point-wise log-likelihood is the marginal normal log density of each observed eta_re
// under the draw: mean the model's eta_re, variance the model's own (predictive sd), the
// discrepancy term and the point's measurement error, as the posterior predictive check
// draws it. The likelihood itself correlates the model's errors across points, so these
// terms do not sum to the joint log-likelihood; they are what point-wise diagnostics (PSIS-LOO,
// WAIC) need, with that caveat.
#include <vector>

#include <Eigen/Dense>

#include "calibration/mcmc_calibration.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

// Steps first, first + thin, ... < steps of every chain; the last step always among them.
struct DrawThinning {
  int first = 0, thin = 1;
};
// At most about `max_draws` draws (all walkers of all chains per kept step) after burn-in.
DrawThinning thin_draws(const McmcResult& result, int max_draws);

struct SavedDraws {
  std::vector<std::string> parameter_names;  // as the posterior has them (ln_G_s, ln_lambda, ..., offset_c)
  int chains = 0, walkers = 0;               // walker series c = chain k * walkers + walker w
  std::vector<int> steps;                    // the kept steps
  // Row c * steps.size() + d: walker series c at steps[d].
  Eigen::MatrixXd parameters;     // one column per parameter, as sampled (logs where named ln_)
  Eigen::VectorXd log_posterior;  // per row
  Eigen::MatrixXd log_likelihood;  // per row, one column per data point (see above)
  std::vector<RelativeViscosityPoint> points;  // the data points, in the columns' order
  std::vector<double> observed_eta_re;         // each point's measured eta_re (at the plateau eta0)
};

// At most about max_draws draws (thin_draws), fewer where draws x points would exceed this.
inline constexpr long long kMaxLikelihoodValues = 500'000;
SavedDraws saved_draws(const surrogate::ViscosityModel& model, const McmcCalibration& calibration, int max_draws);

}  // namespace rbcal::calibration
