// Sweep plans: the optional cap on the lattice shear modulus lowers the Reynolds number
// of the low-Ca cases only, to exactly the cap (scaled down for lambda < 1).
#include <gtest/gtest.h>

#include <map>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "solver/lattice_units.hpp"
#include "solver/sweep/sweep_plan.hpp"

using namespace rbcal::solver;

namespace {

std::string write_plan(const std::string& name, const std::string& extra) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << R"({"schema": "rbcal.plan/1", "grid": {"phi": [0.05], "Ca": [0.01, 0.1], "lambda": [1, 0.1]},
    "base": {"cells": {"shape": "sphere", "triangles": 80, "law": "neo-hookean"},
             "numerics": {"N_a": 4, "box": [4.0, 4.0, 4.0], "tau_out": 1.0, "Re": 0.2},
             "run": {"strain_end": 1.0, "window": [0.5, 1.0]}})"
                      << extra << "}";
  return path.string();
}

}  // namespace

TEST(SweepPlan, ShearModulusCapLowersReynoldsNumberOnlyWhereNeeded) {
  const SweepPlan plan = read_sweep_plan(write_plan("rbcal_plan_cap.json", R"(, "max_shear_modulus_lattice": 0.05)"));
  ASSERT_EQ(plan.cases.size(), 4u);  // lambda 1 (Ca 0.01, 0.1), then lambda 0.1
  // Ca 0.01: G_s,lu at Re 0.2 would be 0.2 (1/6)^2 / (4 x 0.01) = 0.139 > 0.05, so Re
  // becomes 0.05 x 4 x 0.01 x 36 = 0.072 and G_s,lu equals the cap.
  const SimulationCase& low = plan.cases[0].spec;
  EXPECT_NEAR(low.flow.reynolds_number, 0.072, 1e-12);
  EXPECT_NEAR(derive_lattice_units(low.flow, low.resolution).shear_modulus, 0.05, 1e-12);
  // Ca 0.1: 0.0139 < 0.05, the base Re stays.
  EXPECT_EQ(plan.cases[1].spec.flow.reynolds_number, 0.2);
  // lambda 0.1: the cap is 0.05 (1 + 0.1) / 2 = 0.0275, so Re = 0.0275 x 1.44 = 0.0396.
  const SimulationCase& thin = plan.cases[2].spec;
  EXPECT_EQ(thin.flow.viscosity_ratio, 0.1);
  EXPECT_NEAR(thin.flow.reynolds_number, 0.0396, 1e-12);
  EXPECT_NEAR(derive_lattice_units(thin.flow, thin.resolution).shear_modulus, 0.0275, 1e-12);
  // Without a cap every case keeps the base Re.
  const SweepPlan plain = read_sweep_plan(write_plan("rbcal_plan_nocap.json", ""));
  EXPECT_EQ(plain.cases[0].spec.flow.reynolds_number, 0.2);
}

TEST(SweepPlan, RejectsANonPositiveShearModulusCapNamingTheField) {
  try {
    read_sweep_plan(write_plan("rbcal_plan_badcap.json", R"(, "max_shear_modulus_lattice": -1)"));
    FAIL() << "accepted a negative cap";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_shear_modulus_lattice"), std::string::npos) << e.what();
  }
}

TEST(SweepPlan, RefusesABoxThatIsNoWholeNumberOfNodesNamingThePlan) {
  // Found by fuzzing: the lattice of the base case failed later, without naming the file.
  const std::string path = write_plan("rbcal_plan_badbox.json", "");
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = text.find("[4.0, 4.0, 4.0]");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 15, "[4.1, 4.0, 4.0]");
  std::ofstream(path) << text;
  try {
    read_sweep_plan(path);
    FAIL() << "accepted a box of 16.4 nodes";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(path + " (base): field numerics: lattice units: box"), std::string::npos)
        << e.what();
  }
}

// A listed plan makes one case per point, in the list's order, with the same Re cap.
TEST(SweepPlan, AListedPlanMakesOneCasePerPointInItsOrder) {
  const std::string path = write_plan("rbcal_plan_listed.json", "");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
  j.erase("grid");
  j["points"] = {{0.05, 0.1, 1}, {0.05, 0.01, 0.1}};
  std::ofstream(path) << j.dump();
  const SweepPlan plan = read_sweep_plan(path);
  ASSERT_EQ(plan.cases.size(), 2u);
  EXPECT_EQ(plan.cases[0].id, "phi0.05_Ca0.1_lambda1");
  EXPECT_EQ(plan.cases[1].id, "phi0.05_Ca0.01_lambda0.1");
  EXPECT_DOUBLE_EQ(plan.cases[1].spec.flow.capillary_number, 0.01);
}

