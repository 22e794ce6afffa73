// Inside fraction from the membrane mesh: its sum is the enclosed volume (a sphere of
// radius 8 lattice spacings within 1 %, as the issue asks; the mesh's own volume within
// 0.5 %), it is 1 deep inside and 0 outside, it follows a mesh across the periodic
// boundary, and touching cells give the same alpha bit for bit on any thread count (the
// crossings are applied by column chunks in parallel).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include <omp.h>

#include "solver/coupling/inside_fraction.hpp"
#include "solver/membrane/cell_shapes.hpp"

using namespace rbcal::solver;

namespace {

double alpha_sum(const InsideFraction& f) {
  double s = 0.0;
  for (double a : f.alpha()) s += a;
  return s;
}

}  // namespace

TEST(InsideFraction, SphereOfRadiusEightIntegratesToItsVolume) {
  const TriangleMesh sphere = make_sphere(5120, 8.0);
  for (const Vec3& centre : {Vec3(15.0, 16.0, 17.0), Vec3(15.37, 16.81, 17.22)}) {
    std::vector<Vec3> x = sphere.vertices;
    for (Vec3& v : x) v += centre;
    InsideFraction f(32, 34, 36);
    f.update({&x}, sphere.triangles);
    const double exact = 4.0 / 3.0 * std::numbers::pi * 512.0;
    EXPECT_NEAR(alpha_sum(f) / exact, 1.0, 0.01);
    std::cout << "sum(alpha) / exact sphere volume - 1 = " << alpha_sum(f) / exact - 1.0
              << ", / mesh volume - 1 = " << alpha_sum(f) / enclosed_volume(x, sphere.triangles) - 1.0 << "\n";
    EXPECT_NEAR(alpha_sum(f) / enclosed_volume(x, sphere.triangles), 1.0, 5e-3);
    EXPECT_EQ(f.alpha()[(15u * 34 + 16) * 36 + 17], 1.0);  // centre node
    EXPECT_EQ(f.alpha()[(2u * 34 + 2) * 36 + 2], 0.0);     // far away
  }
}

TEST(InsideFraction, WrapsAcrossThePeriodicBoundaryAndResets) {
  const TriangleMesh sphere = make_sphere(1280, 5.0);
  std::vector<Vec3> x = sphere.vertices;
  for (Vec3& v : x) v += Vec3(1.2, 10.0, 30.6);  // straddles x = 0 and z = 32
  InsideFraction f(24, 20, 32);
  f.update({&x}, sphere.triangles);
  const double inside = alpha_sum(f);
  EXPECT_NEAR(inside / enclosed_volume(x, sphere.triangles), 1.0, 3e-3);
  for (Vec3& v : x) v += Vec3(5.0, 0.0, 0.0);  // move it: the old footprint must vanish
  f.update({&x}, sphere.triangles);
  EXPECT_NEAR(alpha_sum(f), inside, 3e-3 * inside);
}

TEST(InsideFraction, RefusesACellWiderThanTheLattice) {
  // A blown-up membrane: without the guard its scan-line grid grows with its bounding box.
  const TriangleMesh sphere = make_sphere(320, 5.0);
  std::vector<Vec3> x = sphere.vertices;
  for (Vec3& v : x) v = 4.0 * v + Vec3(12.0, 10.0, 16.0);  // diameter 40 > nx = 24
  InsideFraction f(24, 20, 32);
  EXPECT_THROW(f.update({&x}, sphere.triangles), std::runtime_error);
  x[0].x() = std::nan("");
  EXPECT_THROW(f.update({&x}, sphere.triangles), std::runtime_error);
}

TEST(InsideFraction, TouchingCellsGiveTheSameAlphaOnAnyThreadCount) {
  // Twelve overlapping spheres across the periodic x boundary: nodes shared by several
  // cells and by chunks of columns.
  const TriangleMesh sphere = make_sphere(1280, 4.0);
  std::vector<std::vector<Vec3>> cells;
  for (int i = 0; i < 12; ++i) {
    std::vector<Vec3> x = sphere.vertices;
    for (Vec3& v : x) v += Vec3(-3.0 + 2.7 * i, 8.0 + 0.9 * (i % 3), 10.0 + 1.3 * (i % 4));
    cells.push_back(x);
  }
  std::vector<const std::vector<Vec3>*> meshes;
  for (const auto& x : cells) meshes.push_back(&x);
  auto alpha_with = [&](int threads) {
    omp_set_num_threads(threads);
    InsideFraction f(30, 18, 24);
    f.update(meshes, sphere.triangles);
    f.update(meshes, sphere.triangles);  // and again over its own footprint
    return f.alpha();
  };
  const int threads = omp_get_max_threads();
  const std::vector<double> one = alpha_with(1), two = alpha_with(2), three = alpha_with(3);
  omp_set_num_threads(threads);
  double total = 0.0;
  for (std::size_t n = 0; n < one.size(); ++n) {
    ASSERT_EQ(one[n], two[n]) << "node " << n;
    ASSERT_EQ(one[n], three[n]) << "node " << n;
    total += one[n];
  }
  // Overlaps are clamped at 1, so the sum lies below the twelve volumes but above one.
  const double volume = enclosed_volume(cells[0], sphere.triangles);
  EXPECT_GT(total, 2.0 * volume);
  EXPECT_LT(total, 12.0 * volume);
}
