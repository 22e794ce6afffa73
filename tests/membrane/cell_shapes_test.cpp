// Meshes: icosahedral subdivision counts, closed consistent orientation, convergence of
// the sphere's volume and area, and the biconcave profile's thickness (Evans & Fung,
// Microvasc. Res. 4 (1972) 335: maximum thickness 0.6562 R0 of the published profile).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "solver/membrane/cell_shapes.hpp"

using namespace rbcal::solver;

TEST(Icosphere, CountsAndClosedOrientation) {
  const int triangles[] = {320, 1280, 5120};
  const int vertices[] = {162, 642, 2562};
  for (int k = 0; k < 3; ++k) {
    const TriangleMesh m = make_sphere(triangles[k], 1.0);
    EXPECT_EQ(static_cast<int>(m.triangles.size()), triangles[k]);
    EXPECT_EQ(static_cast<int>(m.vertices.size()), vertices[k]);
    // Euler: a closed genus-0 surface has E = 3T/2 edges, each a hinge.
    EXPECT_EQ(build_hinges(m).size(), 3u * m.triangles.size() / 2);
    EXPECT_GT(enclosed_volume(m.vertices, m.triangles), 0.0);
  }
}

TEST(Icosphere, VolumeAndAreaConvergeToTheSphere) {
  // An inscribed polyhedron under-estimates both by O(h^2): each refinement (h / 2) must
  // cut the error by about four; at 5120 triangles it is about 0.2 %.
  double previous_v = 1.0, previous_a = 1.0;
  for (int n : {320, 1280, 5120}) {
    const TriangleMesh m = make_sphere(n, 2.0);
    const double ev = 1.0 - enclosed_volume(m.vertices, m.triangles) / (4.0 / 3.0 * std::numbers::pi * 8.0);
    const double ea = 1.0 - surface_area(m.vertices, m.triangles) / (4.0 * std::numbers::pi * 4.0);
    EXPECT_GT(ev, 0.0);
    EXPECT_GT(ea, 0.0);
    EXPECT_LT(ev, 0.3 * previous_v);
    EXPECT_LT(ea, 0.3 * previous_a);
    previous_v = ev;
    previous_a = ea;
  }
  EXPECT_LT(previous_v, 2.5e-3);
}

TEST(Icosphere, RejectsCountsThatAreNotSubdivisions) {
  EXPECT_THROW(make_sphere(1000, 1.0), std::invalid_argument);
  EXPECT_THROW(make_biconcave_cell(0, 1.0, BiconcaveProfile::EvansFung), std::invalid_argument);
}

TEST(Biconcave, ThicknessAndRadiusOfBothProfiles) {
  EXPECT_NEAR(biconcave_max_thickness(BiconcaveProfile::EvansFung), 0.6562, 1e-4);
  EXPECT_NEAR(biconcave_max_thickness(BiconcaveProfile::SeedThickness), 0.5, 1e-12);
  for (BiconcaveProfile p : {BiconcaveProfile::EvansFung, BiconcaveProfile::SeedThickness}) {
    const TriangleMesh m = make_biconcave_cell(5120, 4.0, p);
    double zmax = 0.0, rmax = 0.0, dimple = 1e9;
    for (const Vec3& v : m.vertices) {
      zmax = std::max(zmax, v.z());
      rmax = std::max(rmax, std::hypot(v.x(), v.y()));
      if (std::hypot(v.x(), v.y()) < 0.3) dimple = std::min(dimple, std::abs(v.z()));
    }
    EXPECT_NEAR(rmax, 4.0, 1e-12);
    EXPECT_NEAR(2.0 * zmax / 4.0, biconcave_max_thickness(p), 0.01);  // mesh samples the profile
    EXPECT_LT(dimple, 0.5 * zmax);                                     // biconcave: thin centre
    EXPECT_GT(enclosed_volume(m.vertices, m.triangles), 0.0);
    EXPECT_EQ(build_hinges(m).size(), 7680u);
  }
}

TEST(MeshQuality, ReportsEdgesAndAngles) {
  const MeshQuality sphere = mesh_quality(make_sphere(1280, 1.0));
  // Subdivided icosahedra are nearly equilateral: angles 50-70 degrees, edges within 25 %.
  EXPECT_GT(sphere.min_angle_deg, 50.0);
  EXPECT_LT(sphere.max_angle_deg, 75.0);
  EXPECT_LT(sphere.edge_spread, 1.3);
  const MeshQuality cell = mesh_quality(make_biconcave_cell(1280, 1.0, BiconcaveProfile::EvansFung));
  EXPECT_LT(cell.min_angle_deg, sphere.min_angle_deg);  // the mapping distorts the rim
  EXPECT_GT(cell.min_angle_deg, 10.0);
}
