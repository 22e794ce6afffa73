// Homogeneous stretch of a flat membrane patch reproduces the closed-form principal
// tensions of the constitutive laws (Barthes-Biesel & Rallison, J. Fluid Mech. 113
// (1981) 251; Skalak et al., Biophys. J. 13 (1973) 245):
//   Skalak:       T1 = G_s / (l1 l2) [l1^2 (l1^2 - 1) + C J^2 (J^2 - 1)],  J = l1 l2
//   neo-Hookean:  T1 = G_s / (l1 l2) [l1^2 - 1 / J^2]
// (T2 by exchanging l1 and l2), and small equibiaxial strain gives the area modulus
// K_s = G_s (1 + 2C). The edge forces of a patch of linear triangles under homogeneous
// strain must sum to minus the tension times the deformed edge length.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/membrane/membrane_elasticity.hpp"

using namespace rbcal::solver;

namespace {

constexpr double kLength = 2.0, kHeight = 1.5;

// n x m squares, each split into two counter-clockwise triangles, in the z = 0 plane.
TriangleMesh flat_patch(int n, int m) {
  TriangleMesh mesh;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(kLength * i / n, kHeight * j / m, 0.0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

double tension(const MembraneMaterial& m, double l1, double l2) {
  const double j2 = l1 * l1 * l2 * l2;
  if (m.law == MembraneLaw::Skalak)
    return m.shear_modulus / (l1 * l2) * (l1 * l1 * (l1 * l1 - 1.0) + m.area_dilation_c * j2 * (j2 - 1.0));
  return m.shear_modulus / (l1 * l2) * (l1 * l1 - 1.0 / j2);
}

struct EdgeForces {
  double right_x;  // sum of F_x over the vertices at X = L
  double top_y;    // sum of F_y over the vertices at Y = H
  double interior_max;
};

EdgeForces stretch_patch(const MembraneMaterial& m, double l1, double l2) {
  const TriangleMesh ref = flat_patch(6, 5);
  const MembraneElasticity membrane(ref, m);
  std::vector<Vec3> x = ref.vertices;
  for (Vec3& v : x) v = Vec3(l1 * v.x(), l2 * v.y(), 0.0);
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  membrane.add_forces(x, f);
  EdgeForces e{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3& r = ref.vertices[i];
    const bool right = std::abs(r.x() - kLength) < 1e-12, top = std::abs(r.y() - kHeight) < 1e-12;
    const bool boundary = right || top || r.x() < 1e-12 || r.y() < 1e-12;
    if (right) e.right_x += f[i].x();
    if (top) e.top_y += f[i].y();
    if (!boundary) e.interior_max = std::max(e.interior_max, f[i].norm());
  }
  return e;
}

// l2 for which T2 vanishes (uniaxial tension along 1), by bisection.
double free_transverse_stretch(const MembraneMaterial& m, double l1) {
  double lo = 0.05, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (tension(m, mid, l1) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

class FlatPatch : public ::testing::TestWithParam<MembraneLaw> {};

TEST_P(FlatPatch, UniaxialStretchGivesClosedFormTension) {
  const MembraneMaterial m{GetParam(), 2.0, 100.0};
  for (double l1 : {1.05, 1.3, 2.0}) {
    const double l2 = free_transverse_stretch(m, l1);
    const EdgeForces e = stretch_patch(m, l1, l2);
    const double t1 = tension(m, l1, l2);
    EXPECT_NEAR(-e.right_x / (t1 * l2 * kHeight), 1.0, 1e-10) << "l1 = " << l1;
    EXPECT_NEAR(e.top_y / (t1 * l1 * kLength), 0.0, 1e-8) << "l1 = " << l1;  // T2 = 0
    EXPECT_LT(e.interior_max / std::abs(t1), 1e-12);
  }
}

TEST_P(FlatPatch, EquibiaxialStretchGivesClosedFormTension) {
  const MembraneMaterial m{GetParam(), 2.0, 100.0};
  for (double l : {1.01, 1.1, 1.5}) {
    const EdgeForces e = stretch_patch(m, l, l);
    const double t = tension(m, l, l);
    EXPECT_NEAR(-e.right_x / (t * l * kHeight), 1.0, 1e-10);
    EXPECT_NEAR(-e.top_y / (t * l * kLength), 1.0, 1e-10);
  }
}

INSTANTIATE_TEST_SUITE_P(Laws, FlatPatch, ::testing::Values(MembraneLaw::Skalak, MembraneLaw::NeoHookean));

TEST(FlatPatch, SmallEquibiaxialStrainGivesAreaModulus) {
  for (double c : {1.0, 10.0, 100.0}) {
    const MembraneMaterial m{MembraneLaw::Skalak, 3.0, c};
    const double eps = 1e-6, l = 1.0 + eps;
    const EdgeForces e = stretch_patch(m, l, l);
    const double cauchy_tension = -e.right_x / (l * kHeight);
    const double area_strain = l * l - 1.0;
    EXPECT_NEAR(cauchy_tension / area_strain / (3.0 * (1.0 + 2.0 * c)), 1.0, 1e-5) << "C = " << c;
  }
}
