// Reading simulation libraries: schema checks with errors naming file and field,
// consistency across cases, plan grids and the summary for `rbcal library show`.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "surrogate/library_summary.hpp"
#include "surrogate/simulation_library.hpp"
#include "synthetic_library.hpp"

namespace rbcal::surrogate {
namespace {

using testing::case_json;
using testing::fresh_temp_folder;
using testing::write_text;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LibraryReading, ReadsCasesSortedWithTheirValues) {
  const auto root = fresh_temp_folder("reads");
  write_text(root / "cases" / "b.json", case_json(0.2, 0.1, 5.0, 0.201, 1.7, 0.01).dump());
  write_text(root / "cases" / "a.json", case_json(0.1, 0.1, 5.0, 0.099, 1.3, 0.02).dump());
  write_text(root / "cases" / "a.csv", "strain,eta_re_stresslet\n");     // time series: not read
  write_text(root / "work" / "c.json", "{ half written");                // in progress: ignored
  const SimulationLibrary lib = read_library(root);
  ASSERT_EQ(lib.cases.size(), 2u);
  EXPECT_EQ(lib.cases[0].id, "a");
  EXPECT_EQ(lib.cases[1].id, "b");
  EXPECT_DOUBLE_EQ(lib.cases[0].phi, 0.1);
  EXPECT_DOUBLE_EQ(lib.cases[0].phi_actual, 0.099);
  EXPECT_DOUBLE_EQ(lib.cases[0].eta_re, 1.3);
  EXPECT_DOUBLE_EQ(lib.cases[0].eta_re_sem, 0.02);
  EXPECT_DOUBLE_EQ(lib.cases[1].capillary_number, 0.1);
  EXPECT_DOUBLE_EQ(lib.cases[1].viscosity_ratio, 5.0);
  EXPECT_FALSE(lib.plan.has_value());
}

// One corruption of a valid case file and the words its error must contain.
struct Corruption {
  std::string name;
  std::function<void(nlohmann::json&)> corrupt;
  std::string field_message;
};

TEST(LibraryReading, RejectsCorruptCaseFilesNamingFileAndField) {
  const std::vector<Corruption> table = {
      {"schema", [](auto& j) { j["schema"] = "rbcal.case/0"; }, "field schema: must be \"rbcal.case/1\""},
      {"no_ca", [](auto& j) { j["params"].erase("Ca"); }, "field params.Ca: missing"},
      {"negative_ca", [](auto& j) { j["params"]["Ca"] = -0.1; }, "field params.Ca: must be a positive number"},
      {"lambda_text", [](auto& j) { j["params"]["lambda"] = "five"; }, "field params.lambda: must be a positive number"},
      {"negative_sem", [](auto& j) { j["result"]["eta_re_sem"] = -1e-3; },
       "field result.eta_re_sem: must be a non-negative number"},
      {"zero_eta", [](auto& j) { j["result"]["eta_re"] = 0.0; }, "field result.eta_re: must be a positive number"},
      {"no_result", [](auto& j) { j.erase("result"); }, "field result.phi_actual: missing"},
      {"phi_actual_one", [](auto& j) { j["result"]["phi_actual"] = 1.2; }, "field result.phi_actual: must be in (0, 1)"},
      {"n_cells_real", [](auto& j) { j["result"]["n_cells"] = 2.5; }, "field result.n_cells: must be an integer"},
      {"no_kernel", [](auto& j) { j["numerics"].erase("kernel"); }, "field numerics.kernel: missing"},
      {"short_window", [](auto& j) { j["run"]["window"] = {10.0}; }, "field run.window: must be an array"},
      {"top_array", [](auto& j) { j = nlohmann::json::array(); }, "field (top level): must be a JSON object"},
  };
  for (const Corruption& c : table) {
    SCOPED_TRACE(c.name);
    const auto root = fresh_temp_folder("corrupt_" + c.name);
    write_text(root / "cases" / "good.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
    nlohmann::json bad = case_json(0.2, 0.1, 5.0, 0.2, 1.7, 0.01);
    c.corrupt(bad);
    const auto file = root / "cases" / (c.name + ".json");
    write_text(file, bad.dump());
    const std::string message = error_of([&] { read_library(root); });
    EXPECT_NE(message.find(file.string() + ": " + c.field_message), std::string::npos) << message;
  }
}

TEST(LibraryReading, MalformedJsonNamesFileAndPosition) {
  const auto root = fresh_temp_folder("malformed");
  const auto file = root / "cases" / "broken.json";
  write_text(file, "{\n  \"schema\": \"rbcal.case/1\",\n  \"params\": {\"Ca\": 0.1,,}\n}\n");
  const std::string message = error_of([&] { read_library(root); });
  EXPECT_NE(message.find(file.string() + ": invalid JSON"), std::string::npos) << message;
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
}

TEST(LibraryReading, RejectsCasesWithOtherNumericsNamingBothFiles) {
  const std::vector<std::pair<std::string, std::function<void(nlohmann::json&)>>> table = {
      {"numerics.N_a", [](auto& j) { j["numerics"]["N_a"] = 8; }},
      {"numerics.box", [](auto& j) { j["numerics"]["box"] = {16.0, 10.0, 16.0}; }},
      {"numerics.tau_out", [](auto& j) { j["numerics"]["tau_out"] = 0.8; }},
      {"numerics.kernel", [](auto& j) { j["numerics"]["kernel"] = "peskin3"; }},
      {"cells.triangles", [](auto& j) { j["cells"]["triangles"] = 1280; }},
      {"cells.shape", [](auto& j) { j["cells"]["shape"] = "sphere"; }},
      {"cells.law", [](auto& j) { j["cells"]["law"] = "neo-hookean"; }},
      {"run.window", [](auto& j) { j["run"]["window"] = {40.0, 100.0}; }},
      {"params.kb_hat", [](auto& j) { j["params"]["kb_hat"] = 0.0; }},
      {"cells.profile", [](auto& j) { j["cells"]["profile"] = "seed"; }},
      {"cells.skalak_c", [](auto& j) { j["cells"]["skalak_c"] = 10.0; }},
      {"cells.skalak_c_per_Ca", [](auto& j) { j["cells"]["skalak_c_per_Ca"] = 125.0; }},
      // Equivalent on two dense cases (docs/performance.md), but not shown for every case.
      {"numerics.integrator", [](auto& j) { j["numerics"]["integrator"] = "euler"; }},
      {"numerics.indicator_tolerance", [](auto& j) { j["numerics"]["indicator_tolerance"] = 0.1; }},
      {"numerics.coupling_interval", [](auto& j) { j["numerics"]["coupling_interval"] = 2; }},
      {"numerics.volume_stiffness", [](auto& j) { j["numerics"]["volume_stiffness"] = 100.0; }},
  };
  for (const auto& [field, change] : table) {
    SCOPED_TRACE(field);
    const auto root = fresh_temp_folder("numerics_" + field);
    write_text(root / "cases" / "a.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
    nlohmann::json other = case_json(0.2, 0.1, 5.0, 0.2, 1.7, 0.01);
    change(other);
    write_text(root / "cases" / "b.json", other.dump());
    const std::string message = error_of([&] { read_library(root); });
    EXPECT_NE(message.find((root / "cases" / "b.json").string() + ": field " + field), std::string::npos) << message;
    EXPECT_NE(message.find((root / "cases" / "a.json").string()), std::string::npos) << message;
  }
}

TEST(LibraryReading, RejectsTwoCasesWithTheSameParameters) {
  const auto root = fresh_temp_folder("duplicate");
  write_text(root / "cases" / "first.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
  write_text(root / "cases" / "second.json", case_json(0.1, 0.1, 5.0, 0.102, 1.31, 0.01).dump());
  write_text(root / "cases" / "third.json", case_json(0.1, 0.2, 5.0, 0.1, 1.2, 0.01).dump());
  const std::string message = error_of([&] { read_library(root); });
  EXPECT_NE(message.find("second.json: same (phi, Ca, lambda)"), std::string::npos) << message;
  EXPECT_NE(message.find("first.json"), std::string::npos) << message;
}

TEST(LibraryReading, RejectsMissingOrEmptyCaseFolder) {
  const auto root = fresh_temp_folder("empty");
  EXPECT_NE(error_of([&] { read_library(root); }).find("cases: missing"), std::string::npos);
  std::filesystem::create_directories(root / "cases");
  EXPECT_NE(error_of([&] { read_library(root); }).find("no finished cases"), std::string::npos);
}

TEST(LibrarySummary, MarksPresentAndMissingPlanPoints) {
  const auto root = fresh_temp_folder("summary");
  write_text(root / "plan.json",
             R"({"schema": "rbcal.plan/1", "grid": {"phi": [0.1, 0.2], "Ca": [0.1, 0.4], "lambda": [5]}})");
  write_text(root / "cases" / "a.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
  write_text(root / "cases" / "b.json", case_json(0.2, 0.4, 5.0, 0.2, 1.5, 0.03).dump());
  write_text(root / "cases" / "c.json", case_json(0.3, 0.4, 5.0, 0.3, 1.9, 0.02).dump());  // off the plan
  const LibrarySummary s = summarise(read_library(root));
  EXPECT_TRUE(s.grid_from_plan);
  EXPECT_EQ(s.case_count, 3u);
  ASSERT_EQ(s.grid_points.size(), 4u);
  EXPECT_EQ(s.missing_count, 2u);
  EXPECT_EQ(s.off_grid_count, 1u);
  for (const GridPoint& p : s.grid_points)
    EXPECT_EQ(p.present, (p.phi == 0.1 && p.capillary_number == 0.1) || (p.phi == 0.2 && p.capillary_number == 0.4));
  EXPECT_DOUBLE_EQ(s.total_wall_seconds, 3 * 12.5);
  EXPECT_DOUBLE_EQ(s.median_eta_re_sem, 0.02);
  EXPECT_DOUBLE_EQ(s.nominal_range.phi_max, 0.3);
  const std::string text = format_summary(s);
  EXPECT_NE(text.find("2 present, 2 missing"), std::string::npos) << text;
  // With values: the phi 0.1 row shows a's eta_re under Ca 0.1 and '.' under Ca 0.4;
  // the phi 0.2 row '.' then b's.
  const std::string with_values = format_summary(s, true);
  EXPECT_NE(with_values.find("phi 0.1      1.3       .\n"), std::string::npos) << with_values;
  EXPECT_NE(with_values.find("phi 0.2        .     1.5\n"), std::string::npos) << with_values;
}

// A listed design: present and missing points are those of the list, shown one per line.
TEST(LibrarySummary, MarksPresentAndMissingPointsOfAListedDesign) {
  const auto root = fresh_temp_folder("summary_listed");
  write_text(root / "plan.json", R"({"schema": "rbcal.plan/1", "points": [[0.1, 0.1, 5], [0.3, 0.02, 1], [0.5, 2, 10]]})");
  write_text(root / "cases" / "a.json", case_json(0.3, 0.02, 1.0, 0.3, 2.5, 0.01).dump());
  const LibrarySummary s = summarise(read_library(root));
  EXPECT_TRUE(s.listed_design);
  ASSERT_EQ(s.grid_points.size(), 3u);
  EXPECT_EQ(s.missing_count, 2u);
  EXPECT_TRUE(s.grid_points[1].present);
  const std::string text = format_summary(s, true);
  EXPECT_NE(text.find("listed design of 3 points, 1 present, 2 missing"), std::string::npos) << text;
  EXPECT_NE(text.find("phi 0.3    Ca 0.02    lambda 1       eta_re 2.5"), std::string::npos) << text;
  EXPECT_NE(text.find("phi 0.5    Ca 2       lambda 10      . missing"), std::string::npos) << text;
}

// Without a plan, cases that do not fill a grid (a space-filling design) are listed one per
// line, not shown as a mostly empty grid of their unique values (3 x 3 x 3 here).
TEST(LibrarySummary, ListsScatteredCasesWithoutAPlan) {
  const auto root = fresh_temp_folder("summary_scattered");
  write_text(root / "cases" / "a.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
  write_text(root / "cases" / "b.json", case_json(0.3, 0.02, 1.0, 0.3, 2.5, 0.01).dump());
  write_text(root / "cases" / "c.json", case_json(0.5, 2.0, 10.0, 0.5, 3.5, 0.01).dump());
  const LibrarySummary s = summarise(read_library(root));
  EXPECT_FALSE(s.grid_from_plan);
  EXPECT_TRUE(s.listed_design);
  ASSERT_EQ(s.grid_points.size(), 3u);
  EXPECT_EQ(s.missing_count, 0u);
  const std::string text = format_summary(s, true);
  EXPECT_NE(text.find("listed design of 3 points, 3 present, 0 missing"), std::string::npos) << text;
  EXPECT_NE(text.find("phi 0.3    Ca 0.02    lambda 1       eta_re 2.5"), std::string::npos) << text;
}

TEST(LibrarySummary, RejectsPlanWithBadGrid) {
  const auto root = fresh_temp_folder("bad_plan");
  write_text(root / "plan.json", R"({"schema": "rbcal.plan/1", "grid": {"phi": [0.1, 1.5], "Ca": [0.1], "lambda": [5]}})");
  write_text(root / "cases" / "a.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
  const std::string message = error_of([&] { read_library(root); });
  EXPECT_NE(message.find("plan.json: field grid.phi"), std::string::npos) << message;
}

// A plan's shear-modulus cap lowers Re for its low-Ca cases (solver/sweep/sweep_plan.hpp),
// so cases that differ only in Re belong to one library.
TEST(LibraryReading, AcceptsCasesThatDifferOnlyInReynoldsNumber) {
  const auto root = fresh_temp_folder("reynolds");
  write_text(root / "cases" / "a.json", case_json(0.1, 0.1, 5.0, 0.1, 1.3, 0.01).dump());
  nlohmann::json other = case_json(0.2, 0.1, 5.0, 0.2, 1.7, 0.01);
  other["numerics"]["Re"] = 0.05;
  write_text(root / "cases" / "b.json", other.dump());
  EXPECT_EQ(read_library(root).cases.size(), 2u);
}

}  // namespace
}  // namespace rbcal::surrogate
