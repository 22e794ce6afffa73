// From a rheometer CSV file to G_s by all three methods, as `rbcal calibrate` will run them:
// two samples (intact and hardened, the seed study's G_s values) written from a known model
// with noise, read back, calibrated, and compared.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "analytic_viscosity_model.hpp"
#include "calibration/alpha_method.hpp"
#include "calibration/calibration_input.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/sample_comparison.hpp"
#include "../scratch_path.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;
namespace fs = std::filesystem;

namespace {

constexpr double kEta0 = 1.569e-3;  // [Pa s], the seed study's plasma

// Rows of one sample: plasma at five shear rates, suspensions at four phi x eight shear rates,
// each a mean of n = 3 repeats with a 2 % sd.
void write_sample(std::ostream& out, const std::string& name, double shear_modulus,
                  const AnalyticViscosityModel& model, std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  for (double rate : {1.0, 10.0, 31.6, 100.0, 316.0})
    out << name << ",plasma,0," << rate << "," << kEta0 * 1e3 * (1.0 + 0.01 * normal(rng)) << ","
        << kEta0 * 1e3 * 0.02 << ",3\n";
  for (double phi : {0.1, 0.2, 0.3, 0.4})
    for (double rate : {1.0, 2.2, 4.6, 10.0, 22.0, 46.0, 100.0, 220.0}) {
      const auto p = model.predict(phi, capillary_number(kEta0, rate, kDefaultCellRadius, shear_modulus), 5.0);
      const double eta_mpa_s = kEta0 * 1e3 * p.eta_re * (1.0 + 0.02 / std::sqrt(3.0) * normal(rng));
      out << name << ",suspension," << phi << "," << rate << "," << eta_mpa_s << "," << 0.02 * eta_mpa_s << ",3\n";
    }
}

}  // namespace

TEST(EndToEnd, CsvToShearModulusByEveryMethodAndTheirRatio) {
  AnalyticViscosityModel model;
  model.relative_sd = 0.005;
  const double intact_gs = 0.553e-6, hardened_gs = 2.43e-6;
  const fs::path path = rbcal::testing_support::scratch_path("sample.csv");
  {
    std::ofstream out(path);
    out << "# synthetic: analytic model, lambda = 5\nsample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n\n";
    std::mt19937_64 rng(2024);
    write_sample(out, "intact", intact_gs, model, rng);
    write_sample(out, "hardened", hardened_gs, model, rng);
  }
  const CalibrationInput input = read_calibration_input(path);
  ASSERT_EQ(input.samples.size(), 2u);

  McmcCalibrationOptions mcmc_options;
  mcmc_options.sampler.threads = 1;
  std::vector<McmcCalibration> posteriors;
  for (const auto& [name, truth] : {std::pair{"intact", intact_gs}, std::pair{"hardened", hardened_gs}}) {
    SCOPED_TRACE(name);
    const SampleData& sample = input.sample(name);
    EXPECT_NEAR(sample.plasma.eta0 / kEta0, 1.0, 0.03);
    EXPECT_EQ(sample.plasma.plateau_rows, 3);

    const AlphaMethodResult alpha = estimate_by_alpha_matching(sample, model);
    EXPECT_GT(alpha.shear_modulus.count, 4);
    EXPECT_NEAR(alpha.shear_modulus.mean / truth, 1.0, 0.15);

    const DirectFitResult fit = fit_direct(sample, model);
    ASSERT_TRUE(fit.covariance_ok);
    EXPECT_NEAR(std::log(fit.shear_modulus / truth), 0.0, 4.0 * fit.ln_shear_modulus_sd);

    posteriors.push_back(calibrate_mcmc(sample, model, mcmc_options));
    const McmcCalibration& post = posteriors.back();
    EXPECT_TRUE(post.mcmc.converged) << post.mcmc.stop_reason;
    EXPECT_LT(post.shear_modulus_interval.lower, truth);
    EXPECT_GT(post.shear_modulus_interval.upper, truth);
    // Flat prior in ln G_s and a near-Gaussian likelihood: posterior median close to the MAP.
    EXPECT_NEAR(std::log(post.shear_modulus_median / fit.shear_modulus), 0.0, 0.2 * fit.ln_shear_modulus_sd);
  }
  const ShearModulusRatio ratio =
      compare_shear_moduli(posteriors[1].shear_modulus_draws(), posteriors[0].shear_modulus_draws());
  EXPECT_LT(ratio.interval.lower, hardened_gs / intact_gs);
  EXPECT_GT(ratio.interval.upper, hardened_gs / intact_gs);
}
