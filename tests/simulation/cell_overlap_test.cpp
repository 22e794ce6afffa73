// The overlap check of dense suspensions: the winding number of a closed mesh (1 inside,
// 0 outside) and the count of membrane nodes inside other cells, across the periodic seam.
#include <gtest/gtest.h>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/simulation/cell_overlap.hpp"

#include <numbers>

using namespace rbcal::solver;

namespace {

std::vector<Vec3> moved(const TriangleMesh& m, const Vec3& to) {
  std::vector<Vec3> x;
  for (const Vec3& v : m.vertices) x.push_back(v + to);
  return x;
}

}  // namespace

TEST(WindingNumber, OneInsideZeroOutsideOfABiconcaveCell) {
  const TriangleMesh cell = make_biconcave_cell(320, 1.0, BiconcaveProfile::EvansFung);
  EXPECT_NEAR(winding_number(Vec3(0.5, 0.0, 0.0), cell.vertices, cell.triangles), 1.0, 1e-9);
  EXPECT_NEAR(winding_number(Vec3(0.0, 0.8, 0.0), cell.vertices, cell.triangles), 1.0, 1e-9);
  // The dimple: the centre of the disc is inside (the Evans-Fung thickness there is
  // 0.81 um of a 3.91 um radius), points just above and below it are not.
  EXPECT_NEAR(winding_number(Vec3(0.0, 0.0, 0.0), cell.vertices, cell.triangles), 1.0, 1e-9);
  EXPECT_NEAR(winding_number(Vec3(0.0, 0.0, 0.3), cell.vertices, cell.triangles), 0.0, 1e-9);
  EXPECT_NEAR(winding_number(Vec3(1.5, 0.0, 0.0), cell.vertices, cell.triangles), 0.0, 1e-9);
  EXPECT_NEAR(winding_number(Vec3(0.0, 0.0, -2.0), cell.vertices, cell.triangles), 0.0, 1e-9);
}

TEST(CellOverlap, CountsNodesInsideOtherCellsAlsoAcrossTheSeam) {
  const TriangleMesh sphere = make_sphere(320, 4.0);
  const double period = 40.0;
  // Apart: centres 9 apart (radius 4).
  EXPECT_EQ(count_overlaps({moved(sphere, {10, 10, 10}), moved(sphere, {19, 10, 10})}, sphere.triangles, period, period)
                .nodes_inside,
            0);
  // Centres 6 apart: the cap of each sphere beyond the other's plane of symmetry is inside it.
  const OverlapCount near = count_overlaps({moved(sphere, {10, 10, 10}), moved(sphere, {16, 10, 10})},
                                           sphere.triangles, period, period);
  EXPECT_GT(near.nodes_inside, 0);
  EXPECT_EQ(near.cell_pairs, 2);
  // The same pair across the periodic seam in z: 2 and 38 are 4 apart through it.
  const OverlapCount seam = count_overlaps({moved(sphere, {10, 10, 2}), moved(sphere, {10, 10, 38})},
                                           sphere.triangles, period, period);
  EXPECT_GT(seam.nodes_inside, 0);
  EXPECT_EQ(seam.cell_pairs, 2);
}

