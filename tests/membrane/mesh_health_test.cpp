// Mesh health figures: the rest shape is perfect; a squeezed triangle and a folded
// hinge are counted.
#include <gtest/gtest.h>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/mesh_health.hpp"

using namespace rbcal::solver;

TEST(MeshHealth, RestShapeIsPerfect) {
  const TriangleMesh rest = make_icosphere(2);
  const MeshHealth q = mesh_health({rest.vertices, rest.vertices}, rest);
  EXPECT_NEAR(q.smallest_area_ratio, 1.0, 1e-12);
  EXPECT_EQ(q.triangles, 2 * static_cast<long>(rest.triangles.size()));
  EXPECT_EQ(q.hinges, 3 * static_cast<long>(rest.triangles.size()));  // 3/2 hinges per triangle, two cells
  EXPECT_EQ(q.triangles_below_half, 0);
  EXPECT_EQ(q.folded_hinges, 0);
  EXPECT_EQ(q.cells_with_folds, 0);
}

TEST(MeshHealth, CountsASqueezedTriangleAndAFold) {
  const TriangleMesh rest = make_icosphere(2);
  // Lay the wing c of one hinge (a, b, c) / (b, a, d) onto the other wing: the two
  // triangles then lie on top of each other, normals opposite (a fold of 180 degrees).
  const Hinge h = build_hinges(rest).front();
  std::vector<Vec3> folded = rest.vertices;
  folded[h.c] = rest.vertices[h.d] + 0.01 * (rest.vertices[h.a] - rest.vertices[h.d]);
  const MeshHealth q = mesh_health({rest.vertices, folded}, rest);
  EXPECT_GE(q.folded_hinges, 1);
  EXPECT_EQ(q.cells_with_folds, 1);
  // Move vertex 0 to the midpoint of the opposite edge of one of its triangles: that
  // triangle has zero area.
  std::vector<Vec3> squeezed = rest.vertices;
  for (const Triangle& t : rest.triangles)
    if (t[0] == 0) {
      squeezed[0] = 0.5 * (rest.vertices[t[1]] + rest.vertices[t[2]]);
      break;
    }
  const MeshHealth s = mesh_health({squeezed}, rest);
  EXPECT_LT(s.smallest_area_ratio, 1e-12);
  EXPECT_GE(s.triangles_collapsed, 1);
  EXPECT_GE(s.triangles_below_half, 1);
}
