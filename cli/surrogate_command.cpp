// `rbcal surrogate build LIB [-o OUT]`: fit the Gaussian-process surrogate to a simulation
// library and report its leave-one-out errors; `rbcal surrogate predict SURROGATE --phi
// --ca --lambda [--offset C]`: eta_re with its predictive sd from a saved surrogate or family;
// `rbcal surrogate family --member C=FILE ... -o OUT`: surrogates of one library at several
// immersed-boundary offsets as one model with the offset as a nuisance parameter.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "calibration/model_setup.hpp"
#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "surrogate/model_description.hpp"
#include "surrogate/offset_family_file.hpp"
#include "surrogate/surrogate_file.hpp"
#include "surrogate/trend_check.hpp"

namespace rbcal::cli {

namespace {

struct SurrogateBuildOptions {
  std::string library;
  std::string output;
  std::string hyperparameters_of;  // a surrogate file whose hyper-parameters are taken (not fitted)
  double warn_limit = 3.0;
};

struct SurrogatePredictOptions {
  std::string surrogate;
  double phi = 0.0, ca = 0.0, lambda = calibration::kDefaultViscosityRatio;
  double offset = std::nan("");  // a family's offset; NaN: its prior mean
};

struct SurrogateFamilyOptions {
  std::vector<std::string> members;  // OFFSET=FILE
  double prior_mean = 0.75, prior_sd = 0.05;  // the shipped family's prior
  double box_mean = std::nan(""), box_sd = std::nan("");  // the box correction's prior (both or neither)
  std::string box_source;
  std::string output;
};

void run_build(const SurrogateBuildOptions& o) {
  const std::filesystem::path out =
      o.output.empty() ? std::filesystem::path(o.library) / "surrogate.json" : std::filesystem::path(o.output);
  const surrogate::ViscositySurrogate s = o.hyperparameters_of.empty()
                                             ? surrogate::build_surrogate(o.library)
                                             : surrogate::build_surrogate_like(o.library, o.hyperparameters_of);
  surrogate::save_surrogate(s, out);
  std::printf("rbcal surrogate build: %s -> %s\n", o.library.c_str(), out.string().c_str());
  std::printf("%s", surrogate::describe_surrogate(s).c_str());
  const surrogate::LeaveOneOutReport loo = s.leave_one_out();
  std::cout << surrogate::format_leave_one_out(loo, o.warn_limit);
  for (const auto& c : loo.cases)
    if (std::abs(c.standardised_residual) > o.warn_limit)
      std::cerr << "rbcal surrogate build: warning: case " << c.id << " has standardised leave-one-out residual "
                << c.standardised_residual << "\n";
}

void run_predict(const SurrogatePredictOptions& o) {
  const std::unique_ptr<surrogate::ViscosityModel> model = surrogate::load_viscosity_model(o.surrogate);
  const surrogate::ViscosityModel& s = *model;
  const std::vector<surrogate::ModelNuisance> nuisances = s.nuisances();
  if (!std::isnan(o.offset) && nuisances.empty())
    throw CLI::ValidationError("--offset", o.surrogate + " is a single surrogate, not a family with an offset");
  std::vector<double> values;
  for (const auto& n : nuisances) values.push_back(n.mean);
  if (!nuisances.empty() && !std::isnan(o.offset)) {
    const surrogate::ModelNuisance& c = nuisances.front();  // the family's offset
    if (!(o.offset >= c.min && o.offset <= c.max))
      throw CLI::ValidationError("--offset", "must lie within the family's offsets " + std::to_string(c.min) + " .. " +
                                                 std::to_string(c.max));
    values.front() = o.offset;
  }
  const surrogate::ViscosityPrediction p =
      s.predict(o.phi, o.ca, o.lambda, surrogate::NuisanceValues(nuisances, values));
  std::printf("phi %.4g, Ca %.4g, lambda %.4g\n", o.phi, o.ca, o.lambda);
  for (std::size_t k = 0; k < nuisances.size(); ++k)
    std::printf("  %-19s %.4g (%s; prior %.4g +- %.4g, %.4g .. %.4g)\n", nuisances[k].name.c_str(), values[k],
                nuisances[k].what.c_str(), nuisances[k].mean, nuisances[k].sd, nuisances[k].min, nuisances[k].max);
  std::printf("  eta_re              %.6g +- %.3g (1 sd, surrogate uncertainty)\n", p.eta_re, p.sd);
  std::printf("  d eta_re / d phi    %.6g\n", p.d_phi);
  std::printf("  d eta_re / d ln Ca  %.6g\n", p.d_ln_ca);
  std::printf("  d eta_re / d ln lambda %.6g\n", p.d_ln_lambda);
  if (!p.inside_hull) {
    const surrogate::ParameterRange r = s.range();
    std::printf("warning: outside the library (phi %.4g .. %.4g, Ca %.4g .. %.4g, lambda %.4g .. %.4g): extrapolation\n",
                r.phi_min, r.phi_max, r.ca_min, r.ca_max, r.lambda_min, r.lambda_max);
    std::cerr << "rbcal surrogate predict: warning: query outside the library's range\n";
  }
}

void run_family(const SurrogateFamilyOptions& o) {
  std::vector<surrogate::SurrogateFamilyMember> members;
  for (const std::string& m : o.members) {
    const auto eq = m.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == m.size())
      throw CLI::ValidationError("--member", "expected OFFSET=FILE, got \"" + m + "\"");
    double offset = 0.0;
    try {
      std::size_t used = 0;
      offset = std::stod(m.substr(0, eq), &used);
      if (used != eq) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
      throw CLI::ValidationError("--member", "offset \"" + m.substr(0, eq) + "\" is not a number");
    }
    members.push_back({offset, surrogate::load_surrogate(m.substr(eq + 1))});
  }
  std::optional<surrogate::BoxCorrectionRecord> box;
  if (std::isnan(o.box_mean) != std::isnan(o.box_sd))
    throw CLI::ValidationError("--box-mean/--box-sd", "give both or neither");
  if (!std::isnan(o.box_mean)) {
    if (o.box_source.empty()) throw CLI::ValidationError("--box-source", "say where the box correction's numbers come from");
    box = surrogate::BoxCorrectionRecord{{o.box_mean, o.box_sd}, o.box_source};
  }
  const surrogate::OffsetFamilyModel family =
      surrogate::save_surrogate_family(std::move(members), o.prior_mean, o.prior_sd, o.output, box);
  std::printf("rbcal surrogate family: %zu members -> %s\n%s", family.members().size(), o.output.c_str(),
              surrogate::describe_family(family, box ? box->source : "").c_str());
}

}  // namespace

