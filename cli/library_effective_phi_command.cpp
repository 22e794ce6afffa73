// `rbcal library effective-phi TIER... -o OUT`: one library standing for the continuum,
// from runs at any resolutions, each moved to the volume fraction its thickened cells fill
// (surrogate/effective_volume_fraction.hpp); OUT/cases/ID_nN.json keep the raw values.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cell_thickening.hpp"
#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "cli/scatter_floor_options.hpp"
#include "formats/library_schema.hpp"
#include "surrogate/effective_volume_fraction.hpp"
#include "surrogate/mapped_library_file.hpp"

namespace rbcal::cli {

namespace {

struct EffectivePhiOptions {
  std::vector<std::string> tiers;
  std::string output;
  surrogate::EffectiveVolumeFractionOptions mapping;
  ScatterFloorOptions scatter_phi;
};

void run_effective_phi(const EffectivePhiOptions& o) {
  std::vector<surrogate::SimulationLibrary> tiers;
  for (const std::string& t : o.tiers) tiers.push_back(surrogate::read_library(t));
  const solver::SteinerTerms terms = cell_terms(tiers.front().cases.front());
  const surrogate::VolumeRatio ratio = volume_ratio_of(terms);
  const surrogate::MappedLibrary mapped = surrogate::map_to_effective_volume_fraction(tiers, ratio, o.mapping);
  surrogate::write_mapped_library(mapped, o.mapping, o.output);
  std::printf("%s", surrogate::describe_mapped_library(mapped, tiers.size(), o.output, ratio, o.mapping).c_str());
  std::printf("  cell at radius 1: area %.4f, volume %.4f, mean-curvature integral %.4f\n", terms.area, terms.volume,
              terms.mean_curvature_integral);
  std::printf("wrote %s (build its surrogate with `rbcal surrogate build %s`)\n",
              formats::library_layout::cases(o.output).string().c_str(), o.output.c_str());
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
