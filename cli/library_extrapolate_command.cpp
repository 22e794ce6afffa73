// `rbcal library extrapolate COARSE FINE -o OUT`: a library of eta_re extrapolated to the
// continuum from the same design points at two resolutions
// (surrogate/resolution_extrapolation.hpp); OUT/cases/ID.json keep the raw values.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "cli/scatter_floor_options.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "surrogate/resolution_extrapolation.hpp"

namespace rbcal::cli {

namespace {

struct ExtrapolateOptions {
  std::string coarse, fine, output;
  surrogate::ExtrapolationOptions extrapolation;
  ScatterFloorOptions scatter_phi;
};

void run_extrapolate(const ExtrapolateOptions& o) {
  namespace fs = std::filesystem;
  const surrogate::SimulationLibrary coarse = surrogate::read_library(o.coarse);
  const surrogate::SimulationLibrary fine = surrogate::read_library(o.fine);
  const auto cases = surrogate::extrapolate_to_continuum(coarse, fine, o.extrapolation);
  const fs::path cases_dir = formats::library_layout::cases(o.output);
  fs::create_directories(cases_dir);
  std::printf("rbcal library extrapolate: %zu points from %s (N_a %d) and %s (N_a %d), order %g (uncertainty from %g)\n",
              cases.size(), o.coarse.c_str(), coarse.cases.front().nodes_per_radius, o.fine.c_str(),
              fine.cases.front().nodes_per_radius, o.extrapolation.order, o.extrapolation.order_low);
  if (o.extrapolation.scatter_floor > 0.0)
    std::printf("  seed-scatter floor: relative sd %g at phi >= %g, none at phi <= %g, linear between\n",
                o.extrapolation.scatter_floor, o.extrapolation.scatter_phi_high, o.extrapolation.scatter_phi_low);
  std::printf("  %-32s %10s %10s %16s  %s\n", "case", "coarse", "fine", "extrapolated", "method");
  for (const auto& c : cases) {
    formats::write_json_atomically(cases_dir / (c.coarse.id + ".json"), surrogate::extrapolated_case_json(c, o.extrapolation));
    char fine_value[32] = "";
    if (c.paired) std::snprintf(fine_value, sizeof fine_value, "%.4g", c.fine.eta_re);
    std::printf("  %-32s %10.4g %10s %9.4g +- %-5.2g  %s\n", c.coarse.id.c_str(), c.coarse.eta_re, fine_value,
                c.eta_re, c.eta_re_sd, c.method().c_str());
  }
  std::printf("wrote %s (build its surrogate with `rbcal surrogate build %s`)\n", cases_dir.string().c_str(),
              o.output.c_str());
}

}  // namespace

void add_library_extrapolate_command(CLI::App& library) {
  auto o = std::make_shared<ExtrapolateOptions>();
  CLI::App* cmd = library.add_subcommand(
      "extrapolate", "eta_re extrapolated to the continuum from a coarse and a fine library of the same points");
  cmd->add_option("coarse", o->coarse, "Library at the coarser resolution (every design point)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("fine", o->fine, "Library at the finer resolution (all or some of the points)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", o->output, "Output library folder (cases/ID.json)")->required();
  cmd->add_option("--order", o->extrapolation.order, "Convergence order p of the Richardson estimate")
      ->capture_default_str()
      ->check(kPositive);
  cmd->add_option("--order-low", o->extrapolation.order_low,
                  "Other plausible order: half the difference of the two extrapolations enters the sd")
      ->capture_default_str()
      ->check(kPositive);
  add_scatter_floor_options(cmd, o->extrapolation, o->scatter_phi);
  cmd->callback([o] {
    apply_scatter_phi(o->scatter_phi, o->extrapolation);
    run_extrapolate(*o);
  });
}

}  // namespace rbcal::cli
