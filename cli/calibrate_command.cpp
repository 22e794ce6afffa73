// `rbcal calibrate [DATA.csv]`: G_s (and optionally lambda) of each sample in a rheometer CSV by
// the seed study's alpha method, the direct fit and the MCMC posterior, on a saved surrogate;
// prints the estimates with their intervals and writes a report folder (summary.json, CSV
// tables, plots). DESIGN.md sections 5-6.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/alpha_method.hpp"
#include "calibration/calibration_input.hpp"
#include "calibration/calibration_report.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/predictive_bands.hpp"
#include "calibration/sample_comparison.hpp"
#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "surrogate/surrogate_file.hpp"

namespace rbcal::cli {

namespace {

namespace cal = rbcal::calibration;
namespace fs = std::filesystem;

constexpr double kMicro = 1e6;  // N/m -> uN/m
constexpr double kMilli = 1e3;  // Pa s -> mPa s

struct CalibrateOptions {
  std::string data = shipped_file("samples/default.csv");
  std::string surrogate = shipped_file("library/default/surrogate.json");
  std::string method = "all";
  std::vector<std::string> samples;  // empty: every sample
  double lambda = 5.0;
  bool fit_lambda = false;
  double cell_radius_um = 4.0;
  double plateau_min_shear_rate = 10.0;
  double phi_max = 1.0;
  std::uint64_t seed = cal::McmcOptions{}.seed;
  int threads = 0;
  std::string compare;  // NUM/DEN
  std::string report = "calibration_report";
  bool no_plots = false;
  int mcmc_max_steps = cal::McmcOptions{}.max_steps;
  int chains = cal::McmcOptions{}.chains;
  int walkers = cal::McmcOptions{}.walkers;
  std::string command_line;
};

bool runs(const CalibrateOptions& o, const std::string& method) { return o.method == "all" || o.method == method; }

std::string fmt(const char* format, double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

std::string interval_text(const cal::Interval& i, double scale) {
  return fmt("%.0f", 100 * i.level) + " % [" + fmt("%.4g", scale * i.lower) + ", " + fmt("%.4g", scale * i.upper) + "]";
}

nlohmann::json options_json(const CalibrateOptions& o) {
  return {{"method", o.method},
          {"samples", o.samples},
          {"lambda", o.lambda},
          {"fit_lambda", o.fit_lambda},
          {"cell_radius_um", o.cell_radius_um},
          {"plateau_min_shear_rate_per_s", o.plateau_min_shear_rate},
          {"phi_max", o.phi_max},
          {"seed", o.seed},
          {"threads", o.threads},
          {"compare", o.compare},
          {"mcmc_max_steps", o.mcmc_max_steps},
          {"chains", o.chains},
          {"walkers", o.walkers},
          {"plots", !o.no_plots}};
}

// Runs the chosen methods on one sample; a method that throws becomes a warning.
cal::SampleReport calibrate_sample(cal::SampleData sample, const surrogate::ViscosityModel& model,
                                   const CalibrateOptions& o) {
  cal::SampleReport r;
  const std::size_t all_points = sample.points.size();
  std::erase_if(sample.points, [&](const cal::RelativeViscosityPoint& p) { return p.phi > o.phi_max; });
  if (sample.points.size() < all_points)
    r.warnings.push_back(std::to_string(all_points - sample.points.size()) + " points with phi > " +
                         fmt("%.4g", o.phi_max) + " left out (--phi-max)");
  r.sample = sample;
  const double a = o.cell_radius_um * 1e-6;

  if (runs(o, "alpha")) {
    cal::AlphaMethodOptions ao;
    ao.cell_radius = a;
    ao.lambda = o.lambda;
    ao.phi_max = o.phi_max;
    try {
      r.alpha = cal::estimate_by_alpha_matching(sample, model, ao);
      int unmatched = 0;
      for (const auto& m : r.alpha->per_shear_rate) unmatched += m.matched ? 0 : 1;
      if (unmatched > 0)
        r.warnings.push_back("alpha: " + std::to_string(unmatched) + " of " + std::to_string(r.alpha->per_shear_rate.size()) +
                             " shear rates not matched to a Ca of the surrogate (see summary.json)");
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("alpha method failed: ") + e.what());
    }
  }
  cal::DirectFitOptions fo;
  fo.cell_radius = a;
  fo.lambda = o.lambda;
  fo.fit_lambda = o.fit_lambda;
  if (runs(o, "direct")) {
    try {
      r.direct = cal::fit_direct(sample, model, fo);
      if (!r.direct->converged) r.warnings.push_back("direct fit: Ceres did not converge");
      if (!r.direct->covariance_ok) r.warnings.push_back("direct fit: covariance rank deficient, no interval");
      if (r.direct->at_bound) r.warnings.push_back("direct fit: an estimate sits on a bound, interval unreliable");
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("direct fit failed: ") + e.what());
    }
  }
  if (runs(o, "mcmc")) {
    cal::McmcCalibrationOptions mo;
    mo.posterior.cell_radius = a;
    mo.posterior.lambda = o.lambda;
    mo.posterior.fit_lambda = o.fit_lambda;
    mo.start_fit = fo;
    mo.sampler.seed = o.seed;
    mo.sampler.threads = o.threads;
    mo.sampler.max_steps = o.mcmc_max_steps;
    mo.sampler.min_steps = std::min(mo.sampler.min_steps, o.mcmc_max_steps);
    mo.sampler.chains = o.chains;
    mo.sampler.walkers = o.walkers;
    try {
      r.mcmc = cal::calibrate_mcmc(sample, model, mo);
      if (!r.mcmc->mcmc.converged) r.warnings.push_back("MCMC not converged: " + r.mcmc->mcmc.stop_reason);
      cal::PredictiveBandOptions bo;
      bo.seed = o.seed + 1;
      r.band_level = bo.level;
      r.bands = cal::predictive_bands(model, *r.mcmc, bo);
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("MCMC failed: ") + e.what());
    }
  }
  // Points the fit left out (mostly outside the surrogate's range), counted once.
  if (const cal::DirectFitResult* fit = r.point_fit()) {
    int skipped = 0;
    std::string first;
    for (const auto& f : fit->points)
      if (!f.used && skipped++ == 0)
        first = "line " + std::to_string(f.point.line) + ": " + f.reason;
    if (skipped > 0) {
      const surrogate::ParameterRange range = model.range();
      std::ostringstream w;
      w << skipped << " of " << fit->points.size() << " points not fitted (surrogate range phi " << range.phi_min
        << " .. " << range.phi_max << ", Ca " << range.ca_min << " .. " << range.ca_max << "); first: " << first;
      r.warnings.push_back(w.str());
    }
  }
  return r;
}

