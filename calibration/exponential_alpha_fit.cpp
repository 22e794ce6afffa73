#include "calibration/exponential_alpha_fit.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcal::calibration {

namespace {

double r_squared(const std::vector<double>& observed, const std::vector<double>& fitted) {
  double mean = 0.0;
  for (double y : observed) mean += y;
  mean /= static_cast<double>(observed.size());
  double ss_res = 0.0, ss_tot = 0.0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    ss_res += (observed[i] - fitted[i]) * (observed[i] - fitted[i]);
    ss_tot += (observed[i] - mean) * (observed[i] - mean);
  }
  return ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : (ss_res == 0.0 ? 1.0 : 0.0);
}

double linear_space_cost(const std::vector<double>& phi, const std::vector<double>& y, double alpha) {
  double cost = 0.0;
  for (std::size_t i = 0; i < phi.size(); ++i) cost += std::pow(y[i] - std::exp(alpha * phi[i]), 2);
  return cost;
}

}  // namespace

ExponentialAlphaFit fit_exponential_alpha(const std::vector<double>& phi, const std::vector<double>& eta_re,
                                          AlphaFitSpace space) {
  if (phi.empty() || phi.size() != eta_re.size())
    throw std::invalid_argument("exp(alpha phi) fit needs equally many phi and eta_re values (at least one)");
  double s_xy = 0.0, s_xx = 0.0;
  std::vector<double> log_eta(eta_re.size());
  for (std::size_t i = 0; i < phi.size(); ++i) {
    if (!(eta_re[i] > 0.0)) throw std::invalid_argument("exp(alpha phi) fit needs eta_re > 0");
    log_eta[i] = std::log(eta_re[i]);
    s_xy += phi[i] * log_eta[i];
    s_xx += phi[i] * phi[i];
  }
  if (!(s_xx > 0.0)) throw std::invalid_argument("exp(alpha phi) fit needs some phi > 0");
  double alpha = s_xy / s_xx;  // log-space solution, also the start of the linear-space fit
  ExponentialAlphaFit fit;
  fit.points = static_cast<int>(phi.size());
  std::vector<double> fitted(phi.size());
  if (space == AlphaFitSpace::log_through_origin) {
    for (std::size_t i = 0; i < phi.size(); ++i) fitted[i] = alpha * phi[i];
    fit.alpha = alpha;
    fit.r_squared = r_squared(log_eta, fitted);
    return fit;
  }
  // Gauss-Newton with step halving on sum (y - exp(alpha phi))^2, a 1-D convex-enough problem.
  double cost = linear_space_cost(phi, eta_re, alpha);
  for (int iteration = 0; iteration < 200; ++iteration) {
    double jtr = 0.0, jtj = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) {
      const double model = std::exp(alpha * phi[i]);
      const double jacobian = -phi[i] * model;  // d residual / d alpha, residual = y - model
      jtr += jacobian * (eta_re[i] - model);
      jtj += jacobian * jacobian;
    }
    double step = -jtr / jtj;
    double trial_cost = linear_space_cost(phi, eta_re, alpha + step);
    while (trial_cost > cost && std::abs(step) > 1e-15) {
      step *= 0.5;
      trial_cost = linear_space_cost(phi, eta_re, alpha + step);
    }
    if (trial_cost > cost) break;
    alpha += step;
    cost = trial_cost;
    if (std::abs(step) < 1e-13 * (1.0 + std::abs(alpha))) break;
  }
  for (std::size_t i = 0; i < phi.size(); ++i) fitted[i] = std::exp(alpha * phi[i]);
  fit.alpha = alpha;
  fit.r_squared = r_squared(eta_re, fitted);
  return fit;
}

}  // namespace rbcal::calibration
