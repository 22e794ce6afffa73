#pragma once
// How healthy a deformed membrane mesh is, against its rest shape: the smallest triangle
// area ratio, triangles squeezed below half or below DihedralBending::kCollapsedArea of
// their rest area, and folded hinges (neighbouring triangles whose normals are more than
// 120 degrees apart: a crease the mesh cannot resolve). Dense and high-Ca runs with an
// area-compressible membrane (Skalak C 10) show all of these (docs/library.md).
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct MeshHealth {
  double smallest_area_ratio = 1e300;
  long triangles = 0;
  long triangles_below_half = 0;
  long triangles_collapsed = 0;  // below DihedralBending::kCollapsedArea
  long hinges = 0;
  long folded_hinges = 0;
  long cells_with_folds = 0;
};

// Over all cells (each a list of positions of the rest mesh's vertices).
MeshHealth mesh_health(const std::vector<std::vector<Vec3>>& cells, const TriangleMesh& rest);

}  // namespace rbcal::solver