void print_sample(const cal::SampleReport& r) {
  const cal::SampleData& s = r.sample;
  std::printf("sample %s: %zu points, eta0 = %.4g +- %.2g mPa s (%d plateau rows)\n", s.name.c_str(), s.points.size(),
              kMilli * s.plasma.eta0, kMilli * s.plasma.standard_error, s.plasma.plateau_rows);
  if (r.alpha) {
    const auto& g = r.alpha->shear_modulus;
    if (g.count > 0)
      std::printf("  G_s alpha   %.4g uN/m  95 %% [%.4g, %.4g] (mean +- 1.96 se over %d shear rates)\n", kMicro * g.mean,
                  kMicro * (g.mean - 1.96 * g.standard_error), kMicro * (g.mean + 1.96 * g.standard_error), g.count);
    else
      std::printf("  G_s alpha   none: no shear rate matched\n");
  }
  if (r.direct) {
    const auto& d = *r.direct;
    const auto used = std::count_if(d.points.begin(), d.points.end(), [](const auto& f) { return f.used; });
    std::printf("  G_s direct  %.4g uN/m  %s (Laplace, %ld points, chi^2/dof %.3g)\n", kMicro * d.shear_modulus,
                interval_text(d.shear_modulus_interval, kMicro).c_str(), static_cast<long>(used),
                d.degrees_of_freedom > 0 ? d.chi_square / d.degrees_of_freedom : 0.0);
    if (std::find(d.parameter_names.begin(), d.parameter_names.end(), "ln_lambda") != d.parameter_names.end())
      std::printf("  lambda direct %.4g  %s\n", d.lambda, interval_text(d.lambda_interval, 1.0).c_str());
  }
  if (r.mcmc) {
    const auto& m = *r.mcmc;
    std::printf("  G_s mcmc    %.4g uN/m  %s (posterior median)\n", kMicro * m.shear_modulus_median,
                interval_text(m.shear_modulus_interval, kMicro).c_str());
    if (m.posterior.fit_lambda)
      std::printf("  lambda mcmc %.4g  %s\n", m.lambda_median, interval_text(m.lambda_interval, 1.0).c_str());
    const auto& mc = m.mcmc;
    const auto& p = mc.parameters.front();
    std::printf("  MCMC        R-hat %.4f, ESS %.0f, tau %.3g, acceptance %.2f, %d steps x %zu chains x %d walkers, %s\n",
                p.rhat, p.bulk_ess, p.autocorrelation_time, mc.acceptance_fraction, mc.steps, mc.chains.size(),
                mc.chains.empty() ? 0 : mc.chains.front().walkers(), mc.converged ? "converged" : "NOT converged");
  }
  for (const auto& w : r.warnings) std::printf("  warning: %s\n", w.c_str());
}

