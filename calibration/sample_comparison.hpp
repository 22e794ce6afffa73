#pragma once
// Comparison of two samples' G_s (e.g. hardened / intact): the posterior of the ratio from
// independent posteriors, as the ratio of randomly paired draws. `rbcal calibrate --compare`
// takes it from a joint posterior instead (joint_posterior.hpp), where the model's shared
// nuisances cancel; this one-at-a-time ratio is what that is measured against.
#include <cstdint>
#include <vector>

#include "calibration/quantiles.hpp"

namespace rbcal::calibration {

struct ShearModulusRatio {
  double median = 0.0;
  double mean = 0.0;
  Interval interval;                       // central credible interval of the ratio
  double probability_greater_than_one = 0.0;  // P(G_s numerator > G_s denominator | data)
  std::vector<double> draws;               // ratio draws
};

// Draws of G_s (any common unit). The shorter set fixes the number of pairs; both are shuffled
// with the seed so that the pairing is random, not aligned by chain position.
// The ratio of draws already paired (the i-th of each, as far as the shorter reaches): its
// median, mean, central interval and P(ratio > 1).
ShearModulusRatio ratio_of_paired_draws(const std::vector<double>& numerator_draws,
                                        const std::vector<double>& denominator_draws, double level = 0.95);

ShearModulusRatio compare_shear_moduli(std::vector<double> numerator_draws, std::vector<double> denominator_draws,
                                       double level = 0.95, std::uint64_t seed = 11);

}  // namespace rbcal::calibration
