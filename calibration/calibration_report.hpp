#pragma once
// A calibration report (docs/reference.md, "Calibration report"): the results of the three methods for
// each sample, bundled with what produced them, and written into one folder as summary.json,
// CSV tables (report_tables.hpp) and gnuplot plots (report_plots.hpp).
// The structs hold SI values (as the methods return them); the files use the units a
// rheologist reads: G_s in uN/m, viscosity in mPa s, shear rate in 1/s.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/alpha_method.hpp"
#include "calibration/consistency_check.hpp"
#include "calibration/calibration_input.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/model_evidence.hpp"
#include "calibration/model_reach.hpp"
#include "calibration/posterior_predictive_check.hpp"
#include "calibration/predictive_bands.hpp"
#include "calibration/saved_draws.hpp"
#include "calibration/joint_posterior.hpp"
#include "calibration/sample_comparison.hpp"

namespace rbcal::calibration {

// What one sample's calibration produced; a method that was not run (or failed) is empty and
// its failure is one of the warnings.
// A measured point that no method used, and why (--phi-max, hematocrit order,
// --min-shear-rate, or out of the model's reach).
struct LeftOutPoint {
  RelativeViscosityPoint point;
  std::string reason;
};

// One model variant of a sample's calibration (rbcal calibrate --compare-models): its ln Z and
// its G_s, so that variants rank by how well each explains the same data.
struct ModelVariantResult {
  std::string label;  // "lambda fitted under its prior", "lambda fixed at 5"
  ModelEvidence evidence;
  double shear_modulus_median = 0.0;  // [N/m]
  Interval shear_modulus_interval;
};

struct SampleReport {
  SampleData sample;                  // the points the methods used
  std::vector<LeftOutPoint> left_out;  // the sample's other points
  // Points the model cannot reach at any G_s, grouped by phi (calibration/model_reach.hpp).
  std::vector<ReachGroup> unreachable;
  std::optional<AlphaMethodResult> alpha;
  std::optional<DirectFitResult> direct;
  std::optional<McmcCalibration> mcmc;
  std::vector<PredictiveBand> bands;  // posterior-predictive eta(gamma_dot) per phi (with mcmc)
  double band_level = 0.95;           // the bands' probability content (PredictiveBandOptions::level)
  std::optional<PredictiveCheck> predictive_check;  // each used point in its predictive distribution (with mcmc)
  std::optional<ModelEvidence> evidence;            // ln Z of the MCMC's posterior (model_evidence.hpp)
  std::optional<SavedDraws> saved_draws;  // thinned draws with point-wise log-likelihoods (the posterior file)
  std::vector<ModelVariantResult> model_variants;   // --compare-models, best ln Z first
  std::vector<std::string> warnings;  // method failures, points outside the model, chains not converged
  // Parameters pushed to a bound of their range, methods that disagree (consistency_check.hpp).
  ConsistencyCheck consistency;

  // Whether any method gave G_s (alpha matched a shear rate, the direct fit or the MCMC ran).
  bool has_estimate() const;
  // The point-wise fit used for fits.csv: the direct fit, else the MCMC's start fit, else none.
  const DirectFitResult* point_fit() const;
  // A few lines per method: G_s with its interval, MCMC diagnostics, warnings
  // (calibration/brief_reports.cpp).
  std::string brief_report() const;
};

// G_s ratio of two samples (numerator / denominator) from their posterior draws.
struct SampleComparisonReport {
  std::string numerator;
  std::string denominator;
  ShearModulusRatio ratio;
  std::string source;  // which posterior the ratio's draws came from, in words
  std::string brief_report() const;  // the ratio, its interval and P(numerator > denominator)
};

// Where the numbers came from, recorded in summary.json with rbcal's version and git revision.
struct ReportProvenance {
  std::string data_file;
  std::string surrogate_file;
  std::string command_line;
  nlohmann::json options = nlohmann::json::object();  // the options as used
  std::uint64_t seed = 0;
};

// The joint posterior over several samples (--joint, or the two of --compare).
struct JointReport {
  JointCalibration calibration;
  bool shared_lambda = false;
  std::string brief_report() const;  // per sample G_s, the shared nuisances, mu and tau, diagnostics
};

struct CalibrationReport {
  std::vector<SampleReport> samples;
  std::optional<JointReport> joint;
  std::optional<SampleComparisonReport> comparison;
  ReportProvenance provenance;
  double cell_radius = kDefaultCellRadius;  // a [m], maps the model's alpha(Ca) to shear rates
};

struct ReportOptions {
  bool plots = true;            // false: tables and summary only
  int max_chain_draws = 4000;   // per sample in chains.csv (thinned by step)
  int histogram_bins = 40;      // posterior histogram of G_s
  std::string gnuplot = "gnuplot";  // program name (searched on PATH) or path
};

struct ReportFiles {
  std::filesystem::path folder;
  std::vector<std::filesystem::path> files;  // everything written, summary.json last
  bool plots_written = false;
  std::string plots_message;  // why plots were skipped or failed; empty when written
  std::string brief_report(bool plots_requested) const;  // where the report went
};

// Creates the folder (and parents) if needed, writes tables, plots, then summary.json (which
// lists the other files). Throws std::runtime_error naming a file it cannot write; a missing
// or failing gnuplot is not an error (see ReportFiles::plots_message).
ReportFiles write_calibration_report(const CalibrationReport& report, const std::filesystem::path& folder,
                                     const ReportOptions& options = {});

// A sample name made safe as a file-name stem (letters, digits, '-', '_', '.'; others -> '_').
std::string sample_file_stem(const std::string& sample_name);

}  // namespace rbcal::calibration
