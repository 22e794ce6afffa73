#include "calibration/sample_comparison.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>

namespace rbcal::calibration {

ShearModulusRatio compare_shear_moduli(std::vector<double> numerator_draws, std::vector<double> denominator_draws,
                                       double level, std::uint64_t seed) {
  if (numerator_draws.empty() || denominator_draws.empty())
    throw std::invalid_argument("comparison of G_s needs draws of both samples");
  std::mt19937_64 rng(seed);
  std::shuffle(numerator_draws.begin(), numerator_draws.end(), rng);
  std::shuffle(denominator_draws.begin(), denominator_draws.end(), rng);
  return ratio_of_paired_draws(numerator_draws, denominator_draws, level);
}

ShearModulusRatio ratio_of_paired_draws(const std::vector<double>& numerator_draws,
                                        const std::vector<double>& denominator_draws, double level) {
  const std::size_t n = std::min(numerator_draws.size(), denominator_draws.size());
  if (n == 0) throw std::invalid_argument("comparison of G_s needs draws of both samples");
  ShearModulusRatio r;
  r.draws.resize(n);
  double above = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    r.draws[i] = numerator_draws[i] / denominator_draws[i];
    sum += r.draws[i];
    if (r.draws[i] > 1.0) above += 1.0;
  }
  r.mean = sum / n;
  r.median = quantile(r.draws, 0.5);
  r.interval = central_interval(r.draws, level);
  r.probability_greater_than_one = above / n;
  return r;
}

}  // namespace rbcal::calibration
