// The dihedral bending force of a hinge whose wing triangle collapses stays bounded
// (held at kCollapsedArea of the wing's rest area), keeps zero total force and torque,
// and is the exact energy gradient while the wing is above that area.
#include <gtest/gtest.h>

#include "solver/membrane/dihedral_bending.hpp"

using namespace rbcal::solver;

namespace {

// A tetrahedron (the smallest closed mesh), outward oriented; triangle (a, b, c) is the
// one that collapses.
TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.8, 0.0), Vec3(0.5, 0.3, -0.7)};
  m.triangles = {Triangle{0, 1, 2}, Triangle{1, 0, 3}, Triangle{2, 1, 3}, Triangle{0, 2, 3}};
  return m;
}

// c moved onto the edge a-b (and a little below the plane): (a, b, c) keeps
// fraction * sqrt(2) of its rest area.
std::vector<Vec3> squeezed(double fraction) {
  std::vector<Vec3> x = tetrahedron().vertices;
  x[2] = Vec3(0.5, 0.8 * fraction, -0.8 * fraction);
  return x;
}

// Largest force the held gradients allow: every hinge gives each node at most three
// times k_d |e| / (kCollapsedArea |n_rest|) of its smaller wing.
double held_bound(const TriangleMesh& m, double kd) {
  double bound = 0.0;
  for (const Hinge& h : build_hinges(m)) {
    const auto& v = m.vertices;
    const double e = (v[h.b] - v[h.a]).norm();
    const double n1 = (v[h.b] - v[h.a]).cross(v[h.c] - v[h.a]).norm();
    const double n2 = (v[h.a] - v[h.b]).cross(v[h.d] - v[h.b]).norm();
    bound += 3.0 * kd * e / (DihedralBending::kCollapsedArea * std::min(n1, n2));
  }
  return bound;
}

std::vector<Vec3> forces_of(const DihedralBending& b, const std::vector<Vec3>& x) {
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  b.add_forces(x, f);
  return f;
}

}  // namespace

TEST(CollapsedWing, ForceStaysBoundedAndBalanced) {
  const TriangleMesh ref = tetrahedron();
  const double kc = 0.3;
  const DihedralBending bending(ref, kc, SpontaneousShape::Reference);
  const double bound = held_bound(ref, DihedralBending::hinge_constant(kc, BendingConversion::Sphere));
  for (double fraction : {1e-3, 1e-5, 1e-8}) {
    const std::vector<Vec3> x = squeezed(fraction);
    const std::vector<Vec3> f = forces_of(bending, x);
    Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
    double largest = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      total += f[i];
      torque += x[i].cross(f[i]);
      largest = std::max(largest, f[i].norm());
    }
    SCOPED_TRACE(fraction);
    EXPECT_LE(largest, bound);
    EXPECT_LT(total.norm(), 1e-9 * largest);
    EXPECT_LT(torque.norm(), 1e-9 * largest);
  }
}

TEST(CollapsedWing, ExactGradientAboveTheHeldArea) {
  // At 5 % of the rest area (above kCollapsedArea) the force is -dE/dx, by central
  // differences.
  const DihedralBending bending(tetrahedron(), 0.3, SpontaneousShape::Reference);
  std::vector<Vec3> x = squeezed(0.05 / std::sqrt(2.0));
  const std::vector<Vec3> f = forces_of(bending, x);
  const double h = 1e-7;
  for (int node = 0; node < 4; ++node)
    for (int d = 0; d < 3; ++d) {
      std::vector<Vec3> plus = x, minus = x;
      plus[node][d] += h;
      minus[node][d] -= h;
      const double grad = (bending.energy(plus) - bending.energy(minus)) / (2.0 * h);
      EXPECT_NEAR(f[node][d], -grad, 1e-6 * (1.0 + std::abs(grad))) << "node " << node << " axis " << d;
    }
}
