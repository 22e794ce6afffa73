// Stresslet (Pozrikidis 1995) and shape measures on known configurations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/coupling/stresslet.hpp"
#include "solver/membrane/cell_shapes.hpp"

using namespace rbcal::solver;

TEST(Stresslet, VanishesForARigidlyRotatingUndeformedSphere) {
  const TriangleMesh s = make_sphere(1280, 3.0);
  const Vec3 omega(0.2, -0.5, 0.9);
  std::vector<Vec3> v, f(s.vertices.size(), Vec3::Zero());
  for (const Vec3& r : s.vertices) v.push_back(omega.cross(r));
  const Mat3 stresslet = cell_stresslet(s.vertices, f, v, s.triangles, 1.0, 5.0);
  EXPECT_LT(stresslet.norm(), 1e-12);
  // Control: a straining motion v = E r gives a non-zero viscosity-contrast term.
  Mat3 e = Mat3::Zero();
  e(2, 1) = e(1, 2) = 0.5;
  std::vector<Vec3> strain;
  for (const Vec3& r : s.vertices) strain.push_back(e * r);
  EXPECT_GT(cell_stresslet(s.vertices, f, strain, s.triangles, 1.0, 5.0).norm(), 1.0);
}

TEST(Stresslet, LoadTermIsTheFirstMomentOfTheLoad) {
  // Two opposite point loads pulling outward at +-d along z: q = +-F ez, membrane force -q.
  std::vector<Vec3> x = {Vec3(0, 0, -2), Vec3(0, 0, 2), Vec3(1, 0, 0)};
  std::vector<Vec3> f = {Vec3(0, 0, 3), Vec3(0, 0, -3), Vec3::Zero()};  // membrane forces (inward)
  std::vector<Vec3> v(3, Vec3::Zero());
  const Mat3 s = cell_stresslet(x, f, v, {}, 1.0, 1.0);
  // Centroid at (1/3, 0, 0): S_zz = sum z q_z = (-2)(-3) + 2(3) = 12.
  EXPECT_NEAR(s(2, 2), 12.0, 1e-12);
  EXPECT_NEAR(s(2, 1), 0.0, 1e-12);
}

TEST(ShearPlaneShape, EllipsoidDeformationAndInclination) {
  // Ellipsoid with semi-axes (1.0, 0.8, 1.25) in (x, y, z), tilted by 30 deg in the y-z plane.
  const TriangleMesh s = make_sphere(5120, 1.0);
  const double t = std::numbers::pi / 6.0;
  std::vector<Vec3> x;
  for (const Vec3& p : s.vertices) {
    const Vec3 q(p.x(), 0.8 * p.y(), 1.25 * p.z());
    x.emplace_back(q.x(), std::cos(t) * q.y() + std::sin(t) * q.z(), -std::sin(t) * q.y() + std::cos(t) * q.z());
  }
  const ShearPlaneShape shape = shear_plane_shape(x, s.triangles);
  EXPECT_NEAR(shape.taylor_deformation, (1.25 - 0.8) / (1.25 + 0.8), 2e-3);
  EXPECT_NEAR(shape.inclination, t, 1e-3);  // major axis from +z towards +y
}

TEST(ShortAxis, IsTheSymmetryAxisOfADiscocyteInAnyOrientation) {
  // The biconcave mesh has its symmetry axis along z. Turned by 40 deg about y it points to
  // (sin 40, 0, cos 40); its x component is what the series reports as axis_vorticity.
  const TriangleMesh rbc = make_biconcave_cell(1280, 1.0, BiconcaveProfile::EvansFung);
  EXPECT_NEAR(std::abs(short_axis(rbc.vertices, rbc.triangles).z()), 1.0, 1e-9);
  const double t = 40.0 * std::numbers::pi / 180.0;
  std::vector<Vec3> x;
  for (const Vec3& p : rbc.vertices)
    x.emplace_back(std::cos(t) * p.x() + std::sin(t) * p.z(), p.y(), -std::sin(t) * p.x() + std::cos(t) * p.z());
  const Vec3 n = short_axis(x, rbc.triangles);
  EXPECT_NEAR(std::abs(n.x()), std::sin(t), 1e-9);
  EXPECT_NEAR(std::abs(n.z()), std::cos(t), 1e-9);
  EXPECT_NEAR(n.y(), 0.0, 1e-9);
}
