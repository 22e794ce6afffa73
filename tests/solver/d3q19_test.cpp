// Lattice symmetry of D3Q19: the moment identities that make the lattice-Boltzmann
// equation recover the Navier-Stokes equations (Qian, d'Humieres & Lallemand,
// Europhys. Lett. 17 (1992) 479).
#include <gtest/gtest.h>

#include "solver/fluid/d3q19.hpp"

using namespace rbcal::solver::d3q19;

TEST(D3Q19, WeightsSumToOneAndOddMomentsVanish) {
  double sum = 0.0;
  double first[3] = {0, 0, 0};
  for (int q = 0; q < Q; ++q) {
    sum += w[q];
    for (int a = 0; a < 3; ++a) first[a] += w[q] * c[q][a];
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(first[a], 0.0, 1e-15);
}

TEST(D3Q19, SecondAndFourthMomentsAreIsotropic) {
  auto delta = [](int a, int b) { return a == b ? 1.0 : 0.0; };
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double m2 = 0.0;
      for (int q = 0; q < Q; ++q) m2 += w[q] * c[q][a] * c[q][b];
      EXPECT_NEAR(m2, cs2 * delta(a, b), 1e-15) << a << b;
      for (int g = 0; g < 3; ++g)
        for (int d = 0; d < 3; ++d) {
          double m4 = 0.0;
          for (int q = 0; q < Q; ++q) m4 += w[q] * c[q][a] * c[q][b] * c[q][g] * c[q][d];
          const double iso = cs2 * cs2 * (delta(a, b) * delta(g, d) + delta(a, g) * delta(b, d) +
                                          delta(a, d) * delta(b, g));
          EXPECT_NEAR(m4, iso, 1e-15) << a << b << g << d;
        }
    }
}

TEST(D3Q19, OppositeReversesVelocity) {
  for (int q = 0; q < Q; ++q) {
    EXPECT_EQ(opposite(opposite(q)), q);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(c[opposite(q)][a], -c[q][a]);
    EXPECT_EQ(w[opposite(q)], w[q]);
  }
}
