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

TEST(CapillaryNumber, ShearRateAtACapillaryNumberInvertsIt) {
  // The seed study's point: Ca 0.4 of a 0.496 uN/m cell in plasma of 1.569 mPa s at a 4 um is 31.6 1/s.
  EXPECT_NEAR(shear_rate_from_capillary_number(1.569e-3, kDefaultCellRadius, 0.496e-6, 0.4), 31.6, 0.05);
  const double rate = shear_rate_from_capillary_number(1.2e-3, 4e-6, 2e-6, 0.5);
  EXPECT_NEAR(capillary_number(1.2e-3, rate, 4e-6, 2e-6), 0.5, 1e-15);
}
