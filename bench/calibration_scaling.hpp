#pragma once
// The calibration's cost against the number of points of a sample: samples of n points drawn
// from a model at a known G_s (five hematocrits 0.25-0.55, shear rates 40-1000 1/s log-spaced,
// 3 % measurement error, eta0 from three plasma rows), each written as a rheometer CSV and
// calibrated from it as `rbcal calibrate` does (its defaults, no report written): the direct
// method alone, then all methods. Wall times of one run each (a run is seconds to minutes).
#include <cstdint>
#include <string>
#include <vector>

#include "calibration/calibration_input.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::bench {

struct CalibrationScalingRow {
  int points = 0;
  double direct_seconds = 0.0;  // --method direct
  double all_seconds = -1.0;    // --method all (alpha, direct, MCMC, bands, check, evidence); -1: not run
  double mcmc_seconds = -1.0;   // of which the MCMC's sampling
  double direct_shear_modulus = 0.0, mcmc_shear_modulus = 0.0;  // [N/m]
  long long mcmc_evaluations = 0;  // of the posterior by the MCMC
};

struct CalibrationScalingOptions {
  std::vector<int> points = {28, 100, 500, 2000, 10000};
  bool mcmc = true;
  double shear_modulus = 2e-6;  // the truth [N/m]
  std::uint64_t seed = 20240601;
  std::string save_folder;  // when set, each sample is also written there as scaling_N.csv
};

// The sample as a rheometer CSV (docs/reference.md): its plasma as three measured rows at the
// known eta0, 1 % sd, n = 10.
std::string scaling_sample_csv(const calibration::SampleData& sample);

std::vector<CalibrationScalingRow> time_calibration_scaling(const surrogate::ViscosityModel& model,
                                                            const CalibrationScalingOptions& options,
                                                            void (*progress)(const CalibrationScalingRow&) = nullptr);

}  // namespace rbcal::bench
