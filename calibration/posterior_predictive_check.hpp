#pragma once
// Where each measured point falls in its posterior predictive distribution: over posterior
// draws of the MCMC, the model's eta_re at the point plus the model's error, the discrepancy
// term and the point's own measurement error; the point's rank among them (its PIT value,
// uniform on [0, 1] when model and data agree). A point with PIT outside [0.025, 0.975] lies
// outside its 95 % predictive interval; about 5 % of the points should. Far more means the
// model cannot follow these data, whatever the fit's interval says.
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/mcmc_calibration.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct PredictiveCheckPoint {
  RelativeViscosityPoint point;
  double pit = 0.5;            // share of predictive draws below the measured value
  double predicted_median = 0.0;  // median predicted eta_re
  bool outside = false;        // outside the central predictive interval
};

struct PredictiveCheck {
  double level = 0.95;
  std::vector<PredictiveCheckPoint> points;
  int outside() const;
  double expected_outside() const { return (1.0 - level) * static_cast<double>(points.size()); }
  // P(at least outside() of n points outside) if each were outside with probability 1 - level
  // independently (the model's errors are correlated, so read it as a guide).
  double tail_probability() const;
  // A line for the printed summary, and a warning when the tail probability is below 0.01.
  std::string line() const;
  bool disagrees() const { return !points.empty() && tail_probability() < 0.01; }
  nlohmann::json to_json() const;
};

struct PredictiveCheckOptions {
  int max_draws = 400;  // evenly thinned posterior draws (a PIT resolution of 1 / 400)
  double level = 0.95;
  std::uint64_t seed = 11;
};

PredictiveCheck posterior_predictive_check(const surrogate::ViscosityModel& model, const McmcCalibration& calibration,
                                           const PredictiveCheckOptions& options = {});

}  // namespace rbcal::calibration
