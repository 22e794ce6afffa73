#include "solver/membrane/cell_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace rbcal::solver {

namespace {

constexpr double C0 = 0.207161, C2 = 2.002558, C4 = -1.122762;

// Half-thickness factor sqrt(1 - rho^2) (C0 + C2 rho^2 + C4 rho^4) of the published profile.
double evans_fung_factor(double rho2) {
  return std::sqrt(std::max(0.0, 1.0 - rho2)) * (C0 + C2 * rho2 + C4 * rho2 * rho2);
}

double published_max_thickness() {
  // Golden-section search of the unimodal factor on rho in [0, 1]; thickness = a * factor.
  double lo = 0.0, hi = 1.0;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (evans_fung_factor(m1 * m1) < evans_fung_factor(m2 * m2)) lo = m1; else hi = m2;
  }
  return evans_fung_factor(0.25 * (lo + hi) * (lo + hi));
}

double flattening(BiconcaveProfile profile) {
  return profile == BiconcaveProfile::SeedThickness ? 0.5 / published_max_thickness() : 1.0;
}

}  // namespace

std::string to_string(BiconcaveProfile profile) {
  return profile == BiconcaveProfile::EvansFung ? "evans-fung" : "seed";
}

BiconcaveProfile biconcave_profile_from_string(const std::string& name) {
  if (name == "evans-fung") return BiconcaveProfile::EvansFung;
  if (name == "seed") return BiconcaveProfile::SeedThickness;
  throw std::invalid_argument("unknown biconcave profile '" + name + "' (expected evans-fung or seed)");
}

double biconcave_max_thickness(BiconcaveProfile profile) {
  return published_max_thickness() * flattening(profile);
}

TriangleMesh make_icosphere(int subdivisions) {
  if (subdivisions < 0 || subdivisions > 7) throw std::invalid_argument("icosphere: subdivisions must be 0..7");
  TriangleMesh mesh;
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  const double raw[12][3] = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                             {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (const auto& v : raw) mesh.vertices.push_back(Vec3(v[0], v[1], v[2]).normalized());
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      mesh.vertices.push_back((mesh.vertices[i] + mesh.vertices[j]).normalized());
      const int id = static_cast<int>(mesh.vertices.size()) - 1;
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
  return mesh;
}

int subdivisions_for(int triangles) {
  int count = 20;
  for (int k = 0; k <= 7; ++k, count *= 4)
    if (count == triangles) return k;
  throw std::invalid_argument("mesh: " + std::to_string(triangles) +
                              " triangles is not 20 * 4^k (use 320, 1280 or 5120)");
}

TriangleMesh make_sphere(int triangles, double radius) {
  TriangleMesh mesh = make_icosphere(subdivisions_for(triangles));
  for (Vec3& v : mesh.vertices) v *= radius;
  return mesh;
}

TriangleMesh make_biconcave_cell(int triangles, double radius, BiconcaveProfile profile) {
  TriangleMesh mesh = make_icosphere(subdivisions_for(triangles));
  const double s = flattening(profile);
  for (Vec3& v : mesh.vertices) {
    const double rho2 = v.x() * v.x() + v.y() * v.y();
    // sqrt(1 - rho^2) = |z| on the unit sphere, so the sign of z carries over smoothly.
    v = Vec3(radius * v.x(), radius * v.y(), 0.5 * radius * s * v.z() * (C0 + C2 * rho2 + C4 * rho2 * rho2));
  }
  return mesh;
}

TriangleMesh make_spheroid(int triangles, double radius, double aspect_ratio) {
  if (!(aspect_ratio > 0.0)) throw std::invalid_argument("spheroid: aspect ratio must be positive");
  TriangleMesh mesh = make_icosphere(subdivisions_for(triangles));
  for (Vec3& v : mesh.vertices) v = Vec3(radius * v.x(), radius * v.y(), radius * aspect_ratio * v.z());
  return mesh;
}

MeshQuality mesh_quality(const TriangleMesh& mesh) {
  MeshQuality q;
  q.min_edge = std::numeric_limits<double>::max();
  q.min_angle_deg = 180.0;
  double edge_sum = 0.0;
  std::size_t edges = 0;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[t[k]];
      const Vec3 u = mesh.vertices[t[(k + 1) % 3]] - p, w = mesh.vertices[t[(k + 2) % 3]] - p;
      const double len = u.norm();
      q.min_edge = std::min(q.min_edge, len);
      q.max_edge = std::max(q.max_edge, len);
      edge_sum += len;
      ++edges;
      const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / std::numbers::pi;
      q.min_angle_deg = std::min(q.min_angle_deg, angle);
      q.max_angle_deg = std::max(q.max_angle_deg, angle);
    }
  }
  q.mean_edge = edge_sum / static_cast<double>(edges);  // each edge counted twice, once per side
  q.edge_spread = q.max_edge / q.min_edge;
  return q;
}

}  // namespace rbcal::solver
