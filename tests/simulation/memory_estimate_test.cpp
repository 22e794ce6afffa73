// The memory a case needs, known before it allocates: the estimate grows with the lattice,
// a case too large for the memory available is refused naming numerics.N_a and
// numerics.box, and a case file without a resolution is refused instead of becoming the
// seed study's N_a 16 box.
#include <gtest/gtest.h>

#include <stdexcept>

#include "formats/format_error.hpp"
#include "solver/simulation/case_runner.hpp"
#include "solver/simulation/detail/memory_estimate.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "tests/simulation/small_sheared_case.hpp"

using namespace rbcal::solver;

TEST(MemoryEstimate, FollowsTheLatticeAndTheCells) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::NeoHookean);
  c.resolution.nodes_per_radius = 16;
  c.resolution.box_in_radii = {16.0, 10.0, 16.0};  // the seed study's box: 256 x 160 x 256 nodes
  const double paper = static_cast<double>(estimated_peak_bytes(c));
  // 10.5 million nodes at about 950 bytes: 9-11 GB (the reliability pass saw 9.2 GB).
  EXPECT_GT(paper, 9.0e9);
  EXPECT_LT(paper, 11.0e9);
  c.resolution.nodes_per_radius = 8;
  EXPECT_NEAR(static_cast<double>(estimated_peak_bytes(c)) / paper, 1.0 / 8.0, 0.01);
}

TEST(MemoryEstimate, RefusesACaseLargerThanTheMemoryAvailable) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::NeoHookean);
  EXPECT_EQ(memory_refusal(c, 0), "");                        // unknown: no refusal
  EXPECT_EQ(memory_refusal(c, std::uint64_t{1} << 34), "");   // 16 GiB for a 16^3 lattice
  const std::string why = memory_refusal(c, 1000000);         // 1 MB
  EXPECT_NE(why.find("numerics.N_a 4"), std::string::npos) << why;
  EXPECT_NE(why.find("numerics.box"), std::string::npos) << why;
  EXPECT_NE(why.find("16 x 16 x 16"), std::string::npos) << why;
  // run_case asks before it allocates: N_a 256 in a 100a box would need petabytes.
  c.resolution.nodes_per_radius = 256;
  c.resolution.box_in_radii = {100.0, 100.0, 100.0};
  RunOptions o;
  o.output_dir = "memory_estimate_refused.out";
  try {
    run_case(c, o);
    FAIL() << "a case of petabytes was started";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.N_a 256"), std::string::npos) << e.what();
  }
}

TEST(MemoryEstimate, CaseWithoutAResolutionIsRefused) {
  nlohmann::json j = case_to_json(test_cases::small_sheared_case(MembraneLaw::NeoHookean));
  j["numerics"].erase("N_a");
  try {
    case_from_json(j, "no_resolution.json");
    FAIL() << "a case without numerics.N_a was read";
  } catch (const rbcal::formats::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.N_a"), std::string::npos) << e.what();
  }
  j.erase("numerics");
  EXPECT_THROW(case_from_json(j, "no_numerics.json"), rbcal::formats::FormatError);
}
