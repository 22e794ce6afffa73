#include "calibration/saved_draws.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "calibration/detail/draw_predictions.hpp"
#include "calibration/posterior.hpp"
#include "calibration/viscosity_observation.hpp"

namespace rbcal::calibration {

namespace {

// Every `thin`-th step after burn-in, counted back from the last step, so that the final state
// is always kept (and a thinning by a multiple of `thin` keeps a subset of these steps).
DrawThinning every_nth_step(const McmcResult& r, int thin) {
  const int kept = std::max(0, r.steps - r.burn_in_steps);
  return {r.burn_in_steps + (kept > 0 ? (kept - 1) % thin : 0), thin};
}

std::vector<int> steps_of(const McmcResult& r, const DrawThinning& t) {
  std::vector<int> steps;
  for (int step = t.first; step < r.steps; step += t.thin) steps.push_back(step);
  return steps;
}

}  // namespace

DrawThinning thin_draws(const McmcResult& r, int max_draws) {
  long long per_step = 0;
  for (const EnsembleChain& c : r.chains) per_step += c.walkers();
  const long long kept_steps = std::max(0, r.steps - r.burn_in_steps);
  const long long budget = std::max(1, max_draws);
  return every_nth_step(r, static_cast<int>(std::max(1LL, (kept_steps * per_step + budget - 1) / budget)));
}

SavedDraws saved_draws(const surrogate::ViscosityModel& model, const McmcCalibration& calibration, int max_draws) {
  const McmcResult& r = calibration.mcmc;
  SavedDraws out;
  out.parameter_names = r.parameter_names;
  out.points = calibration.points;
  if (r.chains.empty() || calibration.points.empty()) return out;
  out.walkers = r.chains.front().walkers();
  for (const EnsembleChain& c : r.chains)
    if (c.walkers() != out.walkers) throw std::invalid_argument("saved draws: chains with different walker counts");
  out.chains = static_cast<int>(r.chains.size());
  const DrawThinning t = thin_draws(r, max_draws);
  out.steps = steps_of(r, t);
  // The point-wise log-likelihood holds draws x points numbers, each draw a prediction at every
  // point: beyond kMaxLikelihoodValues (4 MB; a sample of hundreds of points) every m-th of
  // these steps only, so that they stay a subset of chains.csv's.
  const long long values = static_cast<long long>(out.steps.size()) * out.chains * out.walkers *
                           static_cast<long long>(calibration.points.size());
  if (values > kMaxLikelihoodValues)
    out.steps = steps_of(r, every_nth_step(r, t.thin * static_cast<int>((values + kMaxLikelihoodValues - 1) /
                                                                         kMaxLikelihoodValues)));
  const Eigen::Index series = static_cast<Eigen::Index>(out.chains) * out.walkers;
  const Eigen::Index per = static_cast<Eigen::Index>(out.steps.size()), dims = static_cast<Eigen::Index>(r.parameter_names.size());
  out.parameters.resize(series * per, dims);
  out.log_posterior.resize(series * per);
  for (int k = 0; k < out.chains; ++k)
    for (int w = 0; w < out.walkers; ++w)
      for (Eigen::Index d = 0; d < per; ++d) {
        const Eigen::Index row = (static_cast<Eigen::Index>(k) * out.walkers + w) * per + d;
        const int step = out.steps[static_cast<std::size_t>(d)];
        for (Eigen::Index p = 0; p < dims; ++p) out.parameters(row, p) = r.chains[k].value(step, w, static_cast<int>(p));
        out.log_posterior(row) = r.chains[k].log_density(step, w);
      }
  const LogPosterior posterior(model, calibration.plasma_viscosity, calibration.points, calibration.posterior,
                               calibration.plasma_viscosity_standard_error);
  const bool eta0_is_parameter = posterior.plasma_viscosity_index() >= 0;
  for (const RelativeViscosityPoint& p : calibration.points)
    out.observed_eta_re.push_back(observed_relative_viscosity(p, false, calibration.plasma_viscosity).eta_re);
  const auto at_draw = predictions_at_draws(posterior, out.parameters, out.parameters.rows(), calibration.points);
  out.log_likelihood.resize(out.parameters.rows(), static_cast<Eigen::Index>(calibration.points.size()));
  for (Eigen::Index row = 0; row < out.parameters.rows(); ++row) {
    const Eigen::VectorXd theta = out.parameters.row(row).transpose();
    const ViscosityObservation obs = posterior.observation_at(theta);
    const double discrepancy = posterior.discrepancy(theta);
    for (std::size_t i = 0; i < calibration.points.size(); ++i) {
      const surrogate::ViscosityPrediction& p = at_draw[static_cast<std::size_t>(row)][i];
      const ObservedRelativeViscosity measured =
          observed_relative_viscosity(calibration.points[i], eta0_is_parameter, obs.plasma_viscosity);
      const double sd = predictive_sd(p, discrepancy, measured.sd);
      const double z = (measured.eta_re - p.eta_re) / sd;
      out.log_likelihood(row, static_cast<Eigen::Index>(i)) =
          -0.5 * z * z - std::log(sd) - 0.5 * std::log(2.0 * std::numbers::pi);
    }
  }
  return out;
}

}  // namespace rbcal::calibration
