// The repulsion between membranes of different cells (cell_contact.hpp): the pair law,
// no force within one cell, the periodic seam, and agreement with a brute-force sum.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solver/simulation/cell_contact.hpp"

using namespace rbcal::solver;

namespace {

using Cells = std::vector<std::vector<Vec3>>;

NodeBins bins;  // one search structure for all tests: its buffers are reused as in a run

// The search holds positions in single precision (16-byte entries it streams through), so
// distances carry relative errors of a few 1e-7 in a box of side 20.
constexpr double kSingle = 1e-5;

Cells zero_forces(const Cells& x) {
  Cells f;
  for (const auto& c : x) f.emplace_back(c.size(), Vec3::Zero());
  return f;
}

}  // namespace

TEST(CellContact, PairForceFollowsTheLawEqualAndOpposite) {
  const Cells x = {{Vec3(5.0, 5.0, 5.0)}, {Vec3(5.6, 5.0, 5.8)}};  // 1.0 apart
  Cells f = zero_forces(x);
  const ContactCount n = add_contact_forces(x, 2.0, 0.3, 20.0, 20.0, f, bins);
  EXPECT_EQ(n.node_pairs, 2);
  const double magnitude = 0.3 * (2.0 / 1.0 - 1.0);
  const Vec3 away = Vec3(-0.6, 0.0, -0.8);  // unit vector from the second node to the first
  EXPECT_NEAR((f[0][0] - magnitude * away).norm(), 0.0, kSingle * magnitude);
  EXPECT_NEAR((f[1][0] + magnitude * away).norm(), 0.0, kSingle * magnitude);
}

TEST(CellContact, NoForceBeyondRangeNorWithinOneCell) {
  const Cells x = {{Vec3(5.0, 5.0, 5.0), Vec3(5.5, 5.0, 5.0)}, {Vec3(7.01, 5.0, 5.0)}};
  Cells f = zero_forces(x);
  EXPECT_EQ(add_contact_forces(x, 1.5, 1.0, 20.0, 20.0, f, bins).node_pairs, 0);
  for (const auto& c : f)
    for (const Vec3& v : c) EXPECT_EQ(v.norm(), 0.0);
}

TEST(CellContact, ActsAcrossThePeriodicSeamInXAndZ) {
  // 0.2 and 19.6 are 0.6 apart across the seam of a period of 20 (positions outside
  // [0, period) are allowed: cells drift across the seam).
  const Cells x = {{Vec3(0.2, 5.0, 0.1)}, {Vec3(19.6, 5.0, -20.0 + 0.1)}};
  Cells f = zero_forces(x);
  EXPECT_EQ(add_contact_forces(x, 1.0, 1.0, 20.0, 20.0, f, bins).node_pairs, 2);
  EXPECT_NEAR(f[0][0].x(), 1.0 / 0.6 - 1.0, kSingle);  // pushed towards +x, away from the seam
  EXPECT_NEAR(f[1][0].x(), -(1.0 / 0.6 - 1.0), kSingle);
}

TEST(CellContact, MatchesABruteForceSumAndExertsNoNetForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double px = 12.0, pz = 9.0, range = 1.3, strength = 0.7;
  Cells x(6);
  for (auto& c : x)
    for (int m = 0; m < 80; ++m) c.push_back(Vec3(px * (2.0 * u(rng) - 0.5), 1.0 + 6.0 * u(rng), pz * u(rng)));
  Cells f = zero_forces(x);
  const ContactCount n = add_contact_forces(x, range, strength, px, pz, f, bins);
  long pairs = 0;
  Vec3 total = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t m = 0; m < x[i].size(); ++m) {
      Vec3 expected = Vec3::Zero();
      for (std::size_t j = 0; j < x.size(); ++j) {
        if (j == i) continue;
        for (const Vec3& q : x[j]) {
          Vec3 d = x[i][m] - q;
          d.x() -= px * std::round(d.x() / px);
          d.z() -= pz * std::round(d.z() / pz);
          const double r = d.norm();
          if (r >= range) continue;
          ++pairs;
          expected += strength * (range / std::max(r, 0.2 * range) - 1.0) / r * d;
        }
      }
      EXPECT_NEAR((f[i][m] - expected).norm(), 0.0, kSingle * (1.0 + expected.norm())) << "cell " << i << " node " << m;
      total += f[i][m];
    }
  EXPECT_GT(pairs, 20);  // the test exercises the law, not only empty neighbourhoods
  EXPECT_EQ(n.node_pairs, pairs);
  EXPECT_NEAR(total.norm(), 0.0, kSingle * pairs);
}

TEST(CellContact, OffWhenRangeOrStrengthIsZero) {
  const Cells x = {{Vec3(5.0, 5.0, 5.0)}, {Vec3(5.1, 5.0, 5.0)}};
  Cells f = zero_forces(x);
  EXPECT_EQ(add_contact_forces(x, 0.0, 1.0, 20.0, 20.0, f, bins).node_pairs, 0);
  EXPECT_EQ(add_contact_forces(x, 1.0, 0.0, 20.0, 20.0, f, bins).node_pairs, 0);
  EXPECT_EQ(f[0][0].norm(), 0.0);
}

TEST(CellSeparation, MovesCloseNodesApartToTheGapAndLeavesOthers) {
  // Nodes 0.4 apart across the seam (gap 1.0): each moves 0.3 away from the other.
  Cells x = {{Vec3(0.2, 5.0, 3.0), Vec3(5.0, 5.0, 3.0)}, {Vec3(19.8, 5.0, 3.0)}};
  const ContactCount n = separate_close_nodes(x, 1.0, 20.0, 20.0, bins);
  EXPECT_EQ(n.node_pairs, 2);
  EXPECT_NEAR((x[0][0] - Vec3(0.5, 5.0, 3.0)).norm(), 0.0, kSingle);
  EXPECT_NEAR((x[1][0] - Vec3(19.5, 5.0, 3.0)).norm(), 0.0, kSingle);
  EXPECT_EQ(x[0][1], Vec3(5.0, 5.0, 3.0));  // its partner is of its own cell: no move
}

TEST(CellSeparation, EachNodeMovesAwayFromItsNearestPartnerOnly) {
  // Node A with two partners of another cell at 0.3 (nearest) and 0.6; gap 0.8.
  Cells x = {{Vec3(5.0, 5.0, 5.0)}, {Vec3(5.3, 5.0, 5.0), Vec3(5.0, 5.6, 5.0)}};
  separate_close_nodes(x, 0.8, 20.0, 20.0, bins);
  EXPECT_NEAR((x[0][0] - Vec3(5.0 - 0.25, 5.0, 5.0)).norm(), 0.0, kSingle);
  EXPECT_NEAR((x[1][0] - Vec3(5.3 + 0.25, 5.0, 5.0)).norm(), 0.0, kSingle);
  EXPECT_NEAR((x[1][1] - Vec3(5.0, 5.6 + 0.1, 5.0)).norm(), 0.0, kSingle);
}
