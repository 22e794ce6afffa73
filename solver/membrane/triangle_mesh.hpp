#pragma once
// A closed triangulated surface: vertex positions and triangles whose vertices run
// counter-clockwise seen from outside (so (x1 - x0) x (x2 - x0) points outwards).
// Lengths in whatever unit the caller uses (metres, cell radii or lattice units).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace rbcal::solver {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

// An interior edge a-b with its two triangles (a, b, c) and (b, a, d): the hinge that
// the bending energy acts on.
struct Hinge {
  int a, b, c, d;
};

// Enclosed volume (divergence theorem), positive for outward orientation.
double enclosed_volume(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles);
double surface_area(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles);
// (x1 - x0) x (x2 - x0) of triangle t: its outward normal times twice its area.
inline Vec3 twice_area_vector(const std::vector<Vec3>& x, const Triangle& t) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
}
// The wings of hinge a-b: normals times twice the areas of triangles (a, b, c) and (b, a, d).
inline std::array<Vec3, 2> wing_normals(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return {(b - a).cross(c - a), (a - b).cross(d - b)};
}
inline std::array<Vec3, 2> wing_normals(const std::vector<Vec3>& x, const Hinge& h) {
  return wing_normals(x[h.a], x[h.b], x[h.c], x[h.d]);
}
Vec3 vertex_centroid(const std::vector<Vec3>& x);
// Winding number of the closed surface about p: 1 inside, 0 outside (up to round-off),
// from the solid angles of the triangles (Van Oosterom and Strackee, IEEE Trans. Biomed.
// Eng. 30 (1983) 125). Robust where ray casting is not: no special cases on edges.
double winding_number(const Vec3& p, const std::vector<Vec3>& x, const std::vector<Triangle>& triangles);

// Axis-aligned bounding box of a point set (lo = hi = 0 for an empty set).
struct Bounds {
  Vec3 lo, hi;
  bool contains(const Vec3& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
};
Bounds bounding_box(const std::vector<Vec3>& x);

// Every edge's hinge; throws std::invalid_argument unless the mesh is a closed, consistently
// oriented two-manifold (each edge shared by exactly two triangles in opposite directions).
std::vector<Hinge> build_hinges(const TriangleMesh& mesh);

}  // namespace rbcal::solver
