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
#include "solver/coupling/node_order.hpp"
#include "solver/coupling/peskin_kernel.hpp"
#include "solver/fluid/fluid_lattice.hpp"
#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

// Adds each node's force (lattice units, force per node) to the lattice force field.
// (order: from sort_nodes and gather_nodes, or order_nodes; it carries the kernel.)
void spread_forces(const NodeOrder& order, FluidLattice& fluid);
void spread_forces(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions,
                   const std::vector<std::vector<Vec3>>& forces, FluidLattice& fluid);
// The same for one set of nodes.
void spread_forces(KernelKind kernel, const std::vector<Vec3>& positions, const std::vector<Vec3>& forces,
                   FluidLattice& fluid);

// Fluid velocity interpolated at a point; u_node(i, j, k) supplies nodal velocities.
template <class VelocityAt>
Vec3 interpolate(const KernelStencil& s, VelocityAt&& u_node) {
  // Summed in locals: summed in the returned vector, which the caller's memory holds and a
  // store to a double may alias, each of the 64 terms was stored and read back.
  double sum[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < s.count; ++a)
    for (int b = 0; b < s.count; ++b) {
      const double wab = s.wx[a] * s.wy[b];
      if (wab == 0.0) continue;
      for (int c = 0; c < s.count; ++c) {
        const double w = wab * s.wz[c];
        const Vec3 u = u_node(s.x[a], s.y[b], s.z[c]);
        for (int d = 0; d < 3; ++d) sum[d] += w * u[d];
      }
    }
  return Vec3(sum[0], sum[1], sum[2]);
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
