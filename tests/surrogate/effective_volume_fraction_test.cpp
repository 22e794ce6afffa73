// The effective volume fraction (surrogate/effective_volume_fraction.hpp) on runs that obey
// its model exactly: eta_re of a run at phi and N_a is the continuum's at g(N_a) phi, with
// g = (1 + c / N_a)^3 (a sphere thickened by c lattice spacings):
//  - each run moves to g phi with its eta_re, and runs beyond phi_max are left out;
//  - a surrogate of two tiers (N_a 6 and 8, different points) recovers the continuum,
//    which neither tier shows as run;
//  - the offset's uncertainty widens each case's sd by ln(eta_re) s_g / g;
//  - the written cases form one library across resolutions; raw tiers mixed are refused,
//    and tiers that differ in more than N_a cannot be mapped together.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "surrogate/effective_volume_fraction.hpp"
#include "surrogate/library_summary.hpp"
#include "surrogate/viscosity_surrogate.hpp"
#include "synthetic_library.hpp"

using namespace rbcal::surrogate;
using namespace rbcal::surrogate::testing;

namespace {

constexpr double kOffset = 0.8;  // lattice spacings
double sphere_ratio(double offset_over_radius) { return std::pow(1.0 + offset_over_radius, 3); }
double g(int n_a) { return sphere_ratio(kOffset / n_a); }

// root/cases: runs at N_a n_a of `count` random points with phi as run in [0.03, 0.35].
void write_tier(const std::filesystem::path& root, int n_a, int count, unsigned seed) {
  std::filesystem::create_directories(root / "cases");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const double phi = 0.03 + 0.32 * u(rng), ca = 0.01 * std::pow(80.0, u(rng)), lambda = 0.5 * std::pow(20.0, u(rng));
    const double phi_actual = phi * (1.0 + 0.04 * (u(rng) - 0.5));  // seeding misses phi by a little
    const double eta = std::exp(known_log_viscosity(g(n_a) * phi_actual, ca, lambda));
    nlohmann::json j = case_json(phi, ca, lambda, phi_actual, eta, 1e-3 * eta);
    j["numerics"]["N_a"] = n_a;
    char id[96];
    std::snprintf(id, sizeof id, "phi%.6g_Ca%.6g_lambda%.6g", phi, ca, lambda);
    write_text(root / "cases" / (std::string(id) + ".json"), j.dump());
  }
}

EffectiveVolumeFractionOptions options(double offset_sd, double phi_max = 0.6) {
  EffectiveVolumeFractionOptions o;
  o.offset = kOffset;
  o.offset_sd = offset_sd;
  o.phi_max = phi_max;
  return o;
}

}  // namespace

TEST(EffectiveVolumeFraction, MovesEachRunToItsThickenedVolumeFraction) {
  const auto root = fresh_temp_folder("evf_move");
  write_tier(root / "n6", 6, 30, 1);
  const SimulationLibrary tier = read_library(root / "n6");
  const MappedLibrary m = map_to_effective_volume_fraction({tier}, sphere_ratio, options(0.0, 0.4));
  ASSERT_EQ(m.cases.size() + m.left_out.size(), tier.cases.size());
  EXPECT_FALSE(m.left_out.empty());
  EXPECT_FALSE(m.cases.empty());
  for (const MappedCase& c : m.cases) {
    EXPECT_NEAR(c.volume_ratio, g(6), 1e-12);
    EXPECT_NEAR(c.phi, g(6) * c.raw.phi, 1e-12);
    EXPECT_NEAR(c.phi_actual, g(6) * c.raw.phi_actual, 1e-12);
    EXPECT_LE(c.phi_actual, 0.4);
    // With no uncertainty in the offset and no scatter floor, the sd is the run's own.
    EXPECT_NEAR(c.eta_re_sd, c.raw.eta_re_sem, 1e-15);
  }
  for (const LibraryCase& c : m.left_out) EXPECT_GT(g(6) * c.phi_actual, 0.4);
}

