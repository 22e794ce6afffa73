// The file formats' ground floor: errors name file and field in one shape, writes are
// atomic, the date honours SOURCE_DATE_EPOCH, plan grids obey one set of bounds, and the
// numerics signature reads an absent field as what it meant when the file was written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "formats/field_reader.hpp"
#include "formats/format_error.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/plan_grid.hpp"
#include "formats/provenance.hpp"

using namespace rbcal::formats;
using nlohmann::json;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const FormatError& e) {
    return e.what();
  }
  return "(no FormatError)";
}

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("rbcal_formats_" + std::to_string(::getpid()) + "_" + name);
}

json library_case(double tolerance_or_absent) {
  json j = {{"schema", kCaseSchema},
            {"params", {{"phi", 0.2}, {"Ca", 0.1}, {"lambda", 5.0}}},
            {"cells", {{"law", "skalak"}, {"shape", "biconcave"}, {"triangles", 320}}},
            {"numerics", {{"N_a", 4}, {"box", {6.0, 8.0, 6.0}}, {"tau_out", 1.0}, {"kernel", "peskin4"}}},
            {"run", {{"window", {5.0, 15.0}}}}};
  if (tolerance_or_absent >= 0.0) j["numerics"]["indicator_tolerance"] = tolerance_or_absent;
  return j;
}

}  // namespace

TEST(FieldReader, NamesFileAndDottedFieldInOneShape) {
  const json j = {{"run", {{"window", {5.0, "x"}}}}, {"training", {{{"phi", -1.0}}}}, {"n", 3.5}};
  const FieldReader r(j, "f.json");
  EXPECT_EQ(error_of([&] { r.numbers("run.window", 2); }),
            "f.json: field run.window: must be an array of at least 2 finite numbers");
  EXPECT_EQ(error_of([&] { r.positive("training.0.phi"); }), "f.json: field training.0.phi: must be a positive number");
  EXPECT_EQ(error_of([&] { r.text("absent.field"); }), "f.json: field absent.field: missing");
  EXPECT_EQ(error_of([&] { r.integer_or("n", 1, 0, 10); }), "f.json: field n: must be an integer");
  EXPECT_EQ(error_of([&] { r.number_or("n", 1.0, 0.0, 2.0); }), "f.json: field n: must be in [0, 2], got 3.5");
  // A scalar where an object is expected is an error, not an absent field.
  EXPECT_EQ(error_of([&] { r.number_or("n.sub", 1.0, 0.0, 2.0); }), "f.json: field n.sub: parent is not an object");
  EXPECT_EQ(r.number_or("absent", 1.25, 0.0, 2.0), 1.25);
  EXPECT_EQ((r.numbers_or<2>("absent", {1.0, 2.0})), (std::array<double, 2>{1.0, 2.0}));
}

// The one check every reader starts with (surrogate, family, case, plan, simulation case).
TEST(FieldReader, ExpectsAnObjectOfTheGivenSchema) {
  EXPECT_NO_THROW(FieldReader(json{{"schema", "rbcal.x/1"}}, "f.json").expect_schema("rbcal.x/1"));
  EXPECT_EQ(error_of([&] { FieldReader(json::array({1, 2}), "f.json").expect_schema("rbcal.x/1"); }),
            "f.json: field (top level): must be a JSON object");
  EXPECT_EQ(error_of([&] { FieldReader(json{{"a", 1}}, "f.json").expect_schema("rbcal.x/1"); }),
            "f.json: field schema: missing");
  EXPECT_EQ(error_of([&] { FieldReader(json{{"schema", "rbcal.x/2"}}, "f.json").expect_schema("rbcal.x/1"); }),
            "f.json: field schema: must be \"rbcal.x/1\", got \"rbcal.x/2\"");
}

