// `rbcal library effective-phi TIER... -o OUT`: one library standing for the continuum,
// from runs at any resolutions, each moved to the volume fraction its thickened cells fill
// (surrogate/effective_volume_fraction.hpp); OUT/cases/ID_nN.json keep the raw values.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "cli/scatter_floor_options.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "solver/membrane/thickened_volume.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "surrogate/effective_volume_fraction.hpp"

namespace rbcal::cli {

namespace {

struct EffectivePhiOptions {
  std::vector<std::string> tiers;
  std::string output;
  surrogate::EffectiveVolumeFractionOptions mapping;
  ScatterFloorOptions scatter_phi;
};

// The Steiner terms of the cell the runs simulated, at radius 1 (cells.* of a case file,
// read as `rbcal simulate` reads it; every case shares them: they are part of the numerics
// signature).
solver::SteinerTerms cell_terms(const surrogate::LibraryCase& c) {
  const solver::SimulationCase run = solver::case_from_json(formats::read_json_file(c.source), c.source.string());
  return solver::steiner_terms(solver::reference_cell(run, 1.0));
}

void run_effective_phi(const EffectivePhiOptions& o) {
  namespace fs = std::filesystem;
  std::vector<surrogate::SimulationLibrary> tiers;
  for (const std::string& t : o.tiers) tiers.push_back(surrogate::read_library(t));
  const solver::SteinerTerms terms = cell_terms(tiers.front().cases.front());
  const auto ratio = [&](double offset) { return solver::thickened_volume_ratio(terms, offset); };
  const surrogate::MappedLibrary mapped = surrogate::map_to_effective_volume_fraction(tiers, ratio, o.mapping);
  // Two runs of one id at one resolution (the same point in two folders) would overwrite each other.
  std::set<std::string> ids;
  for (const auto& c : mapped.cases)
    if (!ids.insert(surrogate::mapped_case_id(c)).second)
      throw std::invalid_argument(c.raw.source.string() + ": a second run " + surrogate::mapped_case_id(c) +
                                  " (the same point at the same N_a in two libraries)");
  const fs::path cases_dir = formats::library_layout::cases(o.output);
  fs::create_directories(cases_dir);
  std::printf("rbcal library effective-phi: %zu runs from %zu librar%s -> %s\n", mapped.cases.size() + mapped.left_out.size(),
              tiers.size(), tiers.size() == 1 ? "y" : "ies", o.output.c_str());
  std::printf("  cell at radius 1: area %.4f, volume %.4f, mean-curvature integral %.4f\n", terms.area, terms.volume,
              terms.mean_curvature_integral);
  std::printf("  offset %g +- %g lattice spacings at N_a 8, slope %g per unit of 1 / N_a; phi_eff = g phi_actual with g:",
              o.mapping.offset, o.mapping.offset_sd, o.mapping.offset_slope);
  for (int n : {6, 8, 10, 12, 16}) std::printf(" %.3f (N_a %d)", ratio(o.mapping.offset_at(n) / n), n);
  std::printf("\n  %-34s %8s %10s %8s %7s %10s %16s\n", "run", "phi", "phi_actual", "phi_eff", "g", "eta_re", "sd");
  for (const auto& c : mapped.cases) {
    const std::string id = surrogate::mapped_case_id(c);
    formats::write_json_atomically(cases_dir / (id + ".json"), surrogate::mapped_case_json(c, o.mapping));
    const fs::path series = c.raw.source.parent_path() / (c.raw.id + ".csv");
    if (fs::exists(series)) fs::copy_file(series, cases_dir / (id + ".csv"), fs::copy_options::overwrite_existing);
    std::printf("  %-34s %8.4g %10.4g %8.4g %7.4f %10.4g %7.2g (sem %.2g)\n", id.c_str(),
                c.raw.phi, c.raw.phi_actual, c.phi_actual, c.volume_ratio, c.raw.eta_re, c.eta_re_sd, c.raw.eta_re_sem);
  }
  for (const auto& c : mapped.left_out)
    std::printf("  left out (g phi_actual above %g): %s at N_a %d\n", o.mapping.phi_max, c.id.c_str(), c.nodes_per_radius);
  std::printf("wrote %s (build its surrogate with `rbcal surrogate build %s`)\n", cases_dir.string().c_str(),
              o.output.c_str());
}

}  // namespace

void add_library_effective_phi_command(CLI::App& library) {
  auto o = std::make_shared<EffectivePhiOptions>();
  CLI::App* cmd = library.add_subcommand(
      "effective-phi",
      "eta_re of the continuum from runs at any resolutions: each run moved to the volume fraction its cells fill "
      "when thickened by the immersed boundary");
  cmd->add_option("tiers", o->tiers, "Libraries of runs (one resolution each, or mixed)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", o->output, "Output library folder (cases/ID_nN.json)")->required();
  cmd->add_option("--offset", o->mapping.offset,
                  "How much thicker the immersed boundary makes a membrane act, in lattice spacings (at N_a 8 when "
                  "--offset-slope is given)")
      ->capture_default_str()
      ->check(kNonNegative);
  cmd->add_option("--offset-slope", o->mapping.offset_slope,
                  "How the offset changes with resolution: c(N_a) = OFFSET + SLOPE (1 / N_a - 1 / 8), so that --offset is c "
                  "at N_a 8 (0: one c at every N_a; studies/ib-thickening)")
      ->capture_default_str();
  cmd->add_option("--offset-sd", o->mapping.offset_sd, "The offset's sd, entered in each case's sd as if independent (0: not entered; docs/library.md)")
      ->capture_default_str()
      ->check(kNonNegative);
  cmd->add_option("--phi-max", o->mapping.phi_max, "Leave out runs whose effective phi (g phi_actual) exceeds this")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));  // and not 0 or 1 (the mapping says so, naming --phi-max)
  add_scatter_floor_options(cmd, o->mapping.scatter, o->scatter_phi);
  cmd->callback([o] {
    apply_scatter_phi(o->scatter_phi, o->mapping.scatter);
    run_effective_phi(*o);
  });
}

}  // namespace rbcal::cli
