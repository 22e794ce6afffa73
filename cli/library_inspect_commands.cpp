// `rbcal library show LIB`: cases, ranges, cost and the grid of present / missing points;
// `rbcal library propose LIB [-n K]`: the next cases where the surrogate is least sure.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "surrogate/case_proposal.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "surrogate/library_summary.hpp"
#include "surrogate/surrogate_file.hpp"

namespace rbcal::cli {

namespace {

struct ProposeOptions {
  std::string library;
  std::size_t count = 5;
  std::string surrogate;  // empty: LIB/surrogate.json if present, else fit now
  std::vector<double> phi, ca, lambda;
  std::string json_path;
};

surrogate::ParameterGrid candidate_grid(const ProposeOptions& o, const surrogate::SimulationLibrary& lib) {
  if (!o.phi.empty() || !o.ca.empty() || !o.lambda.empty()) {
    if (o.phi.empty() || o.ca.empty() || o.lambda.empty())
      throw std::invalid_argument("library propose: a user grid needs all of --phi, --ca and --lambda");
    return {o.phi, o.ca, o.lambda, {}};
  }
  if (lib.plan && lib.plan->is_listed()) {
    // A space-filling design has no axes to refine: a regular grid over its box instead,
    // phi linear, Ca and lambda logarithmic (9 x 9 x 5 candidates).
    auto spaced = [](const std::vector<double>& axis, int n, bool log) {
      const double lo = axis.front(), hi = axis.back();
      std::vector<double> v;
      for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        v.push_back(log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t);
      }
      return v;
    };
    const surrogate::ParameterGrid& p = *lib.plan;
    return {spaced(p.phi, 9, false), spaced(p.capillary_number, 9, true), spaced(p.viscosity_ratio, 5, true), {}};
  }
  if (lib.plan) return surrogate::refined(*lib.plan);
  surrogate::ParameterGrid present;
  for (const auto& c : lib.cases) {
    present.phi.push_back(c.phi);
    present.capillary_number.push_back(c.capillary_number);
    present.viscosity_ratio.push_back(c.viscosity_ratio);
  }
  return surrogate::refined(present);
}

void run_propose(const ProposeOptions& o) {
  const surrogate::SimulationLibrary lib = surrogate::read_library(o.library);
  std::filesystem::path surrogate_file = o.surrogate;
  if (surrogate_file.empty() && std::filesystem::exists(std::filesystem::path(o.library) / "surrogate.json"))
    surrogate_file = std::filesystem::path(o.library) / "surrogate.json";
  const surrogate::ViscositySurrogate s =
      surrogate_file.empty() ? surrogate::ViscositySurrogate::fit(surrogate::training_cases(lib), o.library)
                             : surrogate::load_surrogate(surrogate_file);
  if (!surrogate_file.empty() && s.training_cases().size() != lib.cases.size())
    std::cerr << "rbcal library propose: warning: " << surrogate_file.string() << " was built on "
              << s.training_cases().size() << " cases, the library now has " << lib.cases.size()
              << " (rebuild with `rbcal surrogate build`)\n";
  const surrogate::ParameterGrid grid = candidate_grid(o, lib);
  std::vector<surrogate::ParameterPoint> simulated;
  for (const auto& c : lib.cases) simulated.push_back({c.phi, c.capillary_number, c.viscosity_ratio});
  const std::vector<surrogate::ProposedCase> proposals = surrogate::propose_cases(s, grid, o.count, simulated);
  std::printf("rbcal library propose: %zu of %zu candidates (%s), surrogate %s\n", proposals.size(), grid.size(),
              !o.phi.empty() ? "user grid" : lib.plan ? "plan grid refined" : "library grid refined",
              surrogate_file.empty() ? "fitted now" : surrogate_file.string().c_str());
  std::printf("  %3s %8s %8s %8s %10s %12s %14s\n", "#", "phi", "Ca", "lambda", "eta_re", "rel. sd now", "when chosen");
  nlohmann::json cases = nlohmann::json::array();
  for (std::size_t i = 0; i < proposals.size(); ++i) {
    const auto& p = proposals[i];
    std::printf("  %3zu %8.4g %8.4g %8.4g %10.5g %11.3g%% %13.3g%%%s\n", i + 1, p.phi, p.capillary_number,
                p.viscosity_ratio, p.eta_re, 100.0 * p.relative_sd, 100.0 * p.relative_sd_when_chosen,
                p.inside_hull ? "" : "  (outside the library)");
    cases.push_back({{"phi", p.phi},
                     {"Ca", p.capillary_number},
                     {"lambda", p.viscosity_ratio},
                     {"eta_re_predicted", p.eta_re},
                     {"relative_sd", p.relative_sd}});
  }
  if (!o.json_path.empty())
    formats::write_json_atomically(o.json_path,
                                   {{"schema", formats::kProposalSchema}, {"library", o.library}, {"cases", cases}});
}

}  // namespace

void add_library_inspect_commands(CLI::App& library) {
  auto show_library = std::make_shared<std::string>();
  CLI::App* show = library.add_subcommand("show", "Cases, ranges, cost, median SEM and the present / missing grid points");
  show->add_option("library", *show_library, "Library folder (with cases/, optionally plan.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  auto show_values = std::make_shared<bool>(false);
  show->add_flag("--values", *show_values, "Print each present point's eta_re in the grid tables instead of 'x'");
  show->callback([show_library, show_values] {
    std::cout << surrogate::format_summary(surrogate::summarise(surrogate::read_library(*show_library)), *show_values);
  });

  auto o = std::make_shared<ProposeOptions>();
  CLI::App* propose = library.add_subcommand(
      "propose", "Next cases where the surrogate's variance is largest (greedy over the plan grid refined, or a user grid)");
  propose->add_option("library", o->library, "Library folder")->required()->check(CLI::ExistingDirectory);
  propose->add_option("-n,--count", o->count, "How many cases to propose")->capture_default_str()->check(kPositive);
  propose->add_option("--surrogate", o->surrogate, "Surrogate file (default: LIB/surrogate.json if present, else fit now)")
      ->check(CLI::ExistingFile);
  propose->add_option("--phi", o->phi, "User grid: volume fractions (with --ca and --lambda)")->delimiter(',');
  propose->add_option("--ca", o->ca, "User grid: capillary numbers")->delimiter(',');
  propose->add_option("--lambda", o->lambda, "User grid: viscosity ratios")->delimiter(',');
  propose->add_option("--json", o->json_path, "Also write the proposals to this JSON file (schema rbcal.proposal/1)");
  propose->callback([o] { run_propose(*o); });
}

}  // namespace rbcal::cli
