#pragma once
// Empirical quantiles of a set of draws and the central interval built from them.
#include <vector>

namespace rbcal::calibration {

// Linear interpolation between order statistics (Hyndman & Fan 1996, type 7, as R's default).
// p in [0, 1]; values need not be sorted. Throws std::invalid_argument on an empty set.
double quantile(std::vector<double> values, double p);

struct Interval {
  double lower = 0.0;
  double upper = 0.0;
  double level = 0.95;  // probability content

  bool contains(double x) const { return lower <= x && x <= upper; }  // bounds included
  bool overlaps(const Interval& other) const { return lower <= other.upper && other.lower <= upper; }
};

// The central interval [q((1-level)/2), q((1+level)/2)].
Interval central_interval(const std::vector<double>& values, double level);

}  // namespace rbcal::calibration