TEST(JsonFile, ReportsSyntaxErrorsWithLineAndWritesAtomically) {
  const auto file = temp_file("syntax.json");
  write_file_atomically(file, "{\n  \"a\": 1,,\n}\n");
  const std::string message = error_of([&] { read_json_file(file); });
  EXPECT_EQ(message.rfind(file.string() + ": invalid JSON", 0), 0u) << message;
  EXPECT_NE(message.find("line 2"), std::string::npos) << message;
  EXPECT_EQ(error_of([&] { read_json_file(temp_file("absent.json")); }),
            temp_file("absent.json").string() + ": cannot open: No such file or directory");
  // A folder given as a file was reported as "invalid JSON (byte 1)".
  std::filesystem::create_directories(temp_file("folder.json"));
  EXPECT_EQ(error_of([&] { read_json_file(temp_file("folder.json")); }),
            temp_file("folder.json").string() + ": is a folder, not a JSON file");

  // Found by fuzzing: a number beyond double's range was not reported as the file's error.
  EXPECT_EQ(error_of([&] { parse_json_text("{\"a\": 1e999}", "big.json"); }).rfind("big.json: invalid JSON", 0), 0u);

  write_json_atomically(file, {{"a", 1}});
  EXPECT_EQ(read_json_file(file), (json{{"a", 1}}));
  // No temporary file is left behind.
  for (const auto& e : std::filesystem::directory_iterator(file.parent_path()))
    EXPECT_EQ(e.path().string().find(file.string() + ".tmp"), std::string::npos) << e.path();
  std::filesystem::remove(file);
  // A folder that does not exist: a clear error naming the file, nothing written.
  const auto nowhere = temp_file("no_such_folder") / "x.json";
  try {
    write_json_atomically(nowhere, {{"a", 1}});
    FAIL() << "wrote into a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(nowhere.string() + ": cannot write", 0), 0u) << e.what();
  }
}

TEST(Provenance, DateHonoursSourceDateEpoch) {
  setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  const json p = provenance_block();
  unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_EQ(p["date"], "2023-11-14T22:13:20Z");  // date -u -d @1700000000
  for (const char* key : {"rbcal_version", "git_revision", "host"}) EXPECT_TRUE(p.contains(key)) << key;
}

TEST(PlanGrid, OneSetOfBoundsAndDistinctValues) {
  const json ok = {{"schema", kPlanSchema}, {"grid", {{"phi", {0.1, 0.55}}, {"Ca", {0.01, 3.2}}, {"lambda", {5}}}}};
  EXPECT_EQ(plan_grid_from_json(ok, "p.json").size(), 4u);
  json bad = ok;
  bad["grid"]["phi"] = {0.1, 0.8};
  EXPECT_EQ(error_of([&] { plan_grid_from_json(bad, "p.json"); }),
            "p.json: field grid.phi: values must lie in [0.0001, 0.7], got 0.8");
  bad = ok;
  bad["grid"]["Ca"] = {0.1, 0.1};
  EXPECT_EQ(error_of([&] { plan_grid_from_json(bad, "p.json"); }), "p.json: field grid.Ca: value 0.1 appears twice");
  bad = ok;
  bad["schema"] = "rbcal.plan/0";
  EXPECT_NE(error_of([&] { plan_grid_from_json(bad, "p.json"); }).find("p.json: field schema"), std::string::npos);
}

