#pragma once
// Immersed-boundary coupling between Lagrangian membrane nodes and the lattice
// (Peskin, Acta Numerica 11 (2002) 479). Positions are in lattice units with node (i, j, k)
// at (i, j, k); x and z wrap periodically; the walls bound y at -1/2 and ny - 1/2, and
// kernel weights that would fall on missing nodes beyond a wall are dropped and the rest
// renormalised along y, so that spreading still conserves force and interpolation still
// reproduces constants near a wall.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "solver/coupling/kernel_stencil.hpp"
#include "solver/coupling/peskin_kernel.hpp"
#include "solver/coupling/stable_key_sort.hpp"
#include "solver/fluid/fluid_lattice.hpp"
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
  // The kernel and lattice the order was built for.
  KernelKind kernel = KernelKind::Peskin4;
  int nx = 0, ny = 0, nz = 0;
  // The kernel stencil at position[g], for the spreading and again for the interpolation that
  // follows the fluid step (the nodes have not moved). Computed where it is used: stored,
  // the stencils (128 bytes a node) were written once and read twice per membrane update,
  // and that traffic cost more than computing them (three square roots) each time.
  KernelStencil stencil_of(std::size_t g) const { return make_stencil(kernel, position[g], nx, ny, nz); }
  std::vector<std::size_t> slab_start;                         // slab s is [slab_start[s], slab_start[s + 1])
  // Scratch: each node's key and (cell, node) in mesh order, the sort, the first node of
  // each cell in mesh order (the pairs and the firsts kept while the cells' sizes stay).
  std::vector<std::uint32_t> key;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> mesh_order;
  StableKeySort sort;
  std::vector<std::size_t> cell_first;
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

// Adds each node's force (lattice units, force per node) to the lattice force field.
// (order: from order_nodes, which carries the kernel.)
void spread_forces(const NodeOrder& order, FluidLattice& fluid);
void spread_forces(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions,
                   const std::vector<std::vector<Vec3>>& forces, FluidLattice& fluid);
// The same for one set of nodes.
void spread_forces(KernelKind kernel, const std::vector<Vec3>& positions, const std::vector<Vec3>& forces,
                   FluidLattice& fluid);

// Fluid velocity interpolated at a point; u_node(i, j, k) supplies nodal velocities.
template <class VelocityAt>
Vec3 interpolate(const KernelStencil& s, VelocityAt&& u_node) {
  Vec3 u = Vec3::Zero();
  for (int a = 0; a < s.count; ++a)
    for (int b = 0; b < s.count; ++b) {
      const double wab = s.wx[a] * s.wy[b];
      if (wab == 0.0) continue;
      for (int c = 0; c < s.count; ++c) u += (wab * s.wz[c]) * u_node(s.x[a], s.y[b], s.z[c]);
    }
  return u;
}

// Velocity at a point from a nodal velocity field in structure-of-arrays form
// (u[d][FluidLattice::index(i, j, k)], lattice dimensions ny, nz). The 4-point stencil
// away from the periodic z seam reads its 16 rows as 4-wide vectors (z is contiguous).
Vec3 interpolate_field(const KernelStencil& s, const double* const u[3], int ny, int nz);

// The same at the sorted nodes [begin, end) of order, into out[0, end - begin): with the
// 4-point kernel, their stencils are computed several at a time.
void interpolate_sorted(const NodeOrder& order, std::size_t begin, std::size_t end, const double* const u[3],
                        Vec3* out);

// Velocity of the lattice fluid at a point (from the populations of the last step).
Vec3 interpolate_velocity(KernelKind kernel, const FluidLattice& fluid, const Vec3& position);

}  // namespace rbcal::solver
