// The box correction's prior from anchor runs (surrogate/box_anchors.hpp) against a hand
// computation on a known law, and its errors naming the file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <string>

#include "formats/json_file.hpp"
#include "surrogate/box_anchors.hpp"
#include "surrogate/model_recipe.hpp"
#include "surrogate/simulation_library.hpp"

namespace rbcal::surrogate {
namespace {

namespace fs = std::filesystem;
const fs::path kLibrary = RBCAL_DEFAULT_LIBRARY;

// ln eta_re = 2 phi, exactly.
class ExponentialLaw : public PointwiseViscosityModel {
 public:
  ViscosityPrediction predict_point(double phi, double, double, const NuisanceValues&) const override {
    ViscosityPrediction p;
    p.eta_re = std::exp(2.0 * phi);
    return p;
  }
  ParameterRange range() const override { return {0.0, 0.6, 0.001, 100.0, 0.1, 10.0}; }
};

struct AnchorFiles {
  fs::path dir;
  nlohmann::json run;
  fs::path write(const std::string& name, double phi_actual, double eta, double sem) {
    run["result"]["phi_actual"] = phi_actual;
    run["result"]["eta_re"] = eta;
    run["result"]["eta_re_sem"] = sem;
    formats::write_json_atomically(dir / name, run);
    return dir / name;
  }
};

AnchorFiles anchor_files(const std::string& name) {
  AnchorFiles f;
  f.dir = fs::temp_directory_path() / ("rbcal_box_anchors_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(f.dir);
  fs::create_directories(f.dir);
  f.run = formats::read_json_file(read_library(kLibrary.parent_path() / "v2" / "n8").cases.front().source);
  return f;
}

// phi_eff = 1.5 phi_actual; twins with m = 0.08.
const EffectivePhi kPhiEff = [](const LibraryCase& r) { return 1.5 * r.phi_actual; };

BoxTwinPrior twins_with_mean(double m) {
  BoxTwinPrior t;
  t.mean_beta = m;
  return t;
}

// Two anchors at beta -0.1 and +0.1 of the law: n 0, s sqrt(0.02); with no standard errors the
// prior is n + 0.5 m = 0.04, sd sqrt(s^2 + (0.5 m)^2) = sqrt(0.02 + 0.0016).
TEST(BoxAnchors, PriorFromAnchorsAsTheFormulaSays) {
  AnchorFiles f = anchor_files("formula");
  const ExponentialLaw law;
  const double m1 = std::exp(2.0 * 1.5 * 0.2), m2 = std::exp(2.0 * 1.5 * 0.3);  // the law at phi_eff
  const fs::path a = f.write("a.json", 0.2, std::pow(m1, 0.9), 0.0);
  const fs::path b = f.write("b.json", 0.3, std::pow(m2, 1.1), 0.01);
  const BoxAnchorPrior p = box_anchor_prior({a, b}, law, kPhiEff, {8}, twins_with_mean(0.08));
  ASSERT_EQ(p.anchors.size(), 2u);
  EXPECT_NEAR(p.anchors[0].phi_eff, 0.3, 1e-15);
  EXPECT_NEAR(p.anchors[0].model_eta_re, m1, 1e-12);
  EXPECT_NEAR(p.anchors[0].beta, -0.1, 1e-13);
  EXPECT_NEAR(p.anchors[1].beta, 0.1, 1e-13);
  // se = sem / (eta ln eta_model)
  const double se = 0.01 / (std::pow(m2, 1.1) * std::log(m2));
  EXPECT_NEAR(p.anchors[1].beta_se, se, 1e-15);
  EXPECT_NEAR(p.mean_beta, 0.0, 1e-13);
  EXPECT_NEAR(p.scatter, std::sqrt(0.02), 1e-13);
  EXPECT_NEAR(p.mean_se, se / 2.0, 1e-15);
  EXPECT_NEAR(p.mean, 0.04, 1e-13);
  EXPECT_NEAR(p.sd, std::sqrt(0.02 + 0.0016 + se * se / 4.0), 1e-13);
  EXPECT_NE(describe_box_anchors(p).find("2 anchors"), std::string::npos);
  fs::remove_all(f.dir);
}

// Anchors of two resolutions: the step of each tier beside the pooled one (two N_a 8 anchors at
// beta -0.1 and +0.1, one N_a 12 anchor at +0.3: tiers 0 and +0.3, pooled +0.1).
TEST(BoxAnchors, StepPerResolution) {
  AnchorFiles f = anchor_files("tiers");
  const ExponentialLaw law;
  const double m1 = std::exp(2.0 * 1.5 * 0.2), m2 = std::exp(2.0 * 1.5 * 0.3);
  const fs::path a = f.write("a.json", 0.2, std::pow(m1, 0.9), 0.0);
  const fs::path b = f.write("b.json", 0.3, std::pow(m2, 1.1), 0.0);
  f.run["numerics"]["N_a"] = 12;
  const fs::path c = f.write("c.json", 0.3, std::pow(m2, 1.3), 0.0);
  const BoxAnchorPrior p = box_anchor_prior({a, b, c}, law, kPhiEff, {6, 8}, twins_with_mean(0.0));
  ASSERT_EQ(p.by_resolution.size(), 2u);
  EXPECT_EQ(p.by_resolution[0].nodes_per_radius, 8);
  EXPECT_EQ(p.by_resolution[0].count, 2u);
  EXPECT_NEAR(p.by_resolution[0].spread.mean, 0.0, 1e-13);
  EXPECT_NEAR(p.by_resolution[0].spread.scatter, std::sqrt(0.02), 1e-13);
  EXPECT_EQ(p.by_resolution[1].nodes_per_radius, 12);
  EXPECT_NEAR(p.by_resolution[1].spread.mean, 0.3, 1e-13);
  EXPECT_NEAR(p.mean_beta, 0.1, 1e-13);
  EXPECT_NE(describe_box_anchors(p).find("at N_a 12: 1 anchors, mean beta +0.300"), std::string::npos)
      << describe_box_anchors(p);
  fs::remove_all(f.dir);
}

// An anchor coarser than the library's runs, or outside the model's range, is refused with its
// file named; so is an empty list. One finer than the library's is taken.
TEST(BoxAnchors, RefusesAnchorsTheModelCannotRead) {
  AnchorFiles f = anchor_files("errors");
  const ExponentialLaw law;
  const fs::path a = f.write("at_n8.json", 0.2, 2.0, 0.01);
  const fs::path dense = f.write("too_dense.json", 0.5, 5.0, 0.01);  // phi_eff 0.75 > 0.6
  auto message = [&](const std::vector<fs::path>& files, const std::vector<int>& resolutions) -> std::string {
    try {
      box_anchor_prior(files, law, kPhiEff, resolutions, twins_with_mean(0.05));
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string resolution = message({a}, {10, 12});
  EXPECT_NE(resolution.find("at_n8.json"), std::string::npos) << resolution;
  EXPECT_NE(resolution.find("N_a 8 is coarser"), std::string::npos) << resolution;
  // A finer run than the library's is read at its own resolution.
  EXPECT_EQ(message({a}, {6}), "accepted");
  const std::string range = message({a, dense}, {8});
  EXPECT_NE(range.find("too_dense.json"), std::string::npos) << range;
  EXPECT_NE(range.find("outside the model's range"), std::string::npos) << range;
  EXPECT_NE(message({}, {8}).find("no anchor"), std::string::npos);
  fs::remove_all(f.dir);
}

// The recipe's "box_correction.anchors": each path must exist, named by its index.
TEST(BoxAnchors, RecipeNamesAMissingAnchorByItsIndex) {
  nlohmann::json j = formats::read_json_file(kLibrary / "recipe.json");
  j["box_correction"]["anchors"] = {"../anchors/results/n8_phieff0.40_Ca2_lambda5.result.json", "nowhere.json"};
  try {
    model_recipe_from_json(j, kLibrary / "recipe.json");
    FAIL() << "a missing anchor was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("box_correction.anchors.1"), std::string::npos) << e.what();
  }
  j["box_correction"]["anchors"] = {"../anchors/results/n8_phieff0.40_Ca2_lambda5.result.json"};
  EXPECT_EQ(model_recipe_from_json(j, kLibrary / "recipe.json").box_anchors.size(), 1u);
}

}  // namespace
}  // namespace rbcal::surrogate
