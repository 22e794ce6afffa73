// Timings of the calibration on the real Gaussian-process surrogate (not a test):
//   build-calibration/bin/calibration_timing_surrogate
// The library is a 8 phi x 5 Ca x 3 lambda grid drawn from the analytic test model with 1 %
// noise; the data are 32 points (4 phi x 8 shear rates) with eta0 measured to 2.1 %.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "analytic_viscosity_model.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "surrogate/viscosity_surrogate.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;
using clock_type = std::chrono::steady_clock;

static double seconds_since(clock_type::time_point t) {
  return std::chrono::duration<double>(clock_type::now() - t).count();
}

int main() {
  test_models::AnalyticViscosityModel truth;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  std::vector<rbcal::surrogate::TrainingCase> cases;
  for (double phi : {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.41})
    for (double ca : {0.01, 0.03, 0.1, 0.3, 0.8})
      for (double lambda : {1.0, 5.0, 10.0}) {
        const double ln_eta = std::log(truth.predict(phi, ca, lambda).eta_re) + 0.01 * normal(rng);
        cases.push_back({"c" + std::to_string(cases.size()), phi, std::log(ca), std::log(lambda), ln_eta, 1e-4});
      }
  auto t = clock_type::now();
  const auto surrogate = rbcal::surrogate::ViscositySurrogate::fit(cases, "synthetic");
  std::printf("surrogate fit (%zu cases): %.2f s\n", cases.size(), seconds_since(t));
  t = clock_type::now();
  double sink = 0.0;
  for (int i = 0; i < 10000; ++i) sink += surrogate.predict(0.3, 0.02 + 0.7 * i / 10000.0, 5.0).sd;
  std::printf("one prediction: %.2f us (%g)\n", seconds_since(t) / 10000 * 1e6, sink > 0 ? 1.0 : 0.0);

  test_models::SyntheticDesign design;
  design.shear_modulus = 2.0e-6;  // Ca 0.003 - 0.7 over 1 - 220 1/s: mostly inside the library's 0.01 - 0.8
  design.plasma_relative_standard_error = 0.021;
  const SampleData sample = test_models::synthetic_sample(truth, design, rng);
  t = clock_type::now();
  const DirectFitResult fit = fit_direct(sample, surrogate);
  std::printf("MAP: %.4f s, G_s = %.3g N/m [%.3g, %.3g], %d of %zu points used\n", seconds_since(t),
              fit.shear_modulus, fit.shear_modulus_interval.lower, fit.shear_modulus_interval.upper,
              fit.degrees_of_freedom + 1, sample.points.size());
  for (auto [threads, burn_in] : {std::pair{1, 0.5}, std::pair{2, 0.5}, std::pair{2, 0.25}}) {
    McmcCalibrationOptions options;
    options.sampler.threads = threads;
    options.sampler.burn_in_fraction = burn_in;
    t = clock_type::now();
    const McmcCalibration mcmc = calibrate_mcmc(sample, surrogate, options);
    std::printf("MCMC (%zu parameters, %d thread(s), burn-in %.2f): %.2f s, %d steps, %s; G_s median %.3g [%.3g, %.3g]\n",
                mcmc.mcmc.parameter_names.size(), threads, burn_in, seconds_since(t), mcmc.mcmc.steps,
                mcmc.mcmc.stop_reason.c_str(), mcmc.shear_modulus_median, mcmc.shear_modulus_interval.lower,
                mcmc.shear_modulus_interval.upper);
  }
  return 0;
}
