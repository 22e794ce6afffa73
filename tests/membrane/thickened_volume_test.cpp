// Steiner's formula for the thickened cell: exact for a cube, the sphere's (1 + delta)^3
// in the limit of a fine mesh, and the biconcave mesh's terms against a quadrature of the
// Evans-Fung surface of revolution it samples.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/thickened_volume.hpp"

using namespace rbcal::solver;

namespace {

// The cube [0, L]^3 as 12 triangles, each oriented outwards.
TriangleMesh cube(double L) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back(L * Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  const Vec3 centre = Vec3::Constant(0.5 * L);
  for (const auto& f : faces) {
    for (const Triangle t : {Triangle{f[0], f[1], f[2]}, Triangle{f[0], f[2], f[3]}}) {
      const Vec3 middle = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
      const bool outwards = twice_area_vector(m.vertices, t).dot(middle - centre) > 0.0;
      m.triangles.push_back(outwards ? t : Triangle{t[0], t[2], t[1]});
    }
  }
  return m;
}

}  // namespace

TEST(ThickenedVolume, IsExactForACube) {
  // Parallel body of a cube of side L: L^3 + 6 L^2 d + 3 pi L d^2 + (4 pi / 3) d^3 (the
  // edges' quarter cylinders and the corners' eighth spheres).
  const double L = 2.0, d = 0.3;
  const SteinerTerms s = steiner_terms(cube(L));
  EXPECT_NEAR(s.area, 6 * L * L, 1e-12);
  EXPECT_NEAR(s.volume, L * L * L, 1e-12);
  EXPECT_NEAR(s.mean_curvature_integral, 3 * std::numbers::pi * L, 1e-12);
  const double exact = L * L * L + 6 * L * L * d + 3 * std::numbers::pi * L * d * d + 4.0 / 3.0 * std::numbers::pi * d * d * d;
  EXPECT_NEAR(thickened_volume_ratio(s, d), exact / (L * L * L), 1e-12);
}

TEST(ThickenedVolume, RefusesAnInwardFacingMesh) {
  TriangleMesh inside_out = cube(1.0);
  for (Triangle& t : inside_out.triangles) std::swap(t[1], t[2]);
  EXPECT_THROW(steiner_terms(inside_out), std::invalid_argument);
}

TEST(ThickenedVolume, ApproachesTheSpheresCubeOfRadii) {
  // A sphere of radius 1 thickened by d is a sphere of radius 1 + d: ratio (1 + d)^3.
  const SteinerTerms s = steiner_terms(make_sphere(5120, 1.0));
  EXPECT_NEAR(s.mean_curvature_integral / (4 * std::numbers::pi), 1.0, 2e-3);
  for (double d : {0.05, 0.1, 0.15})
    EXPECT_NEAR(thickened_volume_ratio(s, d), std::pow(1.0 + d, 3), 3e-3);
}

TEST(ThickenedVolume, BiconcaveMeshMatchesTheProfilesQuadrature) {
  // Area, volume and mean-curvature integral of the Evans-Fung surface of revolution at
  // radius 1 (profile of solver/membrane/cell_shapes.hpp), by the midpoint rule over the
  // meridian r = sin t, z = cos t (C0 + C2 r^2 + C4 r^4) / 2, t in [0, pi/2], both halves.
  const double C0 = 0.207161, C2 = 2.002558, C4 = -1.122762;
  auto r_of = [](double t) { return std::sin(t); };
  auto z_of = [&](double t) {
    const double r2 = std::sin(t) * std::sin(t);
    return 0.5 * std::cos(t) * (C0 + C2 * r2 + C4 * r2 * r2);
  };
  const int n = 20000;
  const double h = 0.5 * std::numbers::pi / n;
  double area = 0, volume = 0, curvature = 0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * h, r = r_of(t), z = z_of(t);
    const double dr = (r_of(t + h / 2) - r_of(t - h / 2)) / h, dz = (z_of(t + h / 2) - z_of(t - h / 2)) / h;
    const double ddr = (r_of(t + h) - 2 * r + r_of(t - h)) / (h * h), ddz = (z_of(t + h) - 2 * z + z_of(t - h)) / (h * h);
    const double ds = std::hypot(dr, dz);
    const double meridian = -(dr * ddz - dz * ddr) / (ds * ds * ds);  // principal curvatures, positive where convex
    const double parallel = -dz / ds / r;
    area += 2 * 2 * std::numbers::pi * r * ds * h;
    volume += 2 * 2 * std::numbers::pi * r * z * dr * h;
    curvature += 2 * 0.5 * (meridian + parallel) * 2 * std::numbers::pi * r * ds * h;
  }
  const SteinerTerms s = steiner_terms(make_biconcave_cell(5120, 1.0, BiconcaveProfile::EvansFung));
  EXPECT_NEAR(s.area / area, 1.0, 5e-3);
  EXPECT_NEAR(s.volume / volume, 1.0, 5e-3);
  EXPECT_NEAR(s.mean_curvature_integral / curvature, 1.0, 1e-2);
}
