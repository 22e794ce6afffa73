// Simulated truth (calibration/known_truth_recovery.hpp): samples made from the model's own
// law at known G_s are recovered inside the direct fit's and the MCMC's 95 % intervals in at
// least 90 % of cases, and a 10 % error in the level of the "runs" is caught as a bias.
#include <gtest/gtest.h>

#include <sstream>

#include "analytic_viscosity_model.hpp"
#include "calibration/known_truth_recovery.hpp"

namespace rbcal::calibration {
namespace {

using test_models::AnalyticViscosityModel;

AnalyticViscosityModel law() { return test_models::synthetic_rheometer_law(); }

// "Runs" at two hematocrits and four Ca (as the dense anchors), eta_re from the law times level.
std::vector<SimulatedViscosity> runs_of(const AnalyticViscosityModel& m, double level) {
  std::vector<SimulatedViscosity> runs;
  for (double phi : {0.3, 0.4})
    for (double ca : {0.1, 0.5, 2.0, 8.0})
      runs.push_back({"phi" + std::to_string(phi) + "_Ca" + std::to_string(ca), phi, ca, 5.0,
                      level * m.predict(phi, ca, 5.0).eta_re, 0.0});
  return runs;
}

RecoveryOptions quick_options() {
  RecoveryOptions o;
  o.shear_moduli = {1e-6, 2e-6, 4e-6, 8e-6};
  o.replicates = 3;
  o.job.method = "all";
  o.job.setup.fit_lambda = false;
  o.job.sampler.threads = 1;
  o.job.sampler.chains = 2;
  o.job.sampler.walkers = 8;
  o.job.sampler.max_steps = 300;
  o.job.saved_draws = 0;
  return o;
}

TEST(KnownTruthRecovery, TheModelsOwnLawIsRecoveredInsideTheIntervals) {
  const AnalyticViscosityModel m = law();
  std::ostringstream log;
  const RecoveryReport r = recover_known_shear_moduli(runs_of(m, 1.0), m, quick_options(), log);
  ASSERT_EQ(r.cases.size(), 12u);
  for (const char* method : {"direct", "mcmc"}) {
    const MethodCoverage* c = r.method(method);
    ASSERT_NE(c, nullptr) << method;
    EXPECT_EQ(c->answered, 12) << method;
    EXPECT_GE(c->fraction(), 0.9) << method << "\n" << r.table() << log.str();
    // 5 % noise on 8 points: no systematic error beyond a few percent in ln G_s.
    EXPECT_NEAR(c->bias_factor, 1.0, 0.15) << method << "\n" << r.table();
    // The estimates scatter with the noise, so the bias carries a sampling error.
    EXPECT_GT(c->bias_factor_se, 0.0) << method;
    EXPECT_GT(c->median_width_factor, 1.0) << method;
  }
  EXPECT_GE(r.methods_agree, 11) << r.table() << log.str();
  const nlohmann::json j = r.to_json();
  EXPECT_EQ(j["schema"], "rbcal.recovery/1");
  EXPECT_EQ(j["cases"].size(), 12u);
}

TEST(KnownTruthRecovery, ALevelTenPercentHighIsCaughtAsABias) {
  // eta_re 10 % above the law: the law reaches it at a lower Ca, so G_s comes out too high by
  // about exp(ln 1.1 / (c1 phi)) = exp(0.095 / 0.14), a factor near 2 at phi 0.35.
  const AnalyticViscosityModel m = law();
  RecoveryOptions o = quick_options();
  o.job.method = "direct";
  std::ostringstream log;
  const RecoveryReport r = recover_known_shear_moduli(runs_of(m, 1.1), m, o, log);
  const MethodCoverage* c = r.method("direct");
  ASSERT_NE(c, nullptr);
  EXPECT_GT(c->bias_factor, 1.5) << r.table();
  EXPECT_LT(c->fraction(), 0.9) << r.table();
  // Caught beyond the noise draws' sampling error, not by chance.
  EXPECT_GT(c->bias_factor - 1.0, 3.0 * c->bias_factor_se) << r.table();
}

TEST(KnownTruthRecovery, RefusesAnEmptyDesign) {
  const AnalyticViscosityModel m = law();
  RecoveryOptions o = quick_options();
  std::ostringstream log;
  o.shear_moduli.clear();
  EXPECT_THROW(recover_known_shear_moduli(runs_of(m, 1.0), m, o, log), std::invalid_argument);
  o = quick_options();
  o.replicates = 0;
  EXPECT_THROW(recover_known_shear_moduli(runs_of(m, 1.0), m, o, log), std::invalid_argument);
}

}  // namespace
}  // namespace rbcal::calibration
