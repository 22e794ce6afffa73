// `rbcal overlaps CHECKPOINT`: how far the membranes of a saved state reach into other
// cells (nodes inside another cell, the deepest, the volume claimed twice). For runs
// written before result.json carried these figures, and for states mid-run.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "solver/simulation/cell_overlap.hpp"
#include "solver/simulation/checkpoint.hpp"
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::cli {

namespace {

struct OverlapsOptions {
  std::string checkpoint;
  double spacing = 0.0;  // grid spacing in lattice units (0: solver::overlap_grid_spacing)
};

void run_overlaps(const OverlapsOptions& o) {
  const solver::CheckpointState s = solver::read_checkpoint(o.checkpoint);
  // The checkpoint carries its case (params, cells, numerics): the mesh and the box.
  const solver::SimulationCase c =
      solver::case_from_json(nlohmann::json::parse(s.case_json), o.checkpoint + " (its case)");
  const solver::LatticeUnits u = solver::derive_lattice_units(c.flow, c.resolution);
  const double a = c.resolution.nodes_per_radius;
  const solver::TriangleMesh mesh = solver::reference_cell(c, a);
  long nodes = 0;
  for (const auto& cell : s.positions) nodes += static_cast<long>(cell.size());
  const solver::OverlapCount n = solver::count_overlaps(s.positions, mesh.triangles, u.nx, u.nz);
  const double spacing = o.spacing > 0.0 ? o.spacing : solver::overlap_grid_spacing(c.resolution.nodes_per_radius);
  const double volume = n.nodes_inside > 0 ? solver::overlap_volume_fraction(s.positions, mesh.triangles, u.nx, u.ny,
                                                                             u.nz, spacing)
                                           : 0.0;
  std::printf("rbcal overlaps: %s (N_a %d, %zu cells, %lld steps)\n", o.checkpoint.c_str(),
              c.resolution.nodes_per_radius, s.positions.size(), static_cast<long long>(s.steps));
  std::printf("  nodes inside another cell  %ld of %ld (%.2f %%), %d ordered cell pairs\n", n.nodes_inside, nodes,
              100.0 * n.nodes_inside / nodes, n.cell_pairs);
  std::printf("  deepest                    %.2f lattice spacings (upper bound: distance to the host's nearest node)\n",
              n.max_depth);
  std::printf("  volume claimed twice       %.3f %% of the cells' volume (grid %.3g lattice spacings)\n", 100.0 * volume,
              spacing);
}

}  // namespace

void add_overlaps_command(CLI::App& app) {
  auto o = std::make_shared<OverlapsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "overlaps", "How far membranes reach into other cells in a saved state (checkpoint.bin of rbcal simulate)");
  cmd->add_option("checkpoint", o->checkpoint, "A run's checkpoint.bin")->required()->check(CLI::ExistingFile);
  cmd->add_option("--spacing", o->spacing, "Grid spacing of the volume estimate in lattice units (default a / 6)")
      ->check(CLI::PositiveNumber);
  cmd->callback([o] { run_overlaps(*o); });
}

}  // namespace rbcal::cli
