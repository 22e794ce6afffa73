// Physical-to-lattice conversion of docs/reference.md, "Lattice units".
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "solver/lattice_units.hpp"

using namespace rbcal::solver;

TEST(LatticeUnits, PaperResolutionValues) {
  FlowParameters flow;
  flow.capillary_number = 0.4;
  flow.viscosity_ratio = 5.0;
  flow.reynolds_number = 0.2;
  LatticeResolution res;  // N_a = 16, tau = 1, 16a x 10a x 16a
  const LatticeUnits u = derive_lattice_units(flow, res);
  EXPECT_EQ(u.nx, 256);
  EXPECT_EQ(u.ny, 160);
  EXPECT_EQ(u.nz, 256);
  EXPECT_DOUBLE_EQ(u.nu_out, 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(u.nu_in, 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(u.tau_in, 3.0);
  const double gamma = 0.2 * (1.0 / 6.0) / 256.0;
  EXPECT_DOUBLE_EQ(u.shear_rate, gamma);
  EXPECT_DOUBLE_EQ(u.wall_speed, gamma * 80.0);
  EXPECT_LT(u.mach, 0.1);
  // Ca = eta0 gamma a / G_s holds in lattice units (rho = 1, a = N_a).
  EXPECT_NEAR(u.nu_out * u.shear_rate * 16.0 / u.shear_modulus, 0.4, 1e-14);
}

TEST(LatticeUnits, DefaultReducedBendingMatchesSeedStudy) {
  // k_b = 5e-19 J, G_s = 4 uN/m, a = 4 um give kb_hat = 5e-19 / (16e-12 4e-6) = 7.8125e-3.
  EXPECT_NEAR(FlowParameters{}.reduced_bending, 7.8125e-3, 1e-12);
  const LatticeUnits u = derive_lattice_units(FlowParameters{}, LatticeResolution{});
  EXPECT_NEAR(u.bending_modulus / (256.0 * u.shear_modulus), 7.8125e-3, 1e-12);
}

TEST(LatticeUnits, RejectsBadInputs) {
  LatticeResolution res;
  res.box_in_radii = {16.0, 10.0, 16.03};  // 256.48 nodes along z
  EXPECT_THROW(derive_lattice_units(FlowParameters{}, res), std::invalid_argument);
  res = LatticeResolution{};
  res.tau_out = 0.5;
  EXPECT_THROW(derive_lattice_units(FlowParameters{}, res), std::invalid_argument);
  FlowParameters flow;
  flow.capillary_number = 0.0;
  EXPECT_THROW(derive_lattice_units(flow, LatticeResolution{}), std::invalid_argument);
}
