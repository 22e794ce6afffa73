#pragma once
// Limited-memory BFGS minimisation (Nocedal & Wright, Numerical Optimization, 2nd ed.,
// algorithms 7.4 and 7.5) with a bracketing line search for the weak Wolfe conditions.
// Used for static equilibria of membranes, where the energy is smooth and the Hessian
// is too large to form.
#include <Eigen/Core>
#include <functional>

namespace rbcal::solver {

struct LbfgsSettings {
  int memory = 12;
  int max_iterations = 20000;
  double gradient_tolerance = 1e-8;  // stop when max |g_i| falls below this
};

struct LbfgsResult {
  int iterations = 0;
  double value = 0.0;
  double gradient_max = 0.0;
  bool converged = false;
};

// f(x, g) returns the objective and writes its gradient into g (same size as x).
using Objective = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& gradient)>;

// Minimises f starting from x; x holds the minimiser on return.
LbfgsResult minimize_lbfgs(const Objective& f, Eigen::VectorXd& x, const LbfgsSettings& settings);

}  // namespace rbcal::solver
