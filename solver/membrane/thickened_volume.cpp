#include "solver/membrane/thickened_volume.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rbcal::solver {

SteinerTerms steiner_terms(const TriangleMesh& mesh) {
  SteinerTerms s;
  s.area = surface_area(mesh.vertices, mesh.triangles);
  s.volume = enclosed_volume(mesh.vertices, mesh.triangles);
  if (!(s.volume > 0.0))
    throw std::invalid_argument("steiner_terms: the mesh encloses no positive volume (triangles must face outwards)");
  const std::vector<Vec3>& x = mesh.vertices;
  for (const Hinge& h : build_hinges(mesh)) {
    const auto [n1, n2] = wing_normals(x, h);
    const Vec3 edge = x[h.b] - x[h.a];
    // Exterior angle between the outward normals, positive where the edge is convex (the
    // second wing bends away from the first's outward normal).
    const double angle = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
    const double sign = (x[h.d] - x[h.a]).dot(n1) <= 0.0 ? 1.0 : -1.0;
    s.mean_curvature_integral += 0.5 * edge.norm() * sign * angle;
  }
  return s;
}

double thickened_volume_ratio(const SteinerTerms& s, double delta) {
  const double added = s.area * delta + s.mean_curvature_integral * delta * delta +
                       4.0 / 3.0 * std::numbers::pi * delta * delta * delta;
  return 1.0 + added / s.volume;
}

}  // namespace rbcal::solver
