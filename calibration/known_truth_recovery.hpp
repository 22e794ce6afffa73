#pragma once
// Calibrating samples of known G_s (simulated truth, calibration/synthetic_sample.hpp) and
// asking whether each method's 95 % interval holds the truth: coverage over several true G_s
// and noise draws, the intervals' widths, and whether the three methods agree within the
// intervals. `rbcal recover` runs it on simulation results; a ctest runs it on committed ones.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/calibration_job.hpp"
#include "calibration/quantiles.hpp"
#include "calibration/synthetic_sample.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct RecoveryOptions {
  std::vector<double> shear_moduli = {1e-6, 2e-6, 4e-6, 8e-6};  // the truths [N/m]
  int replicates = 3;               // noise draws per truth (seeds seed, seed + 1, ...)
  SyntheticSampleOptions sample;    // eta0, a, noise, first seed (its G_s is each truth in turn)
  // When set, each synthetic sample is also written there as a rheometer CSV,
  // gs<truth in uN/m>_seed<seed>.csv, for `rbcal calibrate` to take up one case by hand.
  std::string samples_folder;
  CalibrationJobOptions job = [] {  // the methods and their options (every method, every point)
    CalibrationJobOptions o;
    o.min_shear_rate = 0.0;         // simulated suspensions do not aggregate
    o.report.plots = false;
    o.saved_draws = 1;              // no posterior file is written
    // Every reading of a synthetic sample is kept: its noise, not the blood, would put a point
    // below the next lower hematocrit's curve.
    o.keep_out_of_hematocrit_order = true;
    return o;
  }();
};

// One interval method's answer for one sample.
struct RecoveredValue {
  double estimate = 0.0;   // [N/m]: the direct fit's estimate, the MCMC's median
  Interval interval;       // [N/m]: 95 %
  bool covers = false;     // the truth lies in the interval
};

struct RecoveryCase {
  double truth = 0.0;  // [N/m]
  std::uint64_t seed = 0;
  // alpha matching's mean over its matches [N/m]; empty when it did not run or matched nothing.
  std::optional<double> alpha;
  // Empty: the method did not run, failed, or gave no interval to score (a direct fit held at
  // the model's Ca edge, whose interval is a limit, or without a covariance; an MCMC started
  // from such a fit). Such a case counts as a miss.
  std::optional<RecoveredValue> direct, mcmc;
  // The model's nuisances (the immersed boundary's offset, ...) as the MCMC (else the direct
  // fit) put them: what the model had to assume to meet the sample.
  std::vector<NuisanceEstimate> nuisances;
  // The methods agree as `rbcal calibrate`'s consistency check judges them: every pair of the
  // methods' 95 % G_s intervals overlaps (alpha's: its mean +- 1.96 standard errors over the
  // shear rates it matched; consistency_check.hpp). False when the direct fit's or the MCMC's
  // interval is missing.
  bool methods_agree = false;
  std::vector<std::string> warnings;
};

// Per interval method over every case it was asked to answer: a case without an interval
// counts as a miss.
struct MethodCoverage {
  std::string method;
  int asked = 0;
  int answered = 0;
  int covered = 0;
  double median_width_factor = 0.0;  // median of upper / lower over the answered cases
  double bias_factor = 1.0;          // geometric mean of estimate / truth over the answered cases
  // Its standard error from the cases' scatter (the noise draws' sampling error; 0 below two
  // answered cases): sd of ln(estimate / truth) / sqrt(answered), times bias_factor.
  double bias_factor_se = 0.0;
  double fraction() const { return asked > 0 ? static_cast<double>(covered) / asked : 0.0; }
};

struct RecoveryReport {
  std::vector<SimulatedViscosity> points;
  std::vector<RecoveryCase> cases;
  std::vector<MethodCoverage> coverage;  // direct, mcmc (those the options ask for)
  int methods_agree = 0;                 // cases in which the methods agree (with both asked for)
  const MethodCoverage* method(const std::string& name) const;
  nlohmann::json to_json() const;
  std::string table() const;  // one line per case and the coverage, for the terminal
};

// Throws std::invalid_argument for an empty list of truths, replicates below 1, or what
// synthetic_rheometer_data refuses. log: each case as it finishes.
RecoveryReport recover_known_shear_moduli(const std::vector<SimulatedViscosity>& points,
                                          const surrogate::ViscosityModel& model, const RecoveryOptions& options,
                                          std::ostream& log);

}  // namespace rbcal::calibration