// A space-filling design lists its points; the grid's order and the list's are kept by
// points(), and a listed point obeys the same bounds, named by its index.
TEST(PlanGrid, ListedPointsKeepTheirOrderAndObeyTheBounds) {
  const json listed = {{"schema", kPlanSchema}, {"points", {{0.55, 3.2, 10}, {0.05, 0.01, 0.1}, {0.3, 0.1, 5}}}};
  const ParameterGrid g = plan_grid_from_json(listed, "p.json");
  ASSERT_TRUE(g.is_listed());
  EXPECT_EQ(g.size(), 3u);
  const std::vector<ParameterPoint> points = g.points();
  EXPECT_EQ(points[0].phi, 0.55);
  EXPECT_EQ(points[1].capillary_number, 0.01);
  EXPECT_EQ(points[2].viscosity_ratio, 5.0);
  EXPECT_EQ(g.phi, (std::vector<double>{0.05, 0.3, 0.55}));  // the distinct values, sorted
  json bad = listed;
  bad["points"][1] = {0.05, 0.01, 2000};
  EXPECT_EQ(error_of([&] { plan_grid_from_json(bad, "p.json"); }),
            "p.json: field points.1: lambda must lie in [0.001, 1000], got 2000");
  bad = listed;
  bad["points"][2] = {0.55, 3.2, 10};
  EXPECT_EQ(error_of([&] { plan_grid_from_json(bad, "p.json"); }), "p.json: field points.2: appears twice");
  bad = listed;
  bad["points"][0] = {0.55, 3.2};
  EXPECT_EQ(error_of([&] { plan_grid_from_json(bad, "p.json"); }), "p.json: field points.0: must be [phi, Ca, lambda]");
  bad = listed;
  bad["grid"] = {{"phi", {0.1}}, {"Ca", {0.1}}, {"lambda", {5}}};
  EXPECT_EQ(error_of([&] { plan_grid_from_json(bad, "p.json"); }),
            "p.json: field points: a plan has a grid or points, not both");
  // A grid's points: lambda-major, then Ca, then phi (the sweep's case order).
  const json grid = {{"schema", kPlanSchema}, {"grid", {{"phi", {0.1, 0.2}}, {"Ca", {0.1, 1}}, {"lambda", {1, 5}}}}};
  const std::vector<ParameterPoint> order = plan_grid_from_json(grid, "p.json").points();
  ASSERT_EQ(order.size(), 8u);
  EXPECT_EQ(order[1].phi, 0.2);
  EXPECT_EQ(order[2].capillary_number, 1.0);
  EXPECT_EQ(order[4].viscosity_ratio, 5.0);
}

TEST(NumericsSignature, AbsentFieldsMeanWhatTheyMeantWhenWritten) {
  // Written before indicator_tolerance existed: the inside fraction was rebuilt every step.
  const json old_file = numerics_signature(library_case(-1.0), "old.json");
  EXPECT_EQ(old_file["numerics.indicator_tolerance"], 0.0);
  EXPECT_EQ(old_file["numerics.integrator"], "rk4");
  EXPECT_EQ(old_file["numerics.coupling_interval"], 1);
  EXPECT_FALSE(first_signature_difference(old_file, numerics_signature(library_case(0.0), "zero.json")));
  EXPECT_EQ(first_signature_difference(old_file, numerics_signature(library_case(0.1), "new.json")),
            "numerics.indicator_tolerance");
  json no_kernel = library_case(0.0);
  no_kernel["numerics"].erase("kernel");
  EXPECT_EQ(error_of([&] { numerics_signature(no_kernel, "k.json"); }), "k.json: field numerics.kernel: missing");
}

// Before numerics.node_velocity existed an interval moved the membrane by its last step's
// velocity; at one fluid step per membrane step the field means nothing and compares as null.
TEST(NumericsSignature, NodeVelocityCountsOnlyForAnIntervalAboveOne) {
  json one = library_case(0.1), two = library_case(0.1);
  two["numerics"]["coupling_interval"] = 2;
  EXPECT_EQ(numerics_signature(one, "one.json")["numerics.node_velocity"], nullptr);
  EXPECT_EQ(numerics_signature(two, "two.json")["numerics.node_velocity"], "last_step");
  json one_mean = one, two_mean = two;
  one_mean["numerics"]["node_velocity"] = "interval_mean";
  two_mean["numerics"]["node_velocity"] = "interval_mean";
  EXPECT_FALSE(first_signature_difference(numerics_signature(one, "a.json"), numerics_signature(one_mean, "b.json")));
  EXPECT_EQ(first_signature_difference(numerics_signature(two, "a.json"), numerics_signature(two_mean, "b.json")),
            "numerics.node_velocity");
}

TEST(LibraryLayout, CaseIdsAndPaths) {
  EXPECT_EQ(case_id(0.21, 0.1, 5.0), "phi0.21_Ca0.1_lambda5");
  EXPECT_EQ(library_layout::case_result("LIB", "x"), std::filesystem::path("LIB/cases/x.json"));
  EXPECT_EQ(library_layout::plan("LIB"), std::filesystem::path("LIB/plan.json"));
}
