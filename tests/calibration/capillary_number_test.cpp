// The seed study's arithmetic (Takeishi et al.): Ca = 0.4 corresponded to 31.6 1/s for intact
// RBCs, with eta0 = 1.569 mPa s and <a> = 4 um, so G_s = eta0 gamma_dot a / Ca = 0.496 uN/m.
#include <gtest/gtest.h>

#include "calibration/capillary_number.hpp"

using namespace rbcal::calibration;

TEST(CapillaryNumber, SeedStudyArithmetic) {
  const double g_s = shear_modulus_from_capillary_number(1.569e-3, 31.6, kDefaultCellRadius, 0.4);
  EXPECT_NEAR(g_s * 1e6, 0.496, 0.0005);
  EXPECT_NEAR(capillary_number(1.569e-3, 31.6, 4e-6, g_s), 0.4, 1e-12);
}

TEST(CapillaryNumber, ScalesAsStated) {
  // Ca is proportional to eta0, gamma_dot and a and inversely to G_s.
  const double base = capillary_number(1e-3, 10.0, 4e-6, 1e-6);
  EXPECT_NEAR(base, 0.04, 1e-15);
  EXPECT_NEAR(capillary_number(2e-3, 10.0, 4e-6, 1e-6), 2 * base, 1e-15);
  EXPECT_NEAR(capillary_number(1e-3, 10.0, 4e-6, 2e-6), base / 2, 1e-15);
}
