// `rbcal overlaps CHECKPOINT`: how far the membranes of a saved state reach into other
// cells (nodes inside another cell, the deepest, the volume claimed twice). For runs
// written before result.json carried these figures, and for states mid-run. It also
// names the fastest node, where it sits and how close another cell comes: for the states
// a run keeps when its node Mach guard trips (checkpoint_failed.bin), and the mesh's
// health: collapsed triangles and folded hinges (solver/membrane/mesh_health.hpp), and how
// the cells sit across the gap (layers: solver/simulation/gap_profile.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "solver/membrane/dihedral_bending.hpp"
#include "solver/membrane/mesh_health.hpp"
#include "solver/simulation/cell_overlap.hpp"
#include "solver/simulation/checkpoint.hpp"
#include "solver/simulation/gap_profile.hpp"
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::cli {

namespace {

struct OverlapsOptions {
  std::string checkpoint;
  double spacing = 0.0;  // grid spacing in lattice units (0: solver::overlap_grid_spacing)
};

// Shortest and longest edge of one cell's mesh: lengths, or ratios to the rest shape's.
struct EdgeRange {
  double least = 1e300, most = 0.0;
};
EdgeRange edge_range(const std::vector<solver::Vec3>& x, const solver::TriangleMesh& mesh, bool relative) {
  EdgeRange r;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const int i = t[e], j = t[(e + 1) % 3];
      const double length = (x[i] - x[j]).norm() / (relative ? (mesh.vertices[i] - mesh.vertices[j]).norm() : 1.0);
      r.least = std::min(r.least, length);
      r.most = std::max(r.most, length);
    }
  return r;
}

// The node with the largest speed, its distance to the nearer wall, and the nearest node
// of another cell (periodic in x and z), in lattice spacings.
void print_fastest_node(const solver::CheckpointState& s, const solver::LatticeUnits& u,
                        const solver::TriangleMesh& mesh) {
  std::size_t cell = 0, node = 0;
  double fastest = -1.0;
  for (std::size_t i = 0; i < s.velocities.size(); ++i)
    for (std::size_t m = 0; m < s.velocities[i].size(); ++m)
      if (s.velocities[i][m].norm() > fastest) {
        fastest = s.velocities[i][m].norm();
        cell = i;
        node = m;
      }
  if (fastest < 0.0) return;
  const solver::Vec3& p = s.positions[cell][node];
  auto wrapped = [](double d, double n) { return d - n * std::round(d / n); };
  double nearest = std::numeric_limits<double>::infinity();
  std::size_t other = 0;
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    if (i == cell) continue;
    for (const solver::Vec3& q : s.positions[i]) {
      const double d = std::hypot(wrapped(q.x() - p.x(), u.nx), q.y() - p.y(), wrapped(q.z() - p.z(), u.nz));
      if (d < nearest) {
        nearest = d;
        other = i;
      }
    }
  }
  // Walls at y = -1/2 and ny - 1/2 (immersed_boundary.hpp).
  const double wall = std::min(p.y() + 0.5, u.ny - 0.5 - p.y());
  std::printf("  fastest node               cell %zu node %zu, Mach %.3g, %.2f spacings from a wall, nearest node of "
              "another cell (%zu) %.2f spacings away\n",
              cell, node, fastest * std::sqrt(3.0), wall, other, nearest);
  // Its cell's edges against the rest shape: a crumpled mesh shows as edges far from it.
  const EdgeRange its = edge_range(s.positions[cell], mesh, true), rest = edge_range(mesh.vertices, mesh, false);
  std::printf("  its cell's edges           %.2f to %.2f times their rest length (rest %.2f to %.2f spacings)\n",
              its.least, its.most, rest.least, rest.most);
  // The most compressed edge of any cell, for comparison.
  double least = 1e300;
  std::size_t least_cell = 0;
  for (std::size_t i = 0; i < s.positions.size(); ++i)
    if (const double r = edge_range(s.positions[i], mesh, true).least; r < least) {
      least = r;
      least_cell = i;
    }
  std::printf("  most compressed edge       %.2f times its rest length, cell %zu\n", least, least_cell);
}

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
  const solver::MeshHealth q = solver::mesh_health(s.positions, mesh);
  std::printf("  smallest triangle          %.4f of its rest area; %ld of %ld triangles (%.2f %%) below half, %ld below "
              "%.2f\n",
              q.smallest_area_ratio, q.triangles_below_half, q.triangles, 100.0 * q.triangles_below_half / q.triangles,
              q.triangles_collapsed, solver::DihedralBending::kCollapsedArea);
  std::printf("  folded hinges              %ld of %ld (normals over 120 degrees apart), in %ld of %zu cells\n",
              q.folded_hinges, q.hinges, q.cells_with_folds, s.positions.size());
  print_fastest_node(s, u, mesh);
  // Layers across the gap: cell centres per quarter radius; a centre stays about a
  // half-thickness (a / 2 for a resting disc) away from a wall, so the layering number
  // leaves out the bins within a / 2.
  const solver::GapProfile g = solver::cell_centres_across_gap(s.positions, u.ny, 0.25 * a, 0.5 * a);
  std::printf("  cell centres across the gap (per a / 4 from the lower wall):");
  for (int n : g.counts) std::printf(" %d", n);
  std::printf("\n  layering                   %.2f (sd / mean of the counts away from the walls; about %.2f for "
              "centres at random)\n",
              g.layering, 1.0 / std::sqrt(std::max(1.0, static_cast<double>(s.positions.size()) / g.counts.size())));
}

}  // namespace

void add_overlaps_command(CLI::App& app) {
  auto o = std::make_shared<OverlapsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "overlaps", "How far membranes reach into other cells in a saved state (checkpoint.bin of rbcal simulate)");
  cmd->add_option("checkpoint", o->checkpoint, "A run's checkpoint.bin")->required()->check(CLI::ExistingFile);
  cmd->add_option("--spacing", o->spacing, "Grid spacing of the volume estimate in lattice units (default a / 6)")
      ->check(kPositive);
  cmd->callback([o] { run_overlaps(*o); });
}

}  // namespace rbcal::cli
