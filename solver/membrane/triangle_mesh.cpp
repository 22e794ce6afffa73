#include "solver/membrane/triangle_mesh.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace rbcal::solver {

double enclosed_volume(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles) {
  double six_v = 0.0;
  for (const Triangle& t : triangles) six_v += x[t[0]].dot(x[t[1]].cross(x[t[2]]));
  return six_v / 6.0;
}

double winding_number(const Vec3& p, const std::vector<Vec3>& x, const std::vector<Triangle>& triangles) {
  double omega = 0.0;
  for (const Triangle& t : triangles) {
    const Vec3 a = x[t[0]] - p, b = x[t[1]] - p, c = x[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    omega += 2.0 * std::atan2(numerator, denominator);
  }
  return omega / (4.0 * std::numbers::pi);
}

double surface_area(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles) {
  double twice_a = 0.0;
  for (const Triangle& t : triangles) twice_a += twice_area_vector(x, t).norm();
  return 0.5 * twice_a;
}

Vec3 vertex_centroid(const std::vector<Vec3>& x) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

Bounds bounding_box(const std::vector<Vec3>& x) {
  if (x.empty()) return {Vec3::Zero(), Vec3::Zero()};
  Bounds b{x[0], x[0]};
  for (const Vec3& p : x) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

std::vector<Hinge> build_hinges(const TriangleMesh& mesh) {
  // Directed edge (from, to) -> the vertex opposite it in its triangle.
  std::map<std::pair<int, int>, int> opposite_of;
  const int nv = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int from = tri[k], to = tri[(k + 1) % 3], other = tri[(k + 2) % 3];
      if (from < 0 || from >= nv || to < 0 || to >= nv || other < 0 || other >= nv)
        throw std::invalid_argument("mesh: triangle " + std::to_string(t) + " names a missing vertex");
      if (!opposite_of.emplace(std::make_pair(from, to), other).second)
        throw std::invalid_argument("mesh: directed edge " + std::to_string(from) + "-" + std::to_string(to) +
                                    " appears twice (inconsistent orientation or non-manifold)");
    }
  }
  std::vector<Hinge> hinges;
  for (const auto& [edge, c] : opposite_of) {
    const auto [a, b] = edge;
    if (a > b) continue;  // each undirected edge once
    auto twin = opposite_of.find({b, a});
    if (twin == opposite_of.end())
      throw std::invalid_argument("mesh: edge " + std::to_string(a) + "-" + std::to_string(b) +
                                  " has one triangle only (surface not closed)");
    hinges.push_back({a, b, c, twin->second});
  }
  for (const auto& [edge, c] : opposite_of)
    if (edge.first > edge.second && !opposite_of.count({edge.second, edge.first}))
      throw std::invalid_argument("mesh: edge " + std::to_string(edge.first) + "-" +
                                  std::to_string(edge.second) + " has one triangle only (surface not closed)");
  return hinges;
}

}  // namespace rbcal::solver
