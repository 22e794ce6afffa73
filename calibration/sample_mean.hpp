#pragma once
// The mean of a set of values with its sample standard deviation and standard error, the one
// rule behind the alpha method's G_s, the plasma plateau's scatter and a recovery's bias.
#include <vector>

namespace rbcal::calibration {

struct SampleMean {
  double mean = 0.0;            // 0 for an empty set
  double sd = 0.0;              // denominator count - 1; 0 below two values
  double standard_error = 0.0;  // sd / sqrt(count)
  int count = 0;
};

SampleMean sample_mean(const std::vector<double>& values);

}  // namespace rbcal::calibration
