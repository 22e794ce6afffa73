// Extrapolation to the continuum from a coarse and a fine library of the same points
// (surrogate/resolution_extrapolation.hpp), on data with a known resolution error
// eta_re(h) = eta_inf (1 + K phi (h / h6)^p), h = 1 / N_a, h6 = 1 / 6:
//  - at paired points Richardson of the right order returns eta_inf exactly, and the sd
//    is half the distance to the other order's estimate (no statistical noise here);
//  - at the other points the correction model predicts eta_inf within its sd;
//  - the extrapolated library keeps both raw values and `library show` prints them;
//  - libraries that cannot be paired are refused with the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "surrogate/library_summary.hpp"
#include "surrogate/resolution_extrapolation.hpp"
#include "synthetic_library.hpp"

using namespace rbcal::surrogate;
using namespace rbcal::surrogate::testing;

namespace {

constexpr double kK = -0.6;  // eta_re at N_a 6 is 1 - 0.6 phi times the converged value

double at_resolution(double eta_inf, double phi, int n_a, double order) {
  return eta_inf * (1.0 + kK * phi * std::pow(6.0 / n_a, order));
}

struct Point {
  double phi, ca, lambda;
};

std::vector<Point> design(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> points;
  for (int i = 0; i < n; ++i)
    points.push_back({0.05 + 0.5 * u(rng), 0.01 * std::pow(320.0, u(rng)), 0.1 * std::pow(100.0, u(rng))});
  return points;
}

// Writes the cases of `points` at resolution n_a into root/cases (relative SEM 1e-4).
void write_library(const std::filesystem::path& root, const std::vector<Point>& points, int n_a, double order) {
  std::filesystem::create_directories(root / "cases");
  for (const Point& p : points) {
    const double eta = at_resolution(std::exp(known_log_viscosity(p.phi, p.ca, p.lambda)), p.phi, n_a, order);
    nlohmann::json j = case_json(p.phi, p.ca, p.lambda, p.phi, eta, 1e-4 * eta);
    j["numerics"]["N_a"] = n_a;
    char id[96];
    std::snprintf(id, sizeof id, "phi%.6g_Ca%.6g_lambda%.6g", p.phi, p.ca, p.lambda);
    write_text(root / "cases" / (std::string(id) + ".json"), j.dump());
  }
}

}  // namespace

TEST(ResolutionExtrapolation, RichardsonIsExactForTheRightOrderAndTheCorrectionModelCoversTheRest) {
  const std::vector<Point> points = design(40, 5);
  const std::vector<Point> paired(points.begin(), points.begin() + 20);
  const auto root = fresh_temp_folder("extrapolation");
  write_library(root / "n6", points, 6, 2.0);
  write_library(root / "n8", paired, 8, 2.0);
  ExtrapolationOptions second_order;  // the data's own order, and order 1 for the sd
  second_order.order = 2.0;
  second_order.order_low = 1.0;
  const auto cases = extrapolate_to_continuum(read_library(root / "n6"), read_library(root / "n8"), second_order);
  ASSERT_EQ(cases.size(), 40u);
  int paired_count = 0, covered = 0, unpaired_count = 0;
  for (const ExtrapolatedCase& c : cases) {
    const double truth = std::exp(known_log_viscosity(c.coarse.phi, c.coarse.capillary_number, c.coarse.viscosity_ratio));
    if (c.paired) {
      ++paired_count;
      EXPECT_NEAR(c.eta_re / truth, 1.0, 1e-9) << c.coarse.id;
      // Order 1 would give eta_8 + 3 (eta_8 - eta_6); order 2 eta_8 + (9/7) (eta_8 - eta_6).
      const double difference = c.fine.eta_re - c.coarse.eta_re;
      EXPECT_NEAR(c.eta_re_sd, 0.5 * std::abs((3.0 - 9.0 / 7.0) * difference), 1e-3 * c.eta_re_sd) << c.coarse.id;
      EXPECT_EQ(c.method(), "richardson");
    } else {
      ++unpaired_count;
      EXPECT_EQ(c.method(), "correction model");
      EXPECT_GT(c.eta_re_sd, 0.0);
      if (std::abs(c.eta_re - truth) <= 3.0 * c.eta_re_sd) ++covered;
      // The correction itself (up to 33 % at phi 0.55) is captured to a few percent.
      EXPECT_NEAR(c.eta_re / truth, 1.0, 0.05) << c.coarse.id;
    }
  }
  EXPECT_EQ(paired_count, 20);
  EXPECT_GE(covered, unpaired_count - 1);  // 3 sd: at most one miss in 20
}

