#include "solver/numerics/detail/lbfgs.hpp"

#include <cmath>
#include <deque>
#include <limits>
#include <vector>

namespace rbcal::solver {

LbfgsResult minimize_lbfgs(const Objective& f, Eigen::VectorXd& x, const LbfgsSettings& settings) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd g(n), g_new(n), x_new(n), d(n);
  double value = f(x, g);
  std::deque<Eigen::VectorXd> s_hist, y_hist;
  std::deque<double> rho_hist;
  LbfgsResult result;

  for (int iter = 0; iter < settings.max_iterations; ++iter) {
    result.gradient_max = g.cwiseAbs().maxCoeff();
    if (result.gradient_max < settings.gradient_tolerance) {
      result.converged = true;
      result.iterations = iter;
      result.value = value;
      return result;
    }
    // Two-loop recursion: d = -H g.
    d = -g;
    std::vector<double> alpha(s_hist.size());
    for (int i = static_cast<int>(s_hist.size()) - 1; i >= 0; --i) {
      alpha[i] = rho_hist[i] * s_hist[i].dot(d);
      d -= alpha[i] * y_hist[i];
    }
    if (!s_hist.empty()) d *= s_hist.back().dot(y_hist.back()) / y_hist.back().squaredNorm();
    else d /= std::max(1.0, g.norm());  // first step: a unit-length move
    for (std::size_t i = 0; i < s_hist.size(); ++i) {
      const double beta = rho_hist[i] * y_hist[i].dot(d);
      d += (alpha[i] - beta) * s_hist[i];
    }
    double slope = g.dot(d);
    if (!(slope < 0.0)) {  // lost descent: restart from steepest descent
      s_hist.clear();
      y_hist.clear();
      rho_hist.clear();
      d = -g / std::max(1.0, g.norm());
      slope = g.dot(d);
    }

    // Bracketing line search for the weak Wolfe conditions.
    const double c1 = 1e-4, c2 = 0.9;
    double step = 1.0, lo = 0.0, hi = std::numeric_limits<double>::infinity();
    double value_new = value;
    bool accepted = false;
    for (int trial = 0; trial < 60; ++trial) {
      x_new = x + step * d;
      value_new = f(x_new, g_new);
      // Armijo decrease, or near the minimum where round-off hides the decrease, the
      // approximate Wolfe test of Hager & Zhang (SIAM J. Optim. 16 (2005) 170).
      const double slope_new = g_new.dot(d);
      const bool decrease = value_new <= value + c1 * step * slope ||
                            (value_new <= value + 1e-12 * std::abs(value) && slope_new <= (2.0 * c1 - 1.0) * slope);
      if (!std::isfinite(value_new) || !decrease) {
        hi = step;
      } else if (slope_new < c2 * slope) {
        lo = step;
      } else {
        accepted = true;
        break;
      }
      step = std::isinf(hi) ? 2.0 * lo : 0.5 * (lo + hi);
    }
    if (!accepted) {  // no progress possible at this precision
      result.iterations = iter;
      result.value = value;
      return result;
    }
    Eigen::VectorXd s = x_new - x, y = g_new - g;
    const double sy = s.dot(y);
    if (sy > 1e-16 * s.norm() * y.norm()) {
      s_hist.push_back(std::move(s));
      y_hist.push_back(std::move(y));
      rho_hist.push_back(1.0 / sy);
      if (static_cast<int>(s_hist.size()) > settings.memory) {
        s_hist.pop_front();
        y_hist.pop_front();
        rho_hist.pop_front();
      }
    }
    x.swap(x_new);
    g.swap(g_new);
    value = value_new;
  }
  result.iterations = settings.max_iterations;
  result.value = value;
  result.gradient_max = g.cwiseAbs().maxCoeff();
  return result;
}

}  // namespace rbcal::solver
