#include "bench/calibration_scaling.hpp"

#include <chrono>
#include <cmath>
#include <random>

#include "calibration/capillary_number.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/model_setup.hpp"

namespace rbcal::bench {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// n points over five hematocrits, each a log-spaced sweep of 40-1000 1/s, drawn from the model
// at its nuisances' means with 3 % measurement error; eta0 known (1.2 mPa s).
calibration::SampleData sample_of(const surrogate::ViscosityModel& model, int n, double shear_modulus,
                                  std::mt19937_64& rng) {
  const double hematocrits[] = {0.25, 0.325, 0.40, 0.475, 0.55};
  const double plasma_viscosity = 1.2e-3, relative_sd = 0.03;
  std::normal_distribution<double> normal;
  calibration::SampleData sample;
  sample.name = "scaling_" + std::to_string(n);
  sample.plasma.eta0 = plasma_viscosity;
  for (int line = 0; line < 5; ++line) {
    const int count = n / 5 + (line < n % 5 ? 1 : 0);
    for (int i = 0; i < count; ++i) {
      calibration::RelativeViscosityPoint p;
      p.phi = hematocrits[line];
      p.shear_rate = 40.0 * std::pow(25.0, count > 1 ? i / (count - 1.0) : 0.5);
      const double ca = calibration::capillary_number(plasma_viscosity, p.shear_rate, calibration::kDefaultCellRadius,
                                                      shear_modulus);
      const double eta_re = model.predict(p.phi, ca, calibration::kDefaultViscosityRatio).eta_re;
      p.eta_re_sd = relative_sd * eta_re;
      p.eta_re = eta_re + p.eta_re_sd * normal(rng);
      sample.points.push_back(p);
    }
  }
  return sample;
}

}  // namespace

std::vector<CalibrationScalingRow> time_calibration_scaling(const surrogate::ViscosityModel& model,
                                                            const CalibrationScalingOptions& options,
                                                            void (*progress)(const CalibrationScalingRow&)) {
  std::vector<CalibrationScalingRow> rows;
  for (const int n : options.points) {
    std::mt19937_64 rng(options.seed + static_cast<std::uint64_t>(n));
    const calibration::SampleData sample = sample_of(model, n, options.shear_modulus, rng);
    CalibrationScalingRow row;
    row.points = n;
    calibration::DirectFitOptions direct;
    direct.setup = calibration::product_model_setup();  // as rbcal calibrate
    auto t = std::chrono::steady_clock::now();
    row.direct_shear_modulus = calibration::fit_direct(sample, model, direct).shear_modulus;
    row.direct_seconds = seconds_since(t);
    if (options.mcmc) {
      calibration::McmcCalibrationOptions mcmc;
      mcmc.posterior.setup = direct.setup;
      mcmc.start_fit = direct;
      t = std::chrono::steady_clock::now();
      const calibration::McmcCalibration m = calibration::calibrate_mcmc(sample, model, mcmc);
      row.mcmc_seconds = seconds_since(t);
      row.mcmc_shear_modulus = m.shear_modulus_median;
      long walkers = 0;
      for (const auto& chain : m.mcmc.chains) walkers += static_cast<long>(chain.walkers());
      row.mcmc_evaluations = walkers * (m.mcmc.steps + m.mcmc.pilot_steps);
    }
    rows.push_back(row);
    if (progress) progress(row);
  }
  return rows;
}

}  // namespace rbcal::bench