TEST(EffectiveVolumeFraction, CutsOnTheVolumeFractionTheSurrogateSees) {
  // A run seeded at phi_actual 0.32 for a nominal 0.30: the surrogate's input is g phi_actual,
  // so phi_max between g 0.30 and g 0.32 leaves it out.
  const auto root = fresh_temp_folder("evf_cut");
  std::filesystem::create_directories(root / "n6" / "cases");
  nlohmann::json j = case_json(0.30, 0.1, 1.0, 0.32, 3.0, 0.01);
  j["numerics"]["N_a"] = 6;
  write_text(root / "n6" / "cases" / "phi0.3_Ca0.1_lambda1.json", j.dump());
  const SimulationLibrary tier = read_library(root / "n6");
  const double between = 0.31 * g(6);
  EXPECT_EQ(map_to_effective_volume_fraction({tier}, sphere_ratio, options(0.0, between)).left_out.size(), 1u);
  EXPECT_EQ(map_to_effective_volume_fraction({tier}, sphere_ratio, options(0.0, 0.33 * g(6))).cases.size(), 1u);
}

TEST(EffectiveVolumeFraction, TwoResolutionsGiveTheContinuum) {
  const auto root = fresh_temp_folder("evf_continuum");
  write_tier(root / "n6", 6, 40, 2);
  write_tier(root / "n8", 8, 40, 3);
  const MappedLibrary m = map_to_effective_volume_fraction({read_library(root / "n6"), read_library(root / "n8")},
                                                           sphere_ratio, options(0.0));
  // The runs as they are (both tiers at their own phi) cannot be one surface: the same
  // fit on them misses the continuum by far more.
  std::vector<TrainingCase> as_run;
  for (const MappedCase& c : m.cases) as_run.push_back(training_case(c.raw));
  const ViscositySurrogate unmapped = ViscositySurrogate::fit(as_run, "as run");
  EXPECT_GT(unmapped.predict(0.4, 0.1, 2.0).eta_re / std::exp(known_log_viscosity(0.4, 0.1, 2.0)), 1.15);
  std::vector<TrainingCase> training;
  for (const MappedCase& c : m.cases) {
    TrainingCase t = training_case(c.raw);
    t.phi = c.phi_actual;
    t.noise_variance = std::pow(c.eta_re_sd / c.raw.eta_re, 2);
    training.push_back(t);
  }
  const ViscositySurrogate model = ViscositySurrogate::fit(training, "mapped");
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20; ++i) {
    const double phi = 0.1 + 0.35 * u(rng), ca = 0.02 * std::pow(20.0, u(rng)), lambda = 1.0 * std::pow(5.0, u(rng));
    const double truth = std::exp(known_log_viscosity(phi, ca, lambda));
    const ViscosityPrediction p = model.predict(phi, ca, lambda);
    EXPECT_NEAR(p.eta_re / truth, 1.0, 0.03) << phi << " " << ca << " " << lambda;
  }
}

TEST(EffectiveVolumeFraction, TheOffsetsUncertaintyWidensEachCase) {
  const auto root = fresh_temp_folder("evf_sd");
  write_tier(root / "n8", 8, 10, 4);
  const double sd_c = 0.2;
  const MappedLibrary m = map_to_effective_volume_fraction({read_library(root / "n8")}, sphere_ratio, options(sd_c, 0.9));
  for (const MappedCase& c : m.cases) {
    const double s_g = 0.5 * (sphere_ratio((kOffset + sd_c) / 8) - sphere_ratio((kOffset - sd_c) / 8));
    EXPECT_NEAR(c.volume_ratio_sd, s_g, 1e-12);
    const double expected = std::hypot(c.raw.eta_re_sem, c.raw.eta_re * std::log(c.raw.eta_re) * s_g / g(8));
    EXPECT_NEAR(c.eta_re_sd, expected, 1e-12 * expected);
    EXPECT_EQ(c.run_sd, c.raw.eta_re_sem);  // the run's own error keeps no share of the offset
  }
}

