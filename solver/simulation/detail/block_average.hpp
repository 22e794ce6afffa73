#pragma once
// Mean of a correlated time series with a standard error that accounts for the
// correlation, by blocking (Flyvbjerg & Petersen, J. Chem. Phys. 91 (1989) 461): the
// series is halved repeatedly by averaging neighbours; the naive standard error grows
// until blocks are longer than the correlation time and then levels off. The estimate
// is the largest value over the levels that keep at least 8 blocks (conservative).
#include <cmath>
#include <vector>

namespace rbcal::solver {

struct MeanWithError {
  double mean = 0.0;
  double sem = 0.0;
  std::size_t samples = 0;
  std::size_t block_length = 1;  // samples per block at the chosen level
};

inline MeanWithError block_average(const std::vector<double>& series) {
  MeanWithError r;
  r.samples = series.size();
  if (series.empty()) return r;
  double sum = 0.0;
  for (double v : series) sum += v;
  r.mean = sum / static_cast<double>(series.size());
  std::vector<double> level = series;
  std::size_t length = 1;
  while (level.size() >= 8) {
    const double n = static_cast<double>(level.size());
    double var = 0.0;
    for (double v : level) var += (v - r.mean) * (v - r.mean);
    const double sem = std::sqrt(var / (n * (n - 1.0)));
    if (sem > r.sem) {
      r.sem = sem;
      r.block_length = length;
    }
    std::vector<double> next(level.size() / 2);
    for (std::size_t i = 0; i < next.size(); ++i) next[i] = 0.5 * (level[2 * i] + level[2 * i + 1]);
    level.swap(next);
    length *= 2;
  }
  return r;
}

}  // namespace rbcal::solver
