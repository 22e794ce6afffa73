#pragma once
// Posterior-predictive bands of the suspension viscosity eta(gamma_dot) = eta0 * eta_re per phi:
// median and central interval over posterior draws of (G_s, lambda, sigma_d), optionally with the
// model's predictive sd and the discrepancy term drawn as noise (the measurement error is not
// added: the band is for the true curve a new measurement scatters around). eta0 is each draw's
// when it is a parameter of the posterior, else the plateau estimate.
#include <cstdint>
#include <vector>

#include "calibration/mcmc_calibration.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct PredictiveBandOptions {
  std::vector<double> phis;         // empty: every phi of the calibrated points
  int shear_rate_points = 50;       // ln-uniform grid
  double shear_rate_min = 0.0;      // [1/s]; 0: the points' smallest
  double shear_rate_max = 0.0;      // 0: the points' largest
  int max_draws = 1000;             // evenly thinned posterior draws
  bool include_model_error = true;  // add N(0, sd_model^2 + (sigma_d eta_re)^2) to each draw's eta_re
  double level = 0.95;
  std::uint64_t seed = 7;
};

struct PredictiveBand {
  double phi = 0.0;
  std::vector<double> shear_rate;  // [1/s]
  std::vector<double> median;      // eta [Pa s]
  std::vector<double> lower;       // eta [Pa s], quantile (1 - level) / 2
  std::vector<double> upper;       // eta [Pa s], quantile (1 + level) / 2
};

std::vector<PredictiveBand> predictive_bands(const surrogate::ViscosityModel& model,
                                             const McmcCalibration& calibration,
                                             const PredictiveBandOptions& options = {});

}  // namespace rbcal::calibration
