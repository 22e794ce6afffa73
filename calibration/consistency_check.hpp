#pragma once
// Does one sample's calibration hang together? Two signs that it does not, each given with
// its numbers:
//  - a parameter whose prior has a bounded range (the model's nuisances, such as the immersed
//    boundary's offset c, and a fitted lambda) estimated in the outer tenth of that range:
//    the data push it against the model's assumptions instead of informing it, and whatever
//    the bound cuts off is missing from G_s's interval;
//  - two methods whose 95 % intervals of G_s do not overlap.
// rbcal calibrate prints the findings, and summary.json keeps every comparison.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibration/quantiles.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct SampleReport;

// A parameter estimated near a bound of its range.
struct ParameterAtBound {
  std::string parameter;  // "offset_c", "lambda"
  std::string method;     // "direct" or "mcmc"
  double value = 0.0;     // the estimate (direct) or median (mcmc)
  Interval interval;
  double range_min = 0.0, range_max = 0.0;
  bool upper = false;     // the bound it sits near
  bool log_scale = false; // the range is read in ln (lambda)
  // The share of the range between the estimate and the bound (0: on it).
  double distance_share() const;
  std::string line() const;
};

// Two methods' G_s side by side.
struct MethodComparison {
  std::string first, second;
  double first_value = 0.0, second_value = 0.0;  // [N/m]
  Interval first_interval, second_interval;      // 95 % [N/m]
  // |ln G_1 - ln G_2| over the combined sd of ln G_s read off the two intervals.
  double z = 0.0;
  bool overlap = true;  // false: the methods disagree beyond their intervals
  std::string line() const;
};

struct ConsistencyCheck {
  std::vector<ParameterAtBound> at_bounds;
  std::vector<MethodComparison> comparisons;  // every pair of methods with an interval
  bool consistent() const;
  std::vector<std::string> lines() const;  // one per finding; none when consistent
  nlohmann::json to_json() const;
};

// The outer share of a range that counts as "at the bound".
inline constexpr double kBoundShare = 0.1;

// model_range: the model's box, which bounds a fitted lambda (read in ln lambda).
ConsistencyCheck check_consistency(const SampleReport& report, const surrogate::ParameterRange& model_range);

}  // namespace rbcal::calibration
