#pragma once
// Fraction alpha of each lattice node's cell [i-1/2, i+1/2] x ... occupied by cell
// interiors, from the membrane meshes, for the viscosity field
// eta = (1 + (lambda - 1) alpha) eta0.
//
// Scan lines: each lattice column (i, j) is sampled by S x S lines parallel to z at
// x = i + (s + 1/2)/S - 1/2, y = j + (t + 1/2)/S - 1/2 (S = 2). Each line is intersected
// with every triangle of a closed mesh (projected point-in-triangle test, z from the
// barycentric weights); the crossings, ordered along z and signed by the triangle's
// orientation, bound the inside intervals (winding number). A node takes the length of
// [k - 1/2, k + 1/2] that lies inside, averaged over its S^2 lines: a volume-of-fluid
// fraction whose sum is a midpoint-rule volume integral on a grid of spacing dx / S.
// Lines are offset by a fixed irrational fraction of a spacing so that no line passes
// exactly through a mesh vertex or edge. Periodic in x and z: meshes must be given in
// unwrapped coordinates (no jump across the box).
#include <utility>
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

class InsideFraction {
 public:
  InsideFraction(int nx, int ny, int nz, int lines_per_spacing = 2);

  // Recomputes alpha for all meshes (node positions in lattice units).
  void update(const std::vector<const std::vector<Vec3>*>& positions, const std::vector<Triangle>& triangles);

  const std::vector<double>& alpha() const { return alpha_; }
  // Nodes whose alpha may have changed in the last update (for incremental viscosity
  // updates): the footprint before it and the footprint after it, as lists by chunk of
  // lattice columns, each node once per footprint (a node can be in both), so that the
  // lists can be walked in parallel.
  using Footprint = std::vector<std::vector<std::size_t>>;
  const Footprint& previous_footprint() const { return previous_; }
  const Footprint& footprint() const { return inside_; }

 private:
  // Signed z-crossings of one mesh on the scan lines of its bounding box, sorted by
  // line, then z.
  struct Hit {  // 16 bytes: the buffers are written once per build, from a cold cache
    double z;
    int line;  // (p - pbase) * qcount + (q - qbase)
    int sign;  // +1 entering, -1 leaving
  };
  struct Crossings {
    int pbase = 0, qbase = 0, qcount = 0;  // first line indices, lines along y
    bool oversized = false;  // the mesh spans more than the lattice in x or y: no hits
    std::vector<Hit> hits;
    std::vector<int> line_start;  // the counting sort's, then the end of each line's hits
  };
  void crossings_of(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, Crossings& out) const;
  // Adds the inside intervals of c's scan lines in lattice columns [column_lo, column_hi)
  // (wrapped x) to alpha, listing newly reached nodes in `reached`.
  void apply(const Crossings& c, int column_lo, int column_hi, std::vector<std::size_t>& reached);

  int nx_, ny_, nz_;
  int sub_;  // scan lines per lattice spacing in x and in y
  std::vector<double> alpha_;
  Footprint inside_;  // nodes with alpha > 0, each once, by column chunk (reused)
  std::vector<unsigned char> marked_;  // 1 for the nodes in inside_
  Footprint previous_;  // inside_ before the last update
  std::vector<Crossings> crossings_;  // per mesh, reused between updates
};

}  // namespace rbcal::solver
