// Optical-tweezers stretching in static equilibrium (coarse mesh, fast): the cell
// lengthens along the force and narrows across it, monotonically; the volume stays
// within 1e-3 % of its reference (the seed study's bound) and the nearly incompressible
// Skalak membrane (C = 100) barely changes area; and the solution depends on force and
// modulus only through F / (G_s a), as dimensional analysis demands.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/membrane/cell_stretching.hpp"

using namespace rbcal::solver;

TEST(CellStretching, LengthensNarrowsAndKeepsVolume) {
  StretchSettings s;
  s.triangles = 320;
  s.material.shear_modulus = 5e-6;
  const std::vector<StretchPoint> pts = stretch_cell(s, {0.0, 20e-12, 60e-12, 120e-12, 200e-12});
  ASSERT_EQ(pts.size(), 5u);
  EXPECT_NEAR(pts[0].axial_diameter, 2.0 * s.radius, 1e-12);
  EXPECT_NEAR(pts[0].transverse_diameter, 2.0 * s.radius, 1e-9);  // icosphere vertices on the rim
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_TRUE(pts[i].converged) << i;
    EXPECT_LT(std::abs(pts[i].volume_error), 1e-5) << i;
    EXPECT_LT(std::abs(pts[i].area_change), 0.01) << i;
    if (i > 0) {
      EXPECT_GT(pts[i].axial_diameter, pts[i - 1].axial_diameter) << i;
      EXPECT_LT(pts[i].transverse_diameter, pts[i - 1].transverse_diameter) << i;
    }
  }
  EXPECT_GT(pts.back().axial_diameter, 1.5 * 2.0 * s.radius);  // large deformation at 200 pN
}

TEST(CellStretching, DependsOnForceOverModulusOnly) {
  StretchSettings soft;
  soft.triangles = 320;
  soft.material.shear_modulus = 4e-6;
  soft.bending_modulus = 5e-19;
  StretchSettings stiff = soft;
  stiff.material.shear_modulus = 8e-6;
  stiff.bending_modulus = 10e-19;  // k_c / (G_s a^2) unchanged
  const auto a = stretch_cell(soft, {50e-12});
  const auto b = stretch_cell(stiff, {100e-12});
  EXPECT_NEAR(a[0].axial_diameter / b[0].axial_diameter, 1.0, 1e-6);
  EXPECT_NEAR(a[0].transverse_diameter / b[0].transverse_diameter, 1.0, 1e-6);
}

TEST(CellStretching, RejectsBadSettings) {
  StretchSettings s;
  s.triangles = 320;
  EXPECT_THROW(stretch_cell(s, {-1e-12}), std::invalid_argument);
  s.contact_fraction = 0.7;
  EXPECT_THROW(stretch_cell(s, {1e-12}), std::invalid_argument);
}
