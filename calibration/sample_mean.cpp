#include "calibration/sample_mean.hpp"

#include <cmath>

namespace rbcal::calibration {

SampleMean sample_mean(const std::vector<double>& values) {
  SampleMean s;
  s.count = static_cast<int>(values.size());
  if (s.count == 0) return s;
  double sum = 0.0;
  for (const double v : values) sum += v;
  s.mean = sum / s.count;
  if (s.count > 1) {
    double squares = 0.0;
    for (const double v : values) squares += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(squares / (s.count - 1));
    s.standard_error = s.sd / std::sqrt(static_cast<double>(s.count));
  }
  return s;
}

}  // namespace rbcal::calibration
