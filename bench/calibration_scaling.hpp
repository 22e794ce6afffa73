#pragma once
// The calibration's cost against the number of points of a sample: samples of n points drawn
// from a model at a known G_s (five hematocrits 0.25-0.55, shear rates 40-1000 1/s log-spaced,
// 3 % measurement error), each fitted directly and sampled by MCMC with the settings of
// `rbcal calibrate`. Wall times of one run each (a run is seconds to minutes: its own median).
#include <cstdint>
#include <string>
#include <vector>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::bench {

struct CalibrationScalingRow {
  int points = 0;
  double direct_seconds = 0.0, mcmc_seconds = -1.0;  // -1: not run
  double direct_shear_modulus = 0.0, mcmc_shear_modulus = 0.0;  // [N/m]
  long mcmc_evaluations = 0;  // walkers x steps of the run (posterior evaluations)
};

struct CalibrationScalingOptions {
  std::vector<int> points = {28, 100, 500, 2000, 10000};
  bool mcmc = true;
  double shear_modulus = 2e-6;  // the truth [N/m]
  std::uint64_t seed = 20240601;
};

std::vector<CalibrationScalingRow> time_calibration_scaling(const surrogate::ViscosityModel& model,
                                                            const CalibrationScalingOptions& options,
                                                            void (*progress)(const CalibrationScalingRow&) = nullptr);

}  // namespace rbcal::bench
