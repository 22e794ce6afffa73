// Cell centres across the gap (solver/simulation/gap_profile.hpp): the histogram puts each
// cell in the bin of its centroid, counted from the lower wall at y = -1/2, and the layering
// number separates cells stacked in two layers from cells spread evenly.
#include <gtest/gtest.h>

#include <stdexcept>

#include "solver/simulation/gap_profile.hpp"

namespace rbcal::solver {
namespace {

// A "cell" of two nodes whose centroid is at height y.
std::vector<Vec3> cell_at(double y) { return {Vec3(0.0, y - 1.0, 0.0), Vec3(2.0, y + 1.0, 4.0)}; }

TEST(GapProfile, CountsCellCentresPerBinFromTheLowerWall) {
  // ny 16: walls at -0.5 and 15.5; bins of 4 spacings from -0.5.
  const GapProfile p = cell_centres_across_gap({cell_at(0.0), cell_at(3.4), cell_at(3.6), cell_at(15.0)}, 16, 4.0, 0.0);
  ASSERT_EQ(p.counts.size(), 4u);
  EXPECT_EQ(p.counts[0], 2);  // 0.5 and 3.9 from the wall
  EXPECT_EQ(p.counts[1], 1);  // 4.1
  EXPECT_EQ(p.counts[2], 0);
  EXPECT_EQ(p.counts[3], 1);  // 15.5
}

TEST(GapProfile, LayersScoreFarAboveAnEvenSpread) {
  const int ny = 64;
  std::vector<std::vector<Vec3>> layered, even;
  for (int i = 0; i < 40; ++i) {
    layered.push_back(cell_at(i % 2 == 0 ? 20.0 : 44.0));  // two layers
    even.push_back(cell_at(8.0 + 48.0 * (i + 0.5) / 40.0));  // evenly from 8 to 56
  }
  const GapProfile a = cell_centres_across_gap(layered, ny, 4.0, 8.0);
  const GapProfile b = cell_centres_across_gap(even, ny, 4.0, 8.0);
  // 12 inner bins: two hold 20 cells each, the rest none; evenly, every inner bin holds 3-4.
  EXPECT_GT(a.layering, 2.0);
  EXPECT_LT(b.layering, 0.2);
}

TEST(GapProfile, RejectsANonPositiveBinWidth) {
  EXPECT_THROW(cell_centres_across_gap({cell_at(1.0)}, 8, 0.0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace rbcal::solver
