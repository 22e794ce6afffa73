// cells.shape "spheroid" with cells.aspect_ratio: read, written back, meshed, and refused
// where it does not belong.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/format_error.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "tests/simulation/small_sheared_case.hpp"

using namespace rbcal::solver;

TEST(SpheroidCase, ReadWrittenBackAndMeshed) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::NeoHookean);
  c.shape = CellShape::Spheroid;
  c.aspect_ratio = 0.328;
  const nlohmann::json j = case_to_json(c);
  EXPECT_EQ(j["cells"]["shape"], "spheroid");
  EXPECT_DOUBLE_EQ(j["cells"]["aspect_ratio"].get<double>(), 0.328);
  const SimulationCase back = case_from_json(j, "spheroid.json");
  EXPECT_EQ(back.shape, CellShape::Spheroid);
  EXPECT_DOUBLE_EQ(back.aspect_ratio, 0.328);
  const TriangleMesh mesh = reference_cell(back, 1.0);
  double zmax = 0.0, rmax = 0.0;
  for (const Vec3& v : mesh.vertices) {
    zmax = std::max(zmax, std::abs(v.z()));
    rmax = std::max(rmax, std::hypot(v.x(), v.y()));
  }
  EXPECT_NEAR(zmax, 0.328, 1e-12);
  EXPECT_NEAR(rmax, 1.0, 1e-12);
  // Other shapes write no aspect ratio, so their cases and checkpoints read as before.
  EXPECT_FALSE(case_to_json(test_cases::small_sheared_case(MembraneLaw::NeoHookean))["cells"].contains("aspect_ratio"));
}

TEST(SpheroidCase, AspectRatioOnlyForASpheroidAndInRange) {
  nlohmann::json j = case_to_json(test_cases::small_sheared_case(MembraneLaw::NeoHookean));
  j["cells"]["aspect_ratio"] = 0.5;
  try {
    case_from_json(j, "sphere.json");
    FAIL() << "an aspect ratio on a sphere was accepted";
  } catch (const rbcal::formats::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("cells.aspect_ratio"), std::string::npos) << e.what();
  }
  j["cells"]["shape"] = "spheroid";
  j["cells"]["aspect_ratio"] = 0.0;
  EXPECT_THROW(case_from_json(j, "spheroid.json"), rbcal::formats::FormatError);
}
