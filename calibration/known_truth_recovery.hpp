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
  CalibrationJobOptions job = [] {  // the methods and their options (every method, every point)
    CalibrationJobOptions o;
    o.min_shear_rate = 0.0;         // simulated suspensions do not aggregate
    o.report.plots = false;
    o.saved_draws = 1;              // no posterior file is written
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
  // alpha matching's mean over its matches [N/m] (a point estimate: the seed study's method
  // gives no interval); empty when it did not run or matched nothing.
  std::optional<double> alpha;
  std::optional<RecoveredValue> direct, mcmc;  // empty: the method did not run or failed
  // The model's nuisances (the immersed boundary's offset, ...) as the MCMC (else the direct
  // fit) put them: what the model had to assume to meet the sample.
  std::vector<NuisanceEstimate> nuisances;
  // The direct fit's and the MCMC's intervals overlap, and alpha's estimate lies in both.
  bool methods_agree = true;
  std::vector<std::string> warnings;
};

// Per method over the cases it answered.
struct MethodCoverage {
  std::string method;
  int answered = 0;
  int covered = 0;
  double median_width_factor = 0.0;  // median of upper / lower
  double bias_factor = 1.0;          // geometric mean of estimate / truth
  double fraction() const { return answered > 0 ? static_cast<double>(covered) / answered : 0.0; }
};

struct RecoveryReport {
  std::vector<SimulatedViscosity> points;
  std::vector<RecoveryCase> cases;
  std::vector<MethodCoverage> coverage;  // direct, mcmc (those that ran)
  int methods_agree = 0;                 // cases in which the methods agree
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
