// Timings of one MAP fit and one MCMC run on a realistic problem (32 points, analytic model):
//   build-calibration/bin/calibration_timing
// Not a test: prints wall times. The analytic model costs far less than a surrogate does, so
// these figures are the calibration's own overhead.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "analytic_viscosity_model.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;

int main() {
  test_models::AnalyticViscosityModel model;
  model.c3 = 1.0;
  test_models::SyntheticDesign design;
  design.plasma_relative_standard_error = 0.021;  // eta0 = 1.569 +- 0.033 mPa s: ln eta0 is a parameter too
  std::mt19937_64 rng(1);
  const SampleData sample = test_models::synthetic_sample(model, design, rng);
  using clock = std::chrono::steady_clock;
  for (bool fit_lambda : {false, true}) {
    DirectFitOptions fit_options;
    fit_options.setup.fit_lambda = fit_lambda;
    // Median of 21 repeats (the first call also pays for warm-up).
    std::vector<double> map_times;
    DirectFitResult fit;
    for (int repeat = 0; repeat < 21; ++repeat) {
      const auto t0 = clock::now();
      fit = fit_direct(sample, model, fit_options);
      map_times.push_back(std::chrono::duration<double>(clock::now() - t0).count());
    }
    std::nth_element(map_times.begin(), map_times.begin() + 10, map_times.end());
    const double map_seconds = map_times[10];
    std::printf("MAP  (%zu points, %zu parameters): %.4f s, G_s = %.4g N/m [%.4g, %.4g]\n", sample.points.size(),
                fit.parameter_names.size(), map_seconds, fit.shear_modulus, fit.shear_modulus_interval.lower,
                fit.shear_modulus_interval.upper);
    McmcCalibrationOptions options;
    options.posterior.setup.fit_lambda = fit_lambda;
    options.posterior.fit_discrepancy = true;
    const auto t1 = clock::now();
    const McmcCalibration mcmc = calibrate_mcmc(sample, model, options);
    const double mcmc_seconds = std::chrono::duration<double>(clock::now() - t1).count();
    std::printf("MCMC (%zu parameters, %d chains x %d walkers): %.3f s, %d steps, %s\n",
                mcmc.mcmc.parameter_names.size(), options.sampler.chains, options.sampler.walkers, mcmc_seconds,
                mcmc.mcmc.steps, mcmc.mcmc.stop_reason.c_str());
    for (const auto& p : mcmc.mcmc.parameters)
      std::printf("  %-10s median %.4f  [%.4f, %.4f]  R-hat %.4f  bulk ESS %.0f  tail ESS %.0f  tau %.1f\n",
                  p.name.c_str(), p.median, p.interval.lower, p.interval.upper, p.rhat, p.bulk_ess, p.tail_ess,
                  p.autocorrelation_time);
  }
  return 0;
}