void add_surrogate_command(CLI::App& app) {
  CLI::App* surrogate =
      app.add_subcommand("surrogate", "Gaussian-process surrogate of eta_re(phi, Ca, lambda): build, predict, check");
  surrogate->require_subcommand(1);

  auto b = std::make_shared<SurrogateBuildOptions>();
  CLI::App* build = surrogate->add_subcommand(
      "build", "Fit the surrogate to a library (LIB/cases/*.json): hyper-parameters, leave-one-out report -> JSON");
  build->add_option("library", b->library, "Library folder (with cases/)")->required()->check(CLI::ExistingDirectory);
  build->add_option("-o,--output", b->output, "Surrogate file (default: LIB/surrogate.json)");
  build->add_option("--hyperparameters-of", b->hyperparameters_of,
                    "Take the hyper-parameters of this surrogate instead of fitting them (members of a surrogate "
                    "family: the same runs at other offsets)")
      ->check(CLI::ExistingFile);
  build->add_option("--warn-residual", b->warn_limit, "Warn about cases with |standardised LOO residual| above this")
      ->check(kPositive);
  build->callback([b] { run_build(*b); });

  auto p = std::make_shared<SurrogatePredictOptions>();
  CLI::App* predict = surrogate->add_subcommand("predict", "eta_re +- sd and derivatives from a saved surrogate");
  predict->add_option("surrogate", p->surrogate, "Surrogate file (rbcal.surrogate/1) or family (rbcal.surrogate_family/1)")
      ->required()
      ->check(CLI::ExistingFile);
  predict->add_option("--phi", p->phi, "Volume fraction")->required()->check(CLI::Range(0.0, 1.0));
  predict->add_option("--ca", p->ca, "Capillary number eta0 gamma_dot a / G_s")->required()->check(kPositive);
  predict->add_option("--lambda", p->lambda, "Viscosity ratio eta1 / eta0")->capture_default_str()->check(kPositive);
  predict->add_option("--offset", p->offset, "A family's immersed-boundary offset c (default: its prior mean)")
      ->check(kFinite);
  predict->callback([p] { run_predict(*p); });

  auto f = std::make_shared<SurrogateFamilyOptions>();
  CLI::App* family = surrogate->add_subcommand(
      "family",
      "Join surrogates of one library mapped at equally spaced offsets c (rbcal library effective-phi --offset C) "
      "into one model whose offset the calibration treats as a nuisance parameter");
  family->add_option("--member", f->members, "OFFSET=SURROGATE_FILE (at least two, equally spaced offsets)")
      ->required();
  family->add_option("--prior-mean", f->prior_mean, "Prior mean of c [lattice spacings]")->capture_default_str();
  family->add_option("--box-mean", f->box_mean,
                     "Box correction beta's prior mean, ln eta_bulk = (1 + beta) ln eta_re (with --box-sd, --box-source)");
  family->add_option("--box-sd", f->box_sd, "Box correction's prior sd")->check(kPositive);
  family->add_option("--box-source", f->box_source, "Where the box correction's numbers come from (kept in the file)");
  family->add_option("--prior-sd", f->prior_sd, "Prior sd of c (truncated to the members' offsets)")
      ->check(kPositive)
      ->capture_default_str();
  family->add_option("-o,--output", f->output, "Family file (rbcal.surrogate_family/1)")->required();
  family->callback([f] { run_family(*f); });

  auto check_file = std::make_shared<std::string>();
  CLI::App* check = surrogate->add_subcommand(
      "check", "Physical trends over a probe grid: rises with phi, shear thinning, high-shear blood (exit 1 on failure)");
  check->add_option("surrogate", *check_file, "Surrogate file (rbcal.surrogate/1) or family (at its prior mean)")
      ->required()
      ->check(CLI::ExistingFile);
  check->callback([check_file] {
    const surrogate::TrendCheck t = surrogate::check_trends(*surrogate::load_viscosity_model(*check_file));
    std::cout << "rbcal surrogate check: " << *check_file << "\n" << t.report();
    if (!t.passed()) throw CLI::RuntimeError(1);
  });
}

}  // namespace rbcal::cli