TEST(EffectiveVolumeFraction, WrittenCasesFormOneLibraryAcrossResolutions) {
  const auto root = fresh_temp_folder("evf_written");
  write_tier(root / "n6", 6, 8, 5);
  write_tier(root / "n8", 8, 8, 6);
  const SimulationLibrary n6 = read_library(root / "n6"), n8 = read_library(root / "n8");
  // Raw runs at two resolutions are no library.
  std::vector<LibraryCase> raw = n6.cases;
  raw.insert(raw.end(), n8.cases.begin(), n8.cases.end());
  EXPECT_THROW(check_library_consistency(raw), std::exception);

  const auto o = options(0.1);
  const MappedLibrary m = map_to_effective_volume_fraction({n6, n8}, sphere_ratio, o);
  std::filesystem::create_directories(root / "mapped" / "cases");
  for (const MappedCase& c : m.cases)
    write_text(root / "mapped" / "cases" / (mapped_case_id(c) + ".json"), mapped_case_json(c, o).dump());
  const SimulationLibrary mapped = read_library(root / "mapped");
  ASSERT_EQ(mapped.cases.size(), m.cases.size());
  for (const LibraryCase& c : mapped.cases) {
    EXPECT_EQ(c.extrapolation_method, "effective volume fraction");
    ASSERT_EQ(c.raw_results.size(), 1u);
    EXPECT_NEAR(c.phi, g(c.raw_results[0].nodes_per_radius) * c.phi_as_run, 1e-9);
    EXPECT_EQ(c.eta_re, c.raw_results[0].eta_re);
    // The run's own error travels with the case, apart from the offset's share.
    EXPECT_EQ(c.run_sd, c.raw_results[0].eta_re_sem);
    EXPECT_GT(c.eta_re_sem, c.run_sd);
    EXPECT_NEAR(training_case(c).run_noise_variance, std::pow(c.run_sd / c.eta_re, 2), 1e-15);
  }
  EXPECT_NE(format_summary(summarise(mapped)).find("(run at phi"), std::string::npos);
}

TEST(EffectiveVolumeFraction, RefusesCasesAlreadyMapped) {
  const auto root = fresh_temp_folder("evf_twice");
  write_tier(root / "n6", 6, 3, 10);
  const auto o = options(0.1);
  const MappedLibrary m = map_to_effective_volume_fraction({read_library(root / "n6")}, sphere_ratio, o);
  std::filesystem::create_directories(root / "mapped" / "cases");
  for (const MappedCase& c : m.cases)
    write_text(root / "mapped" / "cases" / (mapped_case_id(c) + ".json"), mapped_case_json(c, o).dump());
  try {
    map_to_effective_volume_fraction({read_library(root / "mapped")}, sphere_ratio, o);
    FAIL() << "mapped cases were mapped again";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("already effective volume fraction"), std::string::npos) << e.what();
  }
}

TEST(EffectiveVolumeFraction, RefusesTiersThatDifferInMoreThanTheResolution) {
  const auto root = fresh_temp_folder("evf_refuse");
  write_tier(root / "n6", 6, 3, 7);
  write_tier(root / "box", 8, 3, 8);
  for (const auto& e : std::filesystem::directory_iterator(root / "box" / "cases")) {
    nlohmann::json j = nlohmann::json::parse(std::ifstream(e.path()));
    j["numerics"]["box"] = {6.0, 16.0, 6.0};
    write_text(e.path(), j.dump());
  }
  try {
    map_to_effective_volume_fraction({read_library(root / "n6"), read_library(root / "box")}, sphere_ratio, options(0.1));
    FAIL() << "tiers in different boxes were mapped together";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.box"), std::string::npos) << e.what();
  }
}