TEST(ResolutionExtrapolation, TheLibraryKeepsTheRawValuesAndShowPrintsThem) {
  const std::vector<Point> points = design(8, 9);
  const auto root = fresh_temp_folder("extrapolated_library");
  write_library(root / "n6", points, 6, 2.0);
  write_library(root / "n8", points, 8, 2.0);  // all paired: no correction model needed
  ExtrapolationOptions options;
  options.order = 2.0;  // the data's own order
  const auto cases = extrapolate_to_continuum(read_library(root / "n6"), read_library(root / "n8"), options);
  std::filesystem::create_directories(root / "out" / "cases");
  for (const auto& c : cases)
    write_text(root / "out" / "cases" / (c.coarse.id + ".json"), extrapolated_case_json(c, options).dump());
  const SimulationLibrary out = read_library(root / "out");
  ASSERT_EQ(out.cases.size(), 8u);
  const LibraryCase& first = out.cases.front();
  EXPECT_EQ(first.extrapolation_method, "richardson");
  ASSERT_EQ(first.raw_results.size(), 2u);
  EXPECT_EQ(first.raw_results[0].nodes_per_radius, 6);
  EXPECT_EQ(first.raw_results[1].nodes_per_radius, 8);
  EXPECT_LT(first.raw_results[0].eta_re, first.raw_results[1].eta_re);  // K < 0: coarse lies lower here
  EXPECT_NEAR(first.eta_re / std::exp(known_log_viscosity(first.phi, first.capillary_number, first.viscosity_ratio)),
              1.0, 1e-9);
  const std::string shown = format_summary(summarise(out));
  EXPECT_NE(shown.find("extrapolated to the continuum"), std::string::npos) << shown;
  EXPECT_NE(shown.find("N_a 6"), std::string::npos);
  EXPECT_NE(shown.find("N_a 8"), std::string::npos);
  EXPECT_NE(shown.find("richardson"), std::string::npos);
}

TEST(ResolutionExtrapolation, TheSeedScatterFloorRaisesTheErrorOfDenseCasesOnly) {
  // Points below, inside and above the ramp phi 0.21 -> 0.41 (docs/library.md, seed twins).
  const std::vector<Point> points = {{0.10, 0.1, 1.0}, {0.31, 0.1, 1.0}, {0.50, 0.1, 1.0}};
  const auto root = fresh_temp_folder("scatter_floor");
  write_library(root / "n6", points, 6, 2.0);
  write_library(root / "n8", points, 8, 2.0);
  ExtrapolationOptions plain;
  plain.order = 2.0;  // the data's own order
  ExtrapolationOptions floored = plain;
  floored.scatter_floor = 0.05;
  const auto a = extrapolate_to_continuum(read_library(root / "n6"), read_library(root / "n8"), plain);
  const auto b = extrapolate_to_continuum(read_library(root / "n6"), read_library(root / "n8"), floored);
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const LibraryCase& c = b[i].coarse;
    const double weight = std::clamp((c.phi - 0.21) / 0.2, 0.0, 1.0);  // 0, 1/2, 1
    EXPECT_NEAR(error_with_scatter_floor(c, floored), std::hypot(c.eta_re_sem, weight * 0.05 * c.eta_re), 1e-12);
    EXPECT_EQ(b[i].eta_re, a[i].eta_re) << "the floor changes errors, not values";
    EXPECT_EQ(b[i].coarse.eta_re_sem, a[i].coarse.eta_re_sem) << "the raw cases keep their own error";
    // Richardson with g = 9/7: the floors of both runs enter as (1 + g)^2 and g^2.
    const double g = 9.0 / 7.0, sf = weight * 0.05 * b[i].fine.eta_re, sc = weight * 0.05 * c.eta_re;
    const double expected = std::sqrt(a[i].eta_re_sd * a[i].eta_re_sd + (1 + g) * (1 + g) * sf * sf + g * g * sc * sc);
    EXPECT_NEAR(b[i].eta_re_sd, expected, 1e-3 * expected) << c.id;
  }
  EXPECT_NEAR(b[0].eta_re_sd, a[0].eta_re_sd, 1e-6 * a[0].eta_re_sd);  // phi 0.10: no floor
  EXPECT_GT(b[2].eta_re_sd, a[2].eta_re_sd + 0.1);  // 5 % of eta_re near 6, times 2.6 from Richardson
}

TEST(ResolutionExtrapolation, RefusesLibrariesThatCannotBePaired) {
  const std::vector<Point> points = design(6, 3);
  const auto root = fresh_temp_folder("extrapolation_refused");
  write_library(root / "n6", points, 6, 2.0);
  write_library(root / "n8", {points[0], points[1]}, 8, 2.0);
  write_library(root / "n8_foreign", {{0.3, 0.1, 1.0}}, 8, 2.0);
  const SimulationLibrary n6 = read_library(root / "n6"), n8 = read_library(root / "n8");
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { extrapolate_to_continuum(n8, n6); }).find("is not finer than"), std::string::npos);
  EXPECT_NE(message([&] { extrapolate_to_continuum(n6, n8); }).find("2 paired points: too few"), std::string::npos);
  EXPECT_NE(message([&] { extrapolate_to_continuum(n6, read_library(root / "n8_foreign")); }).find("has no twin"),
            std::string::npos);
}
