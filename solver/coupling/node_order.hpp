#pragma once
// Membrane nodes in the order of the lattice nodes their kernel stencils start at, with the
// x-slabs in which the spreading runs in parallel (immersed_boundary.hpp).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "solver/coupling/kernel_stencil.hpp"
#include "solver/coupling/peskin_kernel.hpp"
#include "solver/coupling/stable_key_sort.hpp"
#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

inline KernelStencil make_stencil(KernelKind kernel, const Vec3& p, int nx, int ny, int nz) {
  return make_stencil(kernel, p.x(), p.y(), p.z(), nx, ny, nz);
}

// Membrane nodes sorted by the lattice node where their stencil starts, with copies of
// their positions and forces in that order: neighbours in the list touch the same
// lattice nodes, and their data lie side by side, which keeps both in cache (reading
// positions and forces in mesh order through the sorted index cost as much as the
// spreading itself). The x-slabs that parallel spreading colours are contiguous ranges.
struct NodeOrder {
  // An order may be kept while every node stays within this many lattice spacings of
  // where it stood when it was sorted: each stencil then starts at most one column away
  // from its slab, which the slab schedule allows for (sorting is most of the ordering's
  // cost).
  static constexpr double max_drift = 1.0;
  static constexpr int drift_columns = 1;
  // Slabs of slab_width columns in x, spread in slab_phases parallel phases (slab s in
  // phase s mod slab_phases): slabs slab_phases apart never write the same lattice node,
  // with the widest support and a drift of drift_columns either way. Three phases of
  // 4-column slabs rather than two of 5: on the bench case's 48 columns each phase then has
  // an even number of slabs for two threads (two phases of five slabs left one thread idle
  // for a fifth of the spreading).
  static constexpr int slab_width = 4;
  static constexpr int slab_phases = 3;
  // The slabs of a lattice nx wide (the last one may be narrower).
  static constexpr int slab_count(int nx) { return (nx + slab_width - 1) / slab_width; }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> nodes;  // (cell, node)
  std::vector<Vec3> position, force;                           // of nodes[g]
  // The velocity interpolated at position[g]: written in this order, read back cell by cell
  // through sorted_place (writing it straight into the meshes, scattered, made the
  // interpolation and node update 7 % dearer on the bench case).
  std::vector<Vec3> velocity;
  // The kernel and lattice the order was built for.
  KernelKind kernel = KernelKind::Peskin4;
  int nx = 0, ny = 0, nz = 0;
  // The kernel stencil at position[g], for the spreading and again for the interpolation that
  // follows the fluid step (the nodes have not moved): for the 2- and 3-point kernels, and
  // for 4-point stencils on lattices narrower than a support or of blown-up nodes (the others,
  // walls and seams included, are computed eight at a time where they are used). Computed, not stored: stored, the stencils (128 bytes a
  // node) were written once and read twice per membrane update, and that traffic cost more
  // than computing them (three square roots) each time.
  KernelStencil stencil_of(std::size_t g) const { return make_stencil(kernel, position[g], nx, ny, nz); }
  std::vector<std::size_t> slab_start;                         // slab s is [slab_start[s], slab_start[s + 1])
  // Scratch: each node's key and (cell, node) in mesh order, the sort, the first node of
  // each cell in mesh order (the pairs and the firsts kept while the cells' sizes stay).
  std::vector<std::uint32_t> key;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> mesh_order;
  StableKeySort sort;
  std::vector<std::size_t> cell_first;
  // The place g in the sorted order of node n of cell c, at cell_first[c] + n.
  std::vector<std::uint32_t> sorted_place;
};
// How spread_forces visits the x-slabs of a lattice nx wide: NodeOrder::slab_phases parallel
// phases, in each of which no two slabs write a common lattice column (periodic wrap
// included, for the widest support and stencils up to NodeOrder::drift_columns from their
// slab), then, serially, the slabs that would meet one of their own phase across the
// periodic wrap.
struct SlabSchedule {
  std::vector<int> phase[NodeOrder::slab_phases];
  std::vector<int> tail;
};
SlabSchedule slab_schedule(int nx);

// Sorts the nodes by where their stencils start at these positions, for the kernel and
// lattice the stencils are computed for.
void sort_nodes(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions, int nx, int ny, int nz,
                NodeOrder& order);
// Copies the nodes' positions and forces (the shape of the sorted positions) into the
// order's. The positions may lie up to NodeOrder::max_drift from those sorted.
void gather_nodes(const std::vector<std::vector<Vec3>>& positions, const std::vector<std::vector<Vec3>>& forces,
                  NodeOrder& order);
// Both, from the same positions.
void order_nodes(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions,
                 const std::vector<std::vector<Vec3>>& forces, int nx, int ny, int nz, NodeOrder& order);

}  // namespace rbcal::solver
