// `rbcal calibrate [DATA.csv]`: G_s (and optionally lambda) of each sample in a rheometer CSV by
// the seed study's alpha method, the direct fit and the MCMC posterior, on a saved surrogate;
// prints the estimates with their intervals and writes a report folder (summary.json, CSV
// tables, plots). docs/reference.md. The policy lives in calibration/calibration_job.hpp.
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "calibration/calibration_job.hpp"
#include "cli/commands.hpp"
#include "formats/units.hpp"
#include "cli/number_validators.hpp"
#include "cli/data_folder.hpp"

namespace rbcal::cli {

namespace {

namespace cal = rbcal::calibration;

// The options as typed: paths as strings, the radius in um; the rest binds to the job.
struct CalibrateOptions {
  cal::CalibrationJobOptions job;
  std::string data = shipped_file("samples/kim2017_whole_blood.csv");
  std::string surrogate = shipped_file("library/default/surrogate_family.json");
  std::string report = "calibration_report";
  double cell_radius_um = cal::kDefaultCellRadius * kMicro;
  bool no_plots = false;
  std::string sampler = "independence";
  std::vector<std::string> hold;  // NAME=VALUE
};

// "offset_c=0.6" -> (offset_c, 0.6); CLI::ValidationError naming --hold otherwise.
std::pair<std::string, double> held_nuisance(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw CLI::ValidationError("--hold", "expected NAME=VALUE (e.g. offset_c=0.6), got '" + text + "'");
  std::string value = text.substr(eq + 1);
  if (const std::string why = kFinite(value); !why.empty()) throw CLI::ValidationError("--hold", text + ": " + why);
  return {text.substr(0, eq), std::stod(value)};
}

// The equivalent command with every option spelled out, for the report's provenance.
std::string command_line(const CalibrateOptions& o) {
  const cal::CalibrationJobOptions& j = o.job;
  std::ostringstream line;
  line << "rbcal calibrate " << o.data << " --surrogate " << o.surrogate << " --method " << j.method;
  for (const auto& s : j.samples) line << " --sample " << s;
  for (const auto& [name, value] : j.held_nuisances) line << " --hold " << name << "=" << value;
  if (j.compare_models) line << " --compare-models";
  for (const auto& f : j.alternative_models) line << " --alternative-model " << f.string();
  if (j.joint) line << " --joint" << (j.shared_lambda ? " --shared-lambda" : "") << (j.hierarchical ? " --hierarchical" : "");
  line << " --lambda " << j.setup.lambda << (j.setup.fit_lambda ? "" : " --fix-lambda") << " --lambda-prior-sd "
       << j.setup.lambda_prior_log_sd << " --cell-radius-um "
       << o.cell_radius_um << " --plateau-min-shear-rate " << j.plasma.plateau_min_shear_rate << " --phi-max "
       << j.phi_max << " --min-shear-rate " << j.min_shear_rate << (j.keep_out_of_hematocrit_order ? " --keep-out-of-order" : "") << (j.hold_coverable_points ? " --hold-points" : "") << " --seed " << j.sampler.seed << " --sampler " << o.sampler << " --chains " << j.sampler.chains << " --walkers "
       << j.sampler.walkers << " --mcmc-max-steps " << j.sampler.max_steps
       << (j.compare.empty() ? "" : " --compare " + j.compare) << " -o " << o.report
       << (o.no_plots ? " --no-plots" : "");
  return line.str();
}

}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  cal::CalibrationJobOptions& j = o->job;
  CLI::App* c = app.add_subcommand(
      "calibrate",
      "G_s (uN/m) of each sample in a rheometer CSV by the alpha method, the direct fit and MCMC, with intervals; "
      "writes a report folder (summary.json, CSV tables, PNG/SVG plots)");
  c->add_option("data", o->data, "Rheometer CSV: sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n")
      ->capture_default_str();
  c->add_option("--surrogate", o->surrogate,
                "Surrogate (rbcal.surrogate/1, `rbcal surrogate build`) or surrogate family (rbcal.surrogate_family/1, "
                "`rbcal surrogate family`: the immersed boundary's offset becomes a nuisance parameter of the direct "
                "fit and the MCMC)")
      ->capture_default_str();
  c->add_option("--method", j.method, "Method: alpha, direct, mcmc or all")
      ->check(CLI::IsMember({"alpha", "direct", "mcmc", "all"}))
      ->capture_default_str();
  c->add_option("--sample", j.samples, "Sample name (repeatable; default: every sample in the file)");
  c->add_option("--lambda", j.setup.lambda,
                "Viscosity ratio lambda = eta1 / eta0: the median of its prior (the value itself with --fix-lambda)")
      ->check(kPositive)
      ->capture_default_str();
  c->add_flag("!--fix-lambda", j.setup.fit_lambda,
              "Hold lambda at --lambda; by default the direct fit and the MCMC fit it as a nuisance parameter under its "
              "prior (the alpha method always uses --lambda)");
  c->add_option("--lambda-prior-sd", j.setup.lambda_prior_log_sd,
                "Sd of ln lambda's normal prior about ln(--lambda), within the model's lambda range (default: the "
                "cytoplasm's 6.07 +- 3.8 mPa s over plasma 1.2 mPa s, lambda 1.9-8.2 as 95 %; 0: uniform in ln lambda)")
      ->check(kNonNegative)
      ->capture_default_str();
  c->add_option("--cell-radius-um", o->cell_radius_um, "Cell major radius a [um] in Ca = eta0 gamma_dot a / G_s")
      ->check(kPositive)
      ->capture_default_str();
  c->add_option("--plateau-min-shear-rate", j.plasma.plateau_min_shear_rate,
                "Plasma rows with shear rate above this [1/s] give eta0")
      ->check(kNonNegative)
      ->capture_default_str();
  c->add_option("--phi-max", j.phi_max, "Leave out points with phi above this (the seed study used 0.4 for hardened cells)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  c->add_option("--min-shear-rate", j.min_shear_rate,
                "Leave out points below this shear rate [1/s]: whole blood aggregates at low shear, the "
                "simulations do not (0 keeps all; for washed or hardened cells)")
      ->check(kNonNegative)
      ->capture_default_str();
  c->add_flag("--keep-out-of-order", j.keep_out_of_hematocrit_order,
              "Keep points whose viscosity is not above the next lower hematocrit's at the same shear rate "
              "(left out and reported by default)");
  c->add_flag("--hold-points", j.hold_coverable_points,
              "Fit the largest set of points one G_s keeps inside the model's Ca range, G_s bounded to keep them "
              "there (a limit where the bound holds), instead of the points inside at the optimum");
  c->add_option("--seed", j.sampler.seed, "Seed of the MCMC, bands and comparison (same seed, same numbers)")
      ->capture_default_str();
  c->add_option("--threads", j.sampler.threads,
                "OpenMP threads over MCMC chains (0: OpenMP's default); results do not depend on it")
      ->check(kNonNegative)
      ->capture_default_str();
  c->add_option("--compare", j.compare,
                 "G_s ratio NUM/DEN of two samples with its interval, from their joint posterior (needs mcmc)");
  c->add_flag("--joint", j.joint,
              "Also one posterior over all selected samples: the model's nuisances (the offset c) shared, G_s and eta0 "
              "per sample");
  c->add_flag("--shared-lambda", j.shared_lambda, "With --joint: one lambda for all samples");
  c->add_flag("--hierarchical", j.hierarchical,
              "With --joint: a population layer ln G_s ~ N(mu, tau^2); reports the population's median G_s and tau");
  c->add_flag("--compare-models", j.compare_models,
              "Also calibrate each sample by MCMC with lambda fitted and with lambda held at --lambda, and rank the two "
              "by their evidence ln Z");
  c->add_option("--alternative-model", j.alternative_models,
                "Also calibrate each sample by MCMC on this model (a surrogate or family file: another level mapping, "
                "say) and rank it with the --compare-models variants by ln Z (repeatable)")
      ->check(CLI::ExistingFile);
  c->add_option("--hold", o->hold,
                "Hold a model nuisance at a value instead of fitting it, NAME=VALUE (repeatable): e.g. offset_c=0.6 for "
                "G_s at the immersed-boundary offset 0.6 (a sensitivity study)");
  c->add_option("-o,--report", o->report, "Report folder (created if needed)")->capture_default_str();
  c->add_flag("--no-plots", o->no_plots, "Write summary and tables only");
  c->add_option("--mcmc-max-steps", j.sampler.max_steps, "Stop the MCMC here even if not converged (steps per walker)")
      ->check(CLI::Range(8, 10000000))
      ->capture_default_str();
  c->add_option("--sampler", o->sampler,
                "MCMC sampler: independence (a short stretch-move pilot, then independence Metropolis-Hastings "
                "with a multivariate t fitted to it; falls back to the ensemble if the fit is poor) or ensemble "
                "(stretch move throughout)")
      ->check(CLI::IsMember({"independence", "ensemble"}))
      ->capture_default_str();
  c->add_option("--chains", j.sampler.chains, "Independent MCMC ensembles (R-hat compares them)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  c->add_option("--walkers", j.sampler.walkers,
                "Walkers per ensemble (at least twice the number of parameters; 0: 8 per parameter, at least 16)")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  c->callback([o] {
    cal::CalibrationJobOptions& job = o->job;
    job.data_file = o->data;
    job.surrogate_file = o->surrogate;
    job.report_folder = o->report;
    job.setup.cell_radius = o->cell_radius_um / kMicro;
    job.report.plots = !o->no_plots;
    job.sampler.sampler = cal::sampler_from_string(o->sampler);
    for (const std::string& h : o->hold) job.held_nuisances.push_back(held_nuisance(h));
    job.command_line = command_line(*o);
    const cal::CalibrationJobResult result = cal::run_calibration_job(job, std::cout);
    // A run that estimated nothing has failed, whatever it wrote: scripts must see it.
    int estimated = 0;
    for (const auto& s : result.report.samples) estimated += s.has_estimate() ? 1 : 0;
    if (estimated == 0) {
      std::cerr << "rbcal calibrate: no sample gave an estimate of G_s (the warnings above say why); exit 1\n";
      throw ExitStatus{1};
    }
  });
}

}  // namespace rbcal::cli