// The shipped v2 plans (data/cases/library_v2/plan_n*.json, studies/library-v2-development/design_library_v2.py)
// make the shipped v2 case files that the background runs use: same points, same numerics,
// Re equal up to the case files' rounding to 4 digits.
TEST(SweepPlan, TheV2PlansMakeTheShippedV2CaseFiles) {
  // N_a 8: the 20 of the maximin subset and the 14 of round 2 (every point at phi >= 0.38);
  // the 16a gap: all 22 points at phi >= 0.38.
  const std::map<std::string, std::size_t> cases_in = {{"n6", 60}, {"n8", 34}, {"n8_h16", 22}};
  for (const auto& [tier, count] : cases_in) {
    const std::string dir = std::string(RBCAL_CASES_DIR) + "/library_v2/";
    const SweepPlan plan = read_sweep_plan(dir + "plan_" + tier + ".json");
    EXPECT_EQ(plan.cases.size(), count) << tier;
    for (const PlannedCase& c : plan.cases) {
      const SimulationCase file = read_case(dir + tier + "/" + c.id + ".json");
      EXPECT_EQ(file.flow.capillary_number, c.spec.flow.capillary_number) << c.id;
      EXPECT_EQ(file.flow.viscosity_ratio, c.spec.flow.viscosity_ratio) << c.id;
      EXPECT_EQ(file.target_phi, c.spec.target_phi) << c.id;
      EXPECT_EQ(file.resolution.nodes_per_radius, c.spec.resolution.nodes_per_radius) << c.id;
      EXPECT_EQ(file.coupling_interval, c.spec.coupling_interval) << c.id;
      EXPECT_EQ(file.node_velocity, c.spec.node_velocity) << c.id;
      EXPECT_EQ(file.resolution.box_in_radii, c.spec.resolution.box_in_radii) << c.id;
      EXPECT_EQ(file.window, c.spec.window) << c.id;
      EXPECT_NEAR(file.flow.reynolds_number / c.spec.flow.reynolds_number, 1.0, 5e-4) << c.id;
    }
  }
}

// A plan may name case files instead of a grid: one case per file, its id the file's stem,
// read as `rbcal simulate` reads it; errors name the plan and the field.
TEST(SweepPlan, APlanOfCaseFilesRunsEachFileUnderItsStem) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "rbcal_case_file_plan";
  fs::remove_all(dir);
  fs::create_directories(dir / "cases");
  const std::string base = R"({"schema": "rbcal.case/1", "params": {"phi": 0.05, "Ca": CA, "lambda": 1},
    "cells": {"shape": "sphere", "triangles": 80, "law": "neo-hookean"},
    "numerics": {"N_a": 4, "box": [4.0, 4.0, 4.0], "tau_out": 1.0, "Re": 0.2},
    "run": {"strain_end": 1.0, "window": [0.5, 1.0]}})";
  for (const auto& [name, ca] : std::map<std::string, std::string>{{"b_soft", "0.4"}, {"a_stiff", "0.01"}}) {
    std::string text = base;
    text.replace(text.find("CA"), 2, ca);
    std::ofstream(dir / "cases" / (name + ".json")) << text;
  }
  auto plan_with = [&](const std::string& files) {
    std::ofstream(dir / "plan.json") << R"({"schema": "rbcal.plan/1", "description": "two files", "case_files": )"
                                     << files << "}";
    return (dir / "plan.json").string();
  };
  const SweepPlan plan = read_sweep_plan(plan_with(R"(["cases/b_soft.json", "cases/a_stiff.json"])"));
  ASSERT_EQ(plan.cases.size(), 2u);
  EXPECT_EQ(plan.cases[0].id, "b_soft");  // the file's order, not sorted
  EXPECT_EQ(plan.cases[1].id, "a_stiff");
  EXPECT_DOUBLE_EQ(plan.cases[0].spec.flow.capillary_number, 0.4);
  EXPECT_DOUBLE_EQ(plan.cases[1].spec.flow.capillary_number, 0.01);
  auto refused = [&](const std::string& files) {
    try {
      read_sweep_plan(plan_with(files));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string missing = refused(R"(["cases/b_soft.json", "cases/nowhere.json"])");
  EXPECT_NE(missing.find("plan.json"), std::string::npos) << missing;
  EXPECT_NE(missing.find("case_files.1"), std::string::npos) << missing;
  const std::string twice = refused(R"(["cases/b_soft.json", "cases/../cases/b_soft.json"])");
  EXPECT_NE(twice.find("a second case named b_soft"), std::string::npos) << twice;
  EXPECT_NE(refused("[]").find("case_files"), std::string::npos);
  fs::remove_all(dir);
}