TEST(CellOverlap, DepthAndVolumeOfTwoOverlappingSpheresAcrossTheSeam) {
  // Two spheres of radius 4 with centres 6 apart across the seam in x: each reaches 2 into
  // the other. The lens they share has volume pi (4 R + d)(2 R - d)^2 / 12 = 14.67 pi
  // (R 4, d 6), i.e. 0.1719 of one sphere, 0.0859 of the two together.
  const TriangleMesh sphere = make_sphere(1280, 4.0);
  const double period = 40.0;
  const std::vector<std::vector<Vec3>> x = {moved(sphere, {3, 10, 10}), moved(sphere, {37, 10, 10})};
  const OverlapCount n = count_overlaps(x, sphere.triangles, period, period);
  // The deepest point of one sphere inside the other is 2 from the other's surface; a
  // node's distance to the host's nearest node exceeds its depth by less than the node
  // spacing (about 0.8 here), and the sphere's nodes need not include that point.
  EXPECT_GT(n.max_depth, 1.6);
  EXPECT_LT(n.max_depth, 2.8);
  const double lens = std::numbers::pi * (4 * 4.0 + 6.0) * (2 * 4.0 - 6.0) * (2 * 4.0 - 6.0) / 12.0;
  const double fraction = overlap_volume_fraction(x, sphere.triangles, period, 20.0, period, 0.25);
  const double two_spheres = 2.0 * enclosed_volume(x[0], sphere.triangles);
  EXPECT_NEAR(fraction, lens / two_spheres, 0.1 * lens / two_spheres);  // grid of 0.25: lens ~ 3000 points
  // Apart: nothing is counted twice.
  const std::vector<std::vector<Vec3>> apart = {moved(sphere, {10, 10, 10}), moved(sphere, {20, 10, 10})};
  EXPECT_EQ(overlap_volume_fraction(apart, sphere.triangles, period, 20.0, period, 0.5), 0.0);
  EXPECT_EQ(count_overlaps(apart, sphere.triangles, period, period).max_depth, 0.0);
}

// Placed cells that overlap are refused when the case is read, naming both placements; the
// same cells apart, or with overlap_allowed, are accepted.
#include "formats/format_error.hpp"
#include "solver/simulation/simulation_case.hpp"

TEST(PlacedCells, OverlappingPlacementsAreRefused) {
  nlohmann::json j = {{"schema", "rbcal.case/1"},
                      {"params", {{"Ca", 0.1}, {"lambda", 5.0}}},
                      {"cells",
                       {{"shape", "biconcave"},
                        {"triangles", 320},
                        {"placements", {{{"center", {0.0, 0.0, 0.0}}}, {{"center", {0.1, 0.0, 0.0}}}}}}},
                      {"numerics", {{"N_a", 4}, {"box", {6.0, 6.0, 6.0}}}},
                      {"run", {{"strain_end", 1.0}, {"window", {0.5, 1.0}}}}};
  try {
    case_from_json(j, "two.json");
    FAIL() << "two cells 0.1 a apart were accepted";
  } catch (const rbcal::formats::FormatError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("two.json"), std::string::npos) << what;
    EXPECT_NE(what.find("cells.placements.1"), std::string::npos) << what;
    EXPECT_NE(what.find("cells.placements.0"), std::string::npos) << what;
  }
  // Across the periodic seam in x: centres at -2.9 and +2.9 in a 6a box are 0.2 a apart.
  j["cells"]["placements"] = {{{"center", {-2.9, 0.0, 0.0}}}, {{"center", {2.9, 0.0, 0.0}}}};
  EXPECT_THROW(case_from_json(j, "seam.json"), rbcal::formats::FormatError);
  // Stacked discs 0.8 a apart along their axes (thickness 0.66 a) do not overlap.
  j["cells"]["placements"] = {{{"center", {0.0, 0.0, 0.0}}}, {{"center", {0.0, 0.0, 0.0}}}};
  j["cells"]["placements"][1]["center"] = {0.0, 0.0, 0.0};
  j["cells"]["placements"][1]["rotation"] = {0.0, 0.0, 1.0, 0.0};
  j["cells"]["placements"][0]["center"] = {0.0, 0.0, -0.4};
  j["cells"]["placements"][1]["center"] = {0.0, 0.0, 0.4};
  EXPECT_NO_THROW(case_from_json(j, "stacked.json"));
  // Allowed on purpose (the overlap diagnostics' own tests).
  j["cells"]["placements"][1]["center"] = {0.1, 0.0, 0.0};
  j["cells"]["placements"][0]["center"] = {0.0, 0.0, 0.0};
  j["cells"]["overlap_allowed"] = true;
  EXPECT_TRUE(case_from_json(j, "allowed.json").overlap_allowed);
}
