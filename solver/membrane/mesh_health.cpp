#include "solver/membrane/mesh_health.hpp"

#include <algorithm>

#include "solver/membrane/dihedral_bending.hpp"

namespace rbcal::solver {

namespace {

void add_cell(const std::vector<Vec3>& x, const TriangleMesh& rest, const std::vector<Hinge>& hinges, MeshHealth& q) {
  for (const Triangle& t : rest.triangles) {
    const double ratio = twice_area_vector(x, t).norm() / twice_area_vector(rest.vertices, t).norm();
    q.smallest_area_ratio = std::min(q.smallest_area_ratio, ratio);
    q.triangles_below_half += ratio < 0.5;
    q.triangles_collapsed += ratio < DihedralBending::kCollapsedArea;
    ++q.triangles;
  }
  // Hinge (a, b, c) / (b, a, d): cos of the angle between the normals below -1/2.
  long folds = 0;
  for (const Hinge& h : hinges) {
    const auto [n1, n2] = wing_normals(x, h);
    folds += n1.dot(n2) < -0.5 * n1.norm() * n2.norm();
    ++q.hinges;
  }
  q.folded_hinges += folds;
  q.cells_with_folds += folds > 0;
}

}  // namespace

MeshHealth mesh_health(const std::vector<std::vector<Vec3>>& cells, const TriangleMesh& rest) {
  MeshHealth q;
  const std::vector<Hinge> hinges = build_hinges(rest);
  for (const auto& x : cells) add_cell(x, rest, hinges, q);
  return q;
}

}  // namespace rbcal::solver
