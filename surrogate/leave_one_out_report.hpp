#pragma once
// Leave-one-out cross-validation of the viscosity surrogate, from the closed-form GP
// formulas (GaussianProcess::leave_one_out, Rasmussen & Williams 2006 eq. 5.12) at the
// fitted hyper-parameters: how well each case is predicted by all the others.
#include <string>
#include <vector>

namespace rbcal::surrogate {

struct LeaveOneOutCase {
  std::string id;
  double eta_re = 0.0;                 // simulated
  double eta_re_predicted = 0.0;       // exp(LOO mean of ln eta_re)
  double sd = 0.0;                     // eta_re_predicted * LOO sd of ln eta_re (noise of the case included)
  double standardised_residual = 0.0;  // (ln eta_re - LOO mean) / LOO sd; ~ N(0, 1) if the model is right
  double relative_error = 0.0;         // (eta_re_predicted - eta_re) / eta_re
};

struct LeaveOneOutReport {
  std::vector<LeaveOneOutCase> cases;
  double rms_relative_error = 0.0;
  double rms_standardised_residual = 0.0;  // ~1 when the predictive variances are right
  double max_abs_standardised_residual = 0.0;
};

// Table of all cases, summary lines, and a warning line per case with |residual| > limit.
std::string format_leave_one_out(const LeaveOneOutReport& report, double warn_limit = 3.0);

}  // namespace rbcal::surrogate
