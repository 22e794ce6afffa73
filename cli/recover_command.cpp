// `rbcal recover RUN... [--surrogate MODEL]`: samples of known G_s made from simulation results
// (calibration/synthetic_sample.hpp), calibrated as `rbcal calibrate` would, and the coverage
// of each method's 95 % interval (calibration/known_truth_recovery.hpp).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "calibration/known_truth_recovery.hpp"
#include "formats/json_file.hpp"
#include "formats/units.hpp"
#include "cli/cell_thickening.hpp"
#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "cli/number_validators.hpp"
#include "surrogate/library_case.hpp"
#include "surrogate/offset_family_file.hpp"

namespace rbcal::cli {

namespace {

struct RecoverOptions {
  std::vector<std::string> runs;
  std::string surrogate = shipped_file("library/default/surrogate_family.json");
  std::vector<double> shear_moduli_uN = {1.0, 2.0, 4.0, 8.0};
  int replicates = 3;
  double plasma_viscosity_mPa = 1.2;
  double plasma_relative_sd = 0.02;
  double cell_radius_um = 4.0;
  double noise = 0.05;
  unsigned long long seed = 1;
  std::optional<double> offset;  // empty: the offset the model's runs were mapped with
  std::string method = "all";
  bool hold_points = false;
  std::string output;
  std::string samples_folder;
  double required_coverage = 0.0;
};

// The offset c(N_a) each run is mapped with: --offset for every run, else the model's own
// mapping (surrogate::recorded_offset), so that a run stands where the model's runs of that
// resolution stand.
struct RunOffset {
  std::optional<double> given;
  surrogate::RecordedOffset model;
  double at(int nodes_per_radius) const { return given ? *given : model.at(nodes_per_radius); }
  std::string describe() const {
    char buf[128];
    if (given)
      std::snprintf(buf, sizeof buf, "offset %g", *given);
    else
      std::snprintf(buf, sizeof buf, "the model's offset %g + %g (1/N_a - 1/8)", model.at_n8, model.slope);
    return buf;
  }
};

RunOffset run_offset(const RecoverOptions& o, const nlohmann::json& model_file) {
  RunOffset r{o.offset, {}};
  if (o.offset) return r;
  std::optional<surrogate::RecordedOffset> recorded;
  try {
    recorded = surrogate::recorded_offset(model_file);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(o.surrogate + ": its prior.mean or provenance.recipe.mapping cannot be read (" +
                                e.what() + "); give --offset");
  }
  if (!recorded)
    throw std::invalid_argument(o.surrogate + ": records no offset of its mapping (no family prior, no recipe); give "
                                "--offset");
  r.model = *recorded;
  return r;
}

// A run's point: eta_re at the volume fraction its thickened cells fill (offset c lattice
// spacings, as `rbcal library effective-phi` maps it; c 0: the volume fraction as run).
calibration::SimulatedViscosity simulated_point(const surrogate::LibraryCase& c, double offset) {
  // A case already moved to the continuum (an effective-volume-fraction or extrapolated
  // library's) stands for it at its phi: mapping it again would thicken it twice.
  if (offset > 0.0 && !c.extrapolation_method.empty())
    throw std::invalid_argument(c.source.string() + ": already moved to the continuum (" + c.extrapolation_method +
                                "); give the runs as simulated, or --offset 0 to take it at its phi");
  if (offset > 0.0 && c.nodes_per_radius <= 0) throw std::invalid_argument(c.source.string() + ": field numerics.N_a: missing");
  const double g = offset > 0.0 ? volume_ratio_of(cell_terms(c))(offset / c.nodes_per_radius) : 1.0;
  // NAME.result.json (a run's result.json kept under its case's name) is called NAME.
  std::string id = c.id;
  if (id.ends_with(".result")) id.resize(id.size() - std::string(".result").size());
  return {id, g * c.phi_actual, c.capillary_number, c.viscosity_ratio, c.eta_re, c.eta_re_sem};
}

void run_recover(const RecoverOptions& o) {
  // The report's file is opened first: a bad path fails now, not after the calibrations.
  std::ofstream out;
  if (!o.output.empty()) {
    out.open(o.output);
    if (!out) throw std::runtime_error("cannot write " + o.output);
  }
  const nlohmann::json model_file = formats::read_json_file(o.surrogate);  // read once: offset record and model
  const RunOffset offset = run_offset(o, model_file);
  std::vector<calibration::SimulatedViscosity> points;
  for (const std::string& f : o.runs) {
    const surrogate::LibraryCase run = surrogate::read_library_case(f);
    points.push_back(simulated_point(run, offset.at(run.nodes_per_radius)));
  }
  // One sample is one suspension: its runs share lambda (the calibration's lambda prior applies).
  for (const auto& p : points)
    if (p.viscosity_ratio != points.front().viscosity_ratio)
      throw std::invalid_argument("runs at lambda " + std::to_string(points.front().viscosity_ratio) + " and " +
                                  std::to_string(p.viscosity_ratio) + " (" + p.id +
                                  "): one synthetic sample takes runs at one lambda");
  calibration::RecoveryOptions r;
  r.shear_moduli.clear();
  for (double g : o.shear_moduli_uN) r.shear_moduli.push_back(g / kMicro);
  r.replicates = o.replicates;
  r.sample.plasma_viscosity = o.plasma_viscosity_mPa / kMilli;
  r.sample.plasma_viscosity_relative_sd = o.plasma_relative_sd;
  r.sample.cell_radius = o.cell_radius_um / kMicro;
  r.sample.relative_noise = o.noise;
  r.sample.seed = o.seed;
  r.job.method = o.method;
  r.job.hold_coverable_points = o.hold_points;
  r.samples_folder = o.samples_folder;
  r.job.surrogate_file = o.surrogate;
  r.job.setup.cell_radius = r.sample.cell_radius;
  const std::unique_ptr<surrogate::ViscosityModel> model = surrogate::viscosity_model_from_json(model_file, o.surrogate);
  // Relative to the working folder: the log and the record name no path of the machine they ran on.
  const std::string model_shown =
      std::filesystem::path(o.surrogate).lexically_proximate(std::filesystem::current_path()).string();
  std::printf("rbcal recover: %zu runs (phi at %s), model %s, %zu true G_s x %d noise draws\n", points.size(),
              offset.describe().c_str(), model_shown.c_str(), r.shear_moduli.size(), r.replicates);
  for (const auto& p : points)
    std::printf("  %s: phi %.4f, Ca %g, lambda %g, eta_re %.4f +- %.4f\n", p.id.c_str(), p.phi, p.capillary_number,
                p.viscosity_ratio, p.eta_re, p.eta_re_se);
  std::fflush(stdout);
  const calibration::RecoveryReport report = calibration::recover_known_shear_moduli(points, *model, r, std::cout);
  std::printf("%s", report.table().c_str());
  if (!o.output.empty()) {
    nlohmann::json j = report.to_json();
    j["model"] = model_shown;
    j["offset"] = o.offset ? nlohmann::json(*o.offset)
                           : nlohmann::json{{"at_N_a_8", offset.model.at_n8}, {"slope", offset.model.slope}};
    j["sample"] = {{"plasma_viscosity_mPa_s", o.plasma_viscosity_mPa},
                   {"plasma_relative_sd", o.plasma_relative_sd},
                   {"cell_radius_um", o.cell_radius_um},
                   {"relative_noise", o.noise},
                   {"first_seed", o.seed}};
    j["method"] = o.method;
    out << j.dump(1) << '\n';
    if (!out) throw std::runtime_error("cannot write " + o.output);
    std::printf("wrote %s\n", o.output.c_str());
  }
  if (o.required_coverage > 0.0) {
    if (report.coverage.empty())
      throw std::invalid_argument("--require-coverage needs an interval method (--method direct, mcmc or all)");
    for (const calibration::MethodCoverage& c : report.coverage)
      if (c.fraction() < o.required_coverage) {
        std::printf("%s: coverage %.2f below the required %.2f\n", c.method.c_str(), c.fraction(), o.required_coverage);
        throw ExitStatus{1};
      }
  }
}

}  // namespace

void add_recover_command(CLI::App& app) {
  auto o = std::make_shared<RecoverOptions>();
  CLI::App* cmd = app.add_subcommand(
      "recover",
      "Simulated truth: samples of known G_s made from simulation results (shear rate = Ca G_s / (eta0 a), viscosity "
      "= eta0 eta_re with relative noise), calibrated as `rbcal calibrate` does; prints whether each method's 95 % "
      "interval holds the truth");
  cmd->add_option("runs", o->runs, "Finished runs (result.json of `rbcal simulate`, or a library's cases/*.json)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--surrogate", o->surrogate, "Model to calibrate with (surrogate or family file)")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  cmd->add_option("--shear-moduli", o->shear_moduli_uN, "True G_s [uN/m]")->delimiter(',')->capture_default_str();
  cmd->add_option("--replicates", o->replicates, "Noise draws per true G_s")->capture_default_str()->check(
      CLI::PositiveNumber);
  cmd->add_option("--plasma-viscosity", o->plasma_viscosity_mPa, "eta0 [mPa s]")->capture_default_str()->check(
      kPositive);
  cmd->add_option("--plasma-relative-sd", o->plasma_relative_sd,
                  "sd of the samples' plasma_assumed row, relative to eta0")
      ->capture_default_str()
      ->check(kPositive);
  cmd->add_option("--cell-radius", o->cell_radius_um, "a [um]")->capture_default_str()->check(kPositive);
  cmd->add_option("--noise", o->noise, "Relative sd of each reading (at most 0.2: a reading stays positive)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.2));
  cmd->add_option("--seed", o->seed, "Seed of the first sample's noise (then +1 per sample)")->capture_default_str();
  cmd->add_option("--offset", o->offset,
                  "Immersed-boundary offset c [lattice spacings] that maps each run to the volume fraction it stands "
                  "for (0: the volume fraction as run); default: the model's own, c8 + slope (1/N_a - 1/8) with c8 "
                  "the family's prior mean and the slope its recipe's, at each run's N_a")
      ->check(kNonNegative);
  cmd->add_option("--method", o->method, "alpha, direct, mcmc or all")
      ->capture_default_str()
      ->check(CLI::IsMember({"alpha", "direct", "mcmc", "all"}));
  cmd->add_flag("--hold-points", o->hold_points,
                "Fit each sample as `rbcal calibrate --hold-points` does (the largest set of points one G_s keeps "
                "inside the model's Ca range)");
  cmd->add_option("-o,--output", o->output, "Also write the cases and coverage as JSON (rbcal.recovery/1)");
  cmd->add_option("--write-samples", o->samples_folder,
                  "Also write each synthetic sample to this folder as a rheometer CSV (gs<G_s>_seed<seed>.csv), "
                  "for `rbcal calibrate` to take up one case by hand");
  cmd->add_option("--require-coverage", o->required_coverage,
                  "Exit 1 when the direct fit's or the MCMC's coverage is below this fraction")
      ->check(CLI::Range(0.0, 1.0));
  cmd->callback([o] { run_recover(*o); });
}

}  // namespace rbcal::cli
