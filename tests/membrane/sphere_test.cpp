// Closed spherical membranes against continuum results:
//  - an inflated Skalak sphere in equilibrium obeys Laplace's law p = 2 T / R with the
//    equibiaxial Skalak tension T = G_s [(l^2 - 1) + C l^2 (l^4 - 1)], l = R / R0
//    (Barthes-Biesel, Diaz & Dhenin, J. Fluid Mech. 460 (2002) 211);
//  - the discrete bending energy of a sphere against the Helfrich value 8 pi k_c
//    (Helfrich, Z. Naturforsch. 28c (1973) 693).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/dihedral_bending.hpp"
#include "solver/membrane/membrane_elasticity.hpp"
#include "solver/membrane/volume_constraint.hpp"
#include "solver/numerics/detail/lbfgs.hpp"

using namespace rbcal::solver;

namespace {

// Relative error of Laplace's law for the inflated sphere, pressure p in G_s / R0.
double laplace_error(int triangles, double p, double c) {
  const TriangleMesh ref = make_sphere(triangles, 1.0);
  const MembraneElasticity membrane(ref, MembraneMaterial{MembraneLaw::Skalak, 1.0, c});
  const std::size_t nv = ref.vertices.size();
  Eigen::VectorXd v(3 * nv);
  for (std::size_t i = 0; i < nv; ++i) v.segment<3>(3 * i) = ref.vertices[i];
  auto objective = [&](const Eigen::VectorXd& y, Eigen::VectorXd& g) {
    std::vector<Vec3> x(nv), f(nv, Vec3::Zero());
    for (std::size_t i = 0; i < nv; ++i) x[i] = y.segment<3>(3 * i);
    double e = membrane.add_forces(x, f);
    e -= p * add_volume_gradient(x, ref.triangles, p, f);
    for (std::size_t i = 0; i < nv; ++i) g.segment<3>(3 * i) = -f[i];
    return e;
  };
  LbfgsSettings settings;
  settings.gradient_tolerance = 1e-11;
  const LbfgsResult r = minimize_lbfgs(objective, v, settings);
  EXPECT_TRUE(r.converged) << "gradient " << r.gradient_max << " after " << r.iterations;
  std::vector<Vec3> x(nv);
  for (std::size_t i = 0; i < nv; ++i) x[i] = v.segment<3>(3 * i);
  const Vec3 centre = vertex_centroid(x);
  double radius = 0.0;
  for (const Vec3& p : x) radius += (p - centre).norm() / nv;
  const double l = radius;
  const double t = (l * l - 1.0) + c * l * l * (l * l * l * l - 1.0);
  return std::abs(2.0 * t / radius / p - 1.0);
}

}  // namespace

TEST(InflatedSphere, SatisfiesLaplaceLawAndConverges) {
  const double p = 2.0, c = 1.0;  // stretch l of about 1.1
  const double coarse = laplace_error(320, p, c);
  const double medium = laplace_error(1280, p, c);
  const double fine = laplace_error(5120, p, c);
  std::cout << "Laplace-law error: " << coarse << " (320), " << medium << " (1280), " << fine << " (5120)\n";
  EXPECT_LT(medium, 0.01);
  EXPECT_LT(medium, 0.5 * coarse);
  EXPECT_LT(fine, 0.5 * medium);
}

TEST(InflatedSphere, NearlyIncompressibleSkalakAlsoObeysLaplace) {
  EXPECT_LT(laplace_error(1280, 20.0, 100.0), 0.01);
}

TEST(SphereBending, MatchesHelfrichEnergyWithinTheDihedralModelsLimit) {
  // With k_d = 2 sqrt(3) k_c the energy of an equilateral triangulation of a sphere is
  // exactly 8 pi k_c; the icosahedral meshes are not equilateral and settle 3.2-3.6 % high
  // (see dihedral_bending.hpp). Asserted: within 4 % at every resolution, and converged
  // in the mesh (1280 vs 5120 differ by less than 0.5 %). The cylinder factor gives a
  // third of the energy.
  const double kc = 1.0;
  std::vector<double> ratio;
  for (int n : {320, 1280, 5120}) {
    const TriangleMesh sphere = make_sphere(n, 1.0);
    const DihedralBending bending(sphere, kc, SpontaneousShape::Flat);
    ratio.push_back(bending.energy(sphere.vertices) / (8.0 * std::numbers::pi * kc));
    EXPECT_NEAR(ratio.back(), 1.0, 0.04) << n << " triangles";
    const DihedralBending cylinder_factor(sphere, kc, SpontaneousShape::Flat, BendingConversion::Cylinder);
    EXPECT_NEAR(cylinder_factor.energy(sphere.vertices) / bending.energy(sphere.vertices), 1.0 / 3.0, 1e-12);
  }
  std::cout << "bending energy / 8 pi k_c: " << ratio[0] << " (320), " << ratio[1] << " (1280), " << ratio[2]
            << " (5120)\n";
  EXPECT_NEAR(ratio[2] / ratio[1], 1.0, 0.005);
}
