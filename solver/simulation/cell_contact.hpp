#pragma once
// A short-range repulsion between the membranes of different cells. The immersed boundary
// does not resolve a gap narrower than its kernel, so nothing resists two membranes that
// come closer than a lattice spacing or two, and in dense suspensions they creep into each
// other (docs/library.md). Nodes of different cells closer than `range` push each other
// apart with |F| = strength (range / r - 1) (r floored at range / 5); the pair forces are
// added to the membrane forces, so they are spread into the fluid and enter the stresslet
// like any other membrane force (equal and opposite: no net force on the fluid).
#include <cstdint>
#include <utility>
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

// Nodes binned into cubes of side >= the range: a node's partners lie in its own bin and
// the 26 around it (periodic in x and z). Kept between calls, so that its buffers are
// reused (fresh multi-megabyte vectors on every step cost page faults).
struct NodeBins {
  int bx = 1, by = 1, bz = 1;
  double side_x = 1.0, side_y = 1.0, side_z = 1.0, y_low = 0.0;
  std::vector<std::uint32_t> start;                              // bin k: entries [start[k], start[k + 1])
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;  // (cell, node)
  // Entry positions wrapped into the box in x and z, in single precision with the cell
  // (16 bytes: the search streams through them).
  struct Packed {
    float x, y, z;
    std::uint32_t cell;
  };
  std::vector<Packed> packed;
  std::vector<std::uint32_t> bin_of, fill;  // scratch of the binning
  std::vector<Vec3> shift;                  // scratch of separate_close_nodes
  int bin_x(double v) const;
  int bin_y(double v) const;
  int bin_z(double v) const;
  int index(int ix, int iy, int iz) const { return (ix * by + iy) * bz + iz; }
};

struct ContactCount {
  long node_pairs = 0;  // ordered pairs (node, node of another cell) within range
};

// x: node positions per cell in lattice units, periodic in x and z with periods period_x,
// period_z (positions may lie outside [0, period)); range in lattice spacings; strength in
// lattice force units. Adds each node's contact force to f (same layout as x).
ContactCount add_contact_forces(const std::vector<std::vector<Vec3>>& x, double range, double strength,
                                double period_x, double period_z, std::vector<std::vector<Vec3>>& f, NodeBins& bins);

// The other remedy (as boundary-integral codes do): no force, but every node closer than
// `gap` to a node of another cell is moved away from the nearest such node by half the
// shortfall, after the nodes have moved with the flow. Not seen by the fluid; the
// membrane's elastic response to the displacement is.
ContactCount separate_close_nodes(std::vector<std::vector<Vec3>>& x, double gap, double period_x,
                                  double period_z, NodeBins& bins);

}  // namespace rbcal::solver