void run_calibrate(const CalibrateOptions& o) {
  if (!fs::exists(o.data))
    throw std::runtime_error("data file " + o.data +
                             " not found; give a rheometer CSV (sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,"
                             "sd_mPa_s,n) as `rbcal calibrate DATA.csv`");
  if (!fs::exists(o.surrogate))
    throw std::runtime_error("surrogate file " + o.surrogate +
                             " not found; build one with `rbcal surrogate build LIBRARY -o FILE` and pass --surrogate FILE");
  cal::PlasmaViscosityOptions po;
  po.plateau_min_shear_rate = o.plateau_min_shear_rate;
  const cal::CalibrationInput input = cal::read_calibration_input(o.data, po);

  std::vector<std::string> names = o.samples;
  if (names.empty())
    for (const auto& s : input.samples) names.push_back(s.name);
  std::optional<std::pair<std::string, std::string>> compare;
  if (!o.compare.empty()) {
    const auto slash = o.compare.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == o.compare.size())
      throw std::runtime_error("--compare " + o.compare + ": expected NUMERATOR/DENOMINATOR sample names");
    compare = {o.compare.substr(0, slash), o.compare.substr(slash + 1)};
    if (!runs(o, "mcmc")) throw std::runtime_error("--compare needs the mcmc method (--method mcmc or all)");
    for (const std::string& n : {compare->first, compare->second})
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  std::vector<const cal::SampleData*> selected;
  for (const auto& n : names) {
    try {
      selected.push_back(&input.sample(n));
    } catch (const std::out_of_range& e) {
      throw std::runtime_error(e.what());  // names the file and the known samples
    }
  }
  const surrogate::ViscositySurrogate model = surrogate::load_surrogate(o.surrogate);
  std::printf("rbcal calibrate: %s (%zu of %zu samples), surrogate %s, method %s, lambda %s\n", o.data.c_str(),
              selected.size(), input.samples.size(), o.surrogate.c_str(), o.method.c_str(),
              o.fit_lambda ? "fitted" : fmt("%.4g", o.lambda).c_str());

  cal::CalibrationReport report;
  report.cell_radius = o.cell_radius_um * 1e-6;
  report.provenance = {o.data, o.surrogate, o.command_line, options_json(o), o.seed};
  for (const cal::SampleData* s : selected) {
    report.samples.push_back(calibrate_sample(*s, model, o));
    print_sample(report.samples.back());
  }
  if (compare) {
    auto find = [&](const std::string& n) -> const cal::SampleReport& {
      for (const auto& r : report.samples)
        if (r.sample.name == n) return r;
      throw std::logic_error("sample " + n + " not calibrated");
    };
    const auto& num = find(compare->first);
    const auto& den = find(compare->second);
    if (!num.mcmc || !den.mcmc) {
      std::printf("warning: --compare %s skipped: MCMC failed for a sample\n", o.compare.c_str());
    } else {
      const cal::ShearModulusRatio ratio = cal::compare_shear_moduli(num.mcmc->shear_modulus_draws(),
                                                                     den.mcmc->shear_modulus_draws(), 0.95, o.seed + 2);
      report.comparison = cal::SampleComparisonReport{compare->first, compare->second, ratio};
      std::printf("G_s ratio %s / %s: %.4g  %s, P(%s > %s) = %.3f\n", compare->first.c_str(), compare->second.c_str(),
                  ratio.median, interval_text(ratio.interval, 1.0).c_str(), compare->first.c_str(),
                  compare->second.c_str(), ratio.probability_greater_than_one);
    }
  }
  cal::ReportOptions ro;
  ro.plots = !o.no_plots;
  const cal::ReportFiles files = cal::write_calibration_report(report, o.report, ro);
  std::printf("report: %s (%zu files)%s\n", o.report.c_str(), files.files.size(),
              files.plots_written ? ", plots as PNG and SVG" : "");
  if (!files.plots_written && !o.no_plots) std::printf("warning: %s\n", files.plots_message.c_str());
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* c = app.add_subcommand(
      "calibrate",
      "G_s (uN/m) of each sample in a rheometer CSV by the alpha method, the direct fit and MCMC, with intervals; "
      "writes a report folder (summary.json, CSV tables, PNG/SVG plots)");
  c->add_option("data", o->data, "Rheometer CSV: sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n")
      ->capture_default_str();
  c->add_option("--surrogate", o->surrogate, "Surrogate file (rbcal.surrogate/1, from `rbcal surrogate build`)")
      ->capture_default_str();
  c->add_option("--method", o->method, "Method: alpha, direct, mcmc or all")
      ->check(CLI::IsMember({"alpha", "direct", "mcmc", "all"}))
      ->capture_default_str();
  c->add_option("--sample", o->samples, "Sample name (repeatable; default: every sample in the file)");
  c->add_option("--lambda", o->lambda, "Viscosity ratio lambda = eta1 / eta0 (fixed, or the start with --fit-lambda)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  c->add_flag("--fit-lambda", o->fit_lambda, "Fit lambda too (direct and mcmc), within the surrogate's lambda range");
  c->add_option("--cell-radius-um", o->cell_radius_um, "Cell major radius a [um] in Ca = eta0 gamma_dot a / G_s")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  c->add_option("--plateau-min-shear-rate", o->plateau_min_shear_rate,
                "Plasma rows with shear rate above this [1/s] give eta0")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  c->add_option("--phi-max", o->phi_max, "Leave out points with phi above this (the seed study used 0.4 for hardened cells)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  c->add_option("--seed", o->seed, "Seed of the MCMC, bands and comparison (same seed, same numbers)")->capture_default_str();
  c->add_option("--threads", o->threads, "OpenMP threads over MCMC chains (0: OpenMP's default); results do not depend on it")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  c->add_option("--compare", o->compare, "G_s ratio NUM/DEN of two samples with its interval (needs mcmc)");
  c->add_option("-o,--report", o->report, "Report folder (created if needed)")->capture_default_str();
  c->add_flag("--no-plots", o->no_plots, "Write summary and tables only");
  c->add_option("--mcmc-max-steps", o->mcmc_max_steps, "Stop the MCMC here even if not converged (steps per walker)")
      ->check(CLI::Range(8, 10000000))
      ->capture_default_str();
  c->add_option("--chains", o->chains, "Independent MCMC ensembles (R-hat compares them)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  c->add_option("--walkers", o->walkers, "Walkers per ensemble (at least twice the number of parameters)")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  c->callback([o] {
    // The equivalent command with every option spelled out, for the report's provenance.
    std::ostringstream line;
    line << "rbcal calibrate " << o->data << " --surrogate " << o->surrogate << " --method " << o->method;
    for (const auto& s : o->samples) line << " --sample " << s;
    line << " --lambda " << o->lambda << (o->fit_lambda ? " --fit-lambda" : "") << " --cell-radius-um "
         << o->cell_radius_um << " --plateau-min-shear-rate " << o->plateau_min_shear_rate << " --phi-max " << o->phi_max
         << " --seed " << o->seed << " --chains " << o->chains << " --walkers " << o->walkers << " --mcmc-max-steps "
         << o->mcmc_max_steps << (o->compare.empty() ? "" : " --compare " + o->compare) << " -o " << o->report
         << (o->no_plots ? " --no-plots" : "");
    o->command_line = line.str();
    run_calibrate(*o);
  });
}

}  // namespace rbcal::cli
