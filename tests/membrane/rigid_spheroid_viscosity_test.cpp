// The rolling rigid spheroid's intrinsic viscosity (Jeffery 1922) against its limits and a
// closed form of the integral, and the spheroid mesh against the spheroid's volume.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/rigid_spheroid_viscosity.hpp"
#include "solver/membrane/triangle_mesh.hpp"

using namespace rbcal::solver;

namespace {

// J' of an oblate spheroid (a < b) in closed form: with u^2 = x + a^2 and k^2 = b^2 - a^2,
// J' = 2 int_a^inf du / (u^2 + k^2)^3, whose antiderivative is u / (4 k^2 (u^2 + k^2)^2) +
// 3 u / (8 k^4 (u^2 + k^2)) + 3 atan(u / k) / (8 k^5) (a standard table integral).
double oblate_integral_closed_form(double a, double b) {
  const double k = std::sqrt(b * b - a * a);
  const double at_a = a / (4 * k * k * std::pow(b, 4)) + 3 * a / (8 * std::pow(k, 4) * b * b) +
                      3 * std::atan(a / k) / (8 * std::pow(k, 5));
  return 2.0 * (3 * std::numbers::pi / (16 * std::pow(k, 5)) - at_a);
}

}  // namespace

TEST(RollingSpheroid, SphereGivesEinsteinsFiveHalves) {
  // Einstein, Ann. Phys. 19 (1906) 289 and 34 (1911) 591: eta_sp / phi = 5/2.
  EXPECT_NEAR(rolling_spheroid_intrinsic_viscosity(1.0), 2.5, 1e-10);
  EXPECT_NEAR(jeffery_equatorial_integral(2.0, 2.0), 0.4 * std::pow(2.0, -5), 1e-14);
}

TEST(RollingSpheroid, IntegralMatchesTheClosedFormForOblateBodies) {
  for (double a : {0.05, 0.2, 0.328, 0.6, 0.95})
    EXPECT_NEAR(jeffery_equatorial_integral(a, 1.0) / oblate_integral_closed_form(a, 1.0), 1.0, 1e-9) << "a " << a;
  EXPECT_NEAR(jeffery_equatorial_integral(0.6, 1.5) / oblate_integral_closed_form(0.6, 1.5), 1.0, 1e-9);
}

TEST(RollingSpheroid, ThinDiscDependsOnItsDiameterAlone) {
  // a -> 0: J' -> int_0^inf x^(-1/2) (x + 1)^(-3) dx = B(1/2, 5/2) = 3 pi / 8 (b = 1), so
  // eta_sp / phi -> 8 / (3 pi eps), to a relative O(eps).
  for (double eps : {1e-3, 1e-4}) {
    const double value = rolling_spheroid_intrinsic_viscosity(eps);
    EXPECT_NEAR(value * 3 * std::numbers::pi * eps / 8.0, 1.0, 2.0 * eps) << "eps " << eps;
  }
  // Between the disc and the sphere it falls monotonically towards 5/2 (oblate) and on past
  // it for prolate bodies (towards 2 for a long rod spinning about its axis).
  double last = rolling_spheroid_intrinsic_viscosity(0.1);
  for (double eps : {0.2, 0.33, 0.5, 0.8, 1.0, 1.5, 3.0}) {
    const double value = rolling_spheroid_intrinsic_viscosity(eps);
    EXPECT_LT(value, last) << "eps " << eps;
    last = value;
  }
  EXPECT_THROW(rolling_spheroid_intrinsic_viscosity(0.0), std::invalid_argument);
  EXPECT_THROW(jeffery_equatorial_integral(1.0, -1.0), std::invalid_argument);
}

TEST(SpheroidMesh, EnclosesTheSpheroidsVolume) {
  const double eps = 0.328;
  const TriangleMesh coarse = make_spheroid(1280, 2.0, eps), fine = make_spheroid(5120, 2.0, eps);
  const double exact = 4.0 / 3.0 * std::numbers::pi * eps * 8.0;
  const double e1 = std::abs(enclosed_volume(coarse.vertices, coarse.triangles) / exact - 1.0), e2 = std::abs(enclosed_volume(fine.vertices, fine.triangles) / exact - 1.0);
  EXPECT_LT(e2, 0.005);
  EXPECT_LT(e2, e1);  // inscribed polyhedra converge from below
  EXPECT_THROW(make_spheroid(1280, 1.0, 0.0), std::invalid_argument);
}
