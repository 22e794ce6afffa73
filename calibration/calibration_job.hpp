#pragma once
// One calibration from files to report: read a rheometer CSV, load a surrogate, run the
// chosen methods (alpha matching, direct fit, MCMC) on each selected sample with one
// shared ModelSetup, optionally compare two samples' G_s, and write the report folder.
// This is the policy behind `rbcal calibrate`: which methods run, which points enter
// (phi_max), how a failing method becomes a warning instead of an error, and how the
// options reach each method. Progress and brief reports go to a stream as they come.
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "calibration/calibration_input.hpp"
#include "calibration/calibration_report.hpp"
#include "calibration/mcmc_sampling.hpp"
#include "calibration/model_setup.hpp"
#include "calibration/plasma_viscosity.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

// The most points of one sample that are fitted, and the count above which a warning says the
// MCMC will take minutes. The likelihood's memory grows linearly with the points
// (kLikelihoodBytesPerPoint: the low-rank factor of the model's covariance, at most 1201
// columns, in up to three copies, and each point's covariances with the runs of four
// members); a sample that would need more than the host has available is refused too.
inline constexpr std::size_t kMaxFittedPoints = 100000;
inline constexpr std::size_t kSlowFittedPoints = 1000;
inline constexpr double kLikelihoodBytesPerPoint = 8.0 * (3.0 * 1201.0 + 4.0 * 2.0 * 256.0);

struct CalibrationJobOptions {
  std::filesystem::path data_file;       // rheometer CSV
  std::filesystem::path surrogate_file;  // rbcal.surrogate/1 or rbcal.surrogate_family/1
  std::filesystem::path report_folder = "calibration_report";
  std::string method = "all";            // alpha, direct, mcmc or all
  std::vector<std::string> samples;      // empty: every sample of the file
  ModelSetup setup = product_model_setup();  // a, lambda and its prior: shared by the methods
  PlasmaViscosityOptions plasma;         // which plasma rows give eta0
  double phi_max = 1.0;                  // points above are left out
  // Points below this shear rate [1/s] are left out: the simulations have no aggregation,
  // and whole blood aggregates at low shear. Complete disaggregation needs 13-120 1/s,
  // 38 1/s at 45 % hematocrit (Snabre et al. 1987, as cited by the seed study), hence 40;
  // 0 keeps every point (non-aggregating suspensions: washed cells in buffer, hardened cells).
  double min_shear_rate = 40.0;
  // Points whose eta_re is not above the next lower hematocrit's curve are left out and
  // named (calibration/hematocrit_order.hpp) unless this is set.
  bool keep_out_of_hematocrit_order = false;
  // The direct fit (and the MCMC's start, whose points the MCMC keeps inside the range) hold the
  // largest set of points one G_s keeps inside the model's Ca range
  // (DirectFitOptions::hold_coverable_points; --hold-points). Without it, a direct fit that
  // leaves out points one G_s could keep is refitted so, and a warning gives both.
  bool hold_coverable_points = false;
  // seed, threads, steps, chains, walkers (0: automatic_walkers, 8 per parameter, at least 16)
  McmcOptions sampler = [] {
    McmcOptions o;
    o.walkers = 0;
    return o;
  }();
  // MCMC draws per sample kept for the report's posterior file and chains.csv (thinned by step).
  int saved_draws = 4000;
  // The MCMC's by-products: predictive bands, the posterior predictive check, the saved draws
  // and the evidence, four fifths of a small sample's MCMC time. Off where only the
  // posterior's summary is read (a recovery of a known G_s reads the intervals).
  bool mcmc_byproducts = true;
  std::string compare;                   // "NUMERATOR/DENOMINATOR" sample names, or empty
  // Model nuisances held at a value instead of fitted (name, value): a sensitivity study,
  // e.g. G_s with the immersed boundary's offset held at 0.6 (surrogate/fixed_nuisance_model.hpp).
  std::vector<std::pair<std::string, double>> held_nuisances;
  // Also calibrate each sample (MCMC) with lambda fitted under its prior and held at
  // setup.lambda, and rank the two by their evidence ln Z.
  bool compare_models = false;
  // Further models (surrogate or family files) ranked with those variants: each calibrated
  // by MCMC with lambda as in setup (another level mapping, say). Implies compare_models.
  std::vector<std::filesystem::path> alternative_models;
  // One posterior over all selected samples (calibration/joint_posterior.hpp): the model's
  // nuisances shared, G_s and eta0 per sample; lambda shared too with shared_lambda; a
  // population layer ln G_s ~ N(mu, tau^2) with hierarchical. --compare always takes its ratio
  // from a joint posterior (over the two samples compared when joint is off).
  bool joint = false;
  bool shared_lambda = false;
  bool hierarchical = false;
  ReportOptions report;
  std::string command_line;              // the equivalent command, for the provenance

  // Empty when usable, else the first problem, naming the option (checked once at entry).
  std::string invalid_reason() const;
  bool runs(const std::string& m) const { return method == "all" || method == m; }
  // The options as recorded in summary.json's provenance.
  nlohmann::json to_json() const;
};

struct CalibrationJobResult {
  CalibrationReport report;
  ReportFiles files;
};

// Throws std::invalid_argument for invalid options, and the readers' errors (naming file,
// line and field) for bad input files. log: the plan, each sample's brief report as it
// finishes, the comparison, where the report went, and warnings.
CalibrationJobResult run_calibration_job(const CalibrationJobOptions& options, std::ostream& log);

// The calibration itself, on data already read and any model (no files read or written;
// options.data_file and surrogate_file are only recorded): the selected samples, each
// method, the comparison. Samples not in input throw std::invalid_argument.
CalibrationReport calibrate_samples(const CalibrationInput& input, const surrogate::ViscosityModel& model,
                                    const CalibrationJobOptions& options, std::ostream& log);

}  // namespace rbcal::calibration
