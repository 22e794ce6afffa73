// The viscosity surrogate on libraries drawn from a known function: calibrated bands,
// derivatives, hull, leave-one-out, JSON round trip, reproducible builds, proposals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include <Eigen/Eigenvalues>

#include "surrogate/case_proposal.hpp"
#include "formats/json_file.hpp"
#include "surrogate/surrogate_file.hpp"
#include "synthetic_library.hpp"

namespace rbcal::surrogate {
namespace {

using testing::known_log_viscosity;
using testing::SyntheticGrid;
using testing::synthetic_training_cases;

const ViscositySurrogate& fitted_surrogate() {
  static const ViscositySurrogate s = ViscositySurrogate::fit(synthetic_training_cases(SyntheticGrid{}, 11), "synthetic");
  return s;
}

TEST(ViscositySurrogate, BandsCoverTheKnownFunctionAtHeldOutPoints) {
  const ViscositySurrogate& s = fitted_surrogate();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> phi(0.06, 0.39), ln_ca(std::log(0.012), std::log(0.75)), ln_lambda(0.0, std::log(10.0));
  const int n = 400;
  int covered = 0;
  double worst_relative_error = 0.0;
  for (int i = 0; i < n; ++i) {
    const double p = phi(rng), ca = std::exp(ln_ca(rng)), lambda = std::exp(ln_lambda(rng));
    const ViscosityPrediction pred = s.predict(p, ca, lambda);
    const double truth = std::exp(known_log_viscosity(p, ca, lambda));
    if (std::abs(pred.eta_re - truth) <= 1.96 * pred.sd) ++covered;
    worst_relative_error = std::max(worst_relative_error, std::abs(pred.eta_re - truth) / truth);
    EXPECT_TRUE(pred.inside_hull);
  }
  const double coverage = static_cast<double>(covered) / n;
  EXPECT_GE(coverage, 0.85);
  EXPECT_LE(coverage, 0.99);
  EXPECT_LT(worst_relative_error, 0.05);
  std::cout << "coverage of 95 % bands: " << coverage << ", worst relative error " << worst_relative_error << "\n";
}

// The joint prediction: each point as predict gives it, the diagonal its sd^2, neighbours strongly
// correlated and distant points less, and a valid (positive semi-definite) covariance.
// A surrogate built with another's hyper-parameters takes them as they are and fits nothing:
// on the same cases it predicts exactly as the reference; on other cases (a family member: the
// same runs moved) it keeps the reference's length scales and variance.
TEST(ViscositySurrogate, TakesAnotherSurrogatesHyperparameters) {
  const ViscositySurrogate& reference = fitted_surrogate();
  const ViscositySurrogate same =
      ViscositySurrogate::with_hyperparameters_of(synthetic_training_cases(SyntheticGrid{}, 11), reference);
  EXPECT_EQ(same.predict(0.3, 0.2, 2.0).eta_re, reference.predict(0.3, 0.2, 2.0).eta_re);
  EXPECT_EQ(same.fit_info().starts_tried, 0);
  std::vector<TrainingCase> moved = synthetic_training_cases(SyntheticGrid{}, 11);
  for (TrainingCase& c : moved) c.phi *= 1.05;
  const ViscositySurrogate member = ViscositySurrogate::with_hyperparameters_of(moved, reference);
  const auto& a = member.process().hyperparameters();
  const auto& b = reference.process().hyperparameters();
  EXPECT_EQ(a.packed(), b.packed());
  EXPECT_NE(member.predict(0.3, 0.2, 2.0).eta_re, reference.predict(0.3, 0.2, 2.0).eta_re);
  EXPECT_GE(member.predictive_sd_scale(), 1.0);
}

TEST(ViscositySurrogate, JointPredictionCorrelatesNeighbours) {
  const ViscositySurrogate& s = fitted_surrogate();
  const std::vector<ParameterPoint> q = {{0.2, 0.1, 2.0}, {0.21, 0.11, 2.0}, {0.35, 0.7, 8.0}, {0.08, 0.02, 1.0}};
  const JointViscosityPrediction joint = s.predict_joint(q, {});
  const Eigen::MatrixXd covariance = joint.covariance.dense();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const ViscosityPrediction single = s.predict(q[i].phi, q[i].capillary_number, q[i].viscosity_ratio);
    EXPECT_EQ(joint.points[i].eta_re, single.eta_re);
    EXPECT_NEAR(covariance(i, i), single.sd * single.sd, 1e-12 * single.sd * single.sd + 1e-300);
  }
  const auto correlation = [&](int i, int j) {
    return covariance(i, j) / std::sqrt(covariance(i, i) * covariance(j, j));
  };
  EXPECT_GT(correlation(0, 1), 0.8);
  EXPECT_LT(std::abs(correlation(0, 2)), correlation(0, 1));
  EXPECT_LT(std::abs(correlation(2, 3)), correlation(0, 1));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);
  EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-12 * eigen.eigenvalues().maxCoeff());
}

TEST(ViscositySurrogate, DerivativesMatchFiniteDifferences) {
  const ViscositySurrogate& s = fitted_surrogate();
  for (const auto& [phi, ca, lambda] : {std::tuple{0.17, 0.07, 3.0}, std::tuple{0.33, 0.5, 8.0}, std::tuple{0.5, 2.0, 20.0}}) {
    const ViscosityPrediction p = s.predict(phi, ca, lambda);
    const double h = 1e-6;
    const double d_phi = (s.predict(phi + h, ca, lambda).eta_re - s.predict(phi - h, ca, lambda).eta_re) / (2 * h);
    const double d_ln_ca =
        (s.predict(phi, ca * std::exp(h), lambda).eta_re - s.predict(phi, ca * std::exp(-h), lambda).eta_re) / (2 * h);
    const double d_ln_lambda =
        (s.predict(phi, ca, lambda * std::exp(h)).eta_re - s.predict(phi, ca, lambda * std::exp(-h)).eta_re) / (2 * h);
    EXPECT_NEAR(p.d_phi, d_phi, 1e-6 * (1 + std::abs(d_phi)));
    EXPECT_NEAR(p.d_ln_ca, d_ln_ca, 1e-6 * (1 + std::abs(d_ln_ca)));
    EXPECT_NEAR(p.d_ln_lambda, d_ln_lambda, 1e-6 * (1 + std::abs(d_ln_lambda)));
  }
}

TEST(ViscositySurrogate, DerivativesFollowTheKnownFunction) {
  // Inside the library the fitted slopes are those of the truth to within a few per cent.
  const ViscositySurrogate& s = fitted_surrogate();
  const double phi = 0.25, ca = 0.1, lambda = 5.0, h = 1e-5;
  const double eta = std::exp(known_log_viscosity(phi, ca, lambda));
  const double d_phi = eta * (known_log_viscosity(phi + h, ca, lambda) - known_log_viscosity(phi - h, ca, lambda)) / (2 * h);
  const double d_ln_ca = eta *
                         (known_log_viscosity(phi, ca * std::exp(h), lambda) - known_log_viscosity(phi, ca * std::exp(-h), lambda)) /
                         (2 * h);
  const ViscosityPrediction p = s.predict(phi, ca, lambda);
  EXPECT_NEAR(p.d_phi, d_phi, 0.05 * std::abs(d_phi));
  EXPECT_NEAR(p.d_ln_ca, d_ln_ca, 0.1 * std::abs(d_ln_ca));
}

TEST(ViscositySurrogate, FlagsQueriesOutsideTheLibraryBox) {
  const ViscositySurrogate& s = fitted_surrogate();
  const ParameterRange r = s.range();
  EXPECT_NEAR(r.ca_min, 0.01, 1e-12);
  EXPECT_NEAR(r.lambda_max, 10.0, 1e-10);  // widened by a relative 1e-12, below
  // The grid's own edge values are inside the range, although exp(ln 0.01) > 0.01 by an ulp:
  // callers (the alpha method's Ca grid) compare planned values against it.
  EXPECT_LE(r.ca_min, 0.01);
  EXPECT_GE(r.ca_max, 0.8);
  EXPECT_LE(r.lambda_min, 1.0);
  EXPECT_GE(r.lambda_max, 10.0);
  EXPECT_TRUE(s.predict(0.2, 0.1, 5.0).inside_hull);
  EXPECT_TRUE(s.predict(0.2, 0.01, 10.0).inside_hull);  // on the boundary
  EXPECT_FALSE(s.predict(0.45, 0.1, 5.0).inside_hull);
  EXPECT_FALSE(s.predict(0.41, 0.1, 5.0).inside_hull);
  // The planned grid's edges are inside although phi_actual scatters about the nominal phi.
  for (const double phi : SyntheticGrid{}.phi) EXPECT_TRUE(s.predict(phi, 0.8, 1.0).inside_hull) << phi;
  EXPECT_FALSE(s.predict(0.2, 0.005, 5.0).inside_hull);
  EXPECT_FALSE(s.predict(0.2, 0.1, 0.5).inside_hull);
  // Outside, the band widens (relative sd = sd of ln eta_re).
  auto relative_sd = [&](double phi, double ca, double lambda) {
    const ViscosityPrediction p = s.predict(phi, ca, lambda);
    return p.sd / p.eta_re;
  };
  EXPECT_GT(relative_sd(0.2, 0.002, 5.0), 1.3 * relative_sd(0.2, 0.1, 5.0));
  EXPECT_GT(relative_sd(0.6, 0.1, 5.0), 2.0 * relative_sd(0.35, 0.1, 5.0));
}

TEST(ViscositySurrogate, LeaveOneOutResidualsAreCalibrated) {
  const LeaveOneOutReport loo = fitted_surrogate().leave_one_out();
  ASSERT_EQ(loo.cases.size(), fitted_surrogate().training_cases().size());
  EXPECT_GT(loo.rms_standardised_residual, 0.6);
  EXPECT_LT(loo.rms_standardised_residual, 1.5);
  EXPECT_LT(loo.rms_relative_error, 0.03);
  EXPECT_NE(format_leave_one_out(loo).find("RMS relative error"), std::string::npos);
}

TEST(ViscositySurrogate, DropsMeanTermsOfInputsConstantOverTheLibrary) {
  SyntheticGrid grid;
  grid.lambda = {5.0};
  const ViscositySurrogate s = ViscositySurrogate::fit(synthetic_training_cases(grid, 3));
  EXPECT_EQ(s.mean_terms(), (std::vector<std::string>{"phi", "phi ln Ca"}));
  const ViscosityPrediction p = s.predict(0.22, 0.2, 5.0);
  EXPECT_NEAR(std::log(p.eta_re), known_log_viscosity(0.22, 0.2, 5.0), 0.02);
  EXPECT_TRUE(p.inside_hull);
  EXPECT_FALSE(s.predict(0.22, 0.2, 6.0).inside_hull);
}

TEST(SurrogateFile, LoadedSurrogatePredictsBitIdentically) {
  const auto folder = testing::fresh_temp_folder("round_trip");
  const ViscositySurrogate& s = fitted_surrogate();
  save_surrogate(s, folder / "surrogate.json");
  const ViscositySurrogate loaded = load_surrogate(folder / "surrogate.json");
  for (const auto& [phi, ca, lambda] :
       {std::tuple{0.17, 0.07, 3.0}, std::tuple{0.33, 0.5, 8.0}, std::tuple{0.05, 0.01, 1.0}, std::tuple{0.6, 3.0, 30.0}}) {
    const ViscosityPrediction a = s.predict(phi, ca, lambda), b = loaded.predict(phi, ca, lambda);
    EXPECT_EQ(a.eta_re, b.eta_re);
    EXPECT_EQ(a.sd, b.sd);
    EXPECT_EQ(a.d_phi, b.d_phi);
    EXPECT_EQ(a.d_ln_ca, b.d_ln_ca);
    EXPECT_EQ(a.d_ln_lambda, b.d_ln_lambda);
    EXPECT_EQ(a.inside_hull, b.inside_hull);
  }
  EXPECT_EQ(loaded.source_library(), "synthetic");
  nlohmann::json a = surrogate_to_json(s), b = surrogate_to_json(loaded);
  a.erase("provenance"), b.erase("provenance");
  EXPECT_EQ(a, b);
}

TEST(SurrogateFile, BuildingTwiceFromALibraryGivesIdenticalContent) {
  const auto root = testing::fresh_temp_folder("build_twice");
  SyntheticGrid grid;
  grid.phi = {0.1, 0.2, 0.3, 0.4};
  grid.ca = {0.02, 0.1, 0.5};
  testing::write_synthetic_library(root, grid, 17);
  setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  save_surrogate(build_surrogate(root), root / "first.json");
  save_surrogate(build_surrogate(root), root / "second.json");
  unsetenv("SOURCE_DATE_EPOCH");
  const nlohmann::json first = formats::read_json_file(root / "first.json");
  const nlohmann::json second = formats::read_json_file(root / "second.json");
  EXPECT_EQ(first.dump(), second.dump());
  EXPECT_EQ(first["provenance"]["date"], "2023-11-14T22:13:20Z");
  EXPECT_EQ(first["training"].size(), grid.phi.size() * grid.ca.size() * grid.lambda.size());
  EXPECT_EQ(first["source_library"], root.string());
}

TEST(SurrogateFile, RejectsBadFilesNamingTheField) {
  nlohmann::json j = surrogate_to_json(fitted_surrogate());
  auto message = [](const nlohmann::json& bad) {
    try {
      surrogate_from_json(bad, "s.json");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  nlohmann::json bad = j;
  bad["schema"] = "rbcal.surrogate/2";
  EXPECT_NE(message(bad).find("s.json: field schema"), std::string::npos);
  bad = j;
  bad["hyperparameters"].erase("log_nugget_variance");
  EXPECT_NE(message(bad).find("s.json: field hyperparameters.log_nugget_variance: missing"), std::string::npos);
  bad = j;
  bad["training"][3]["noise_variance"] = -1.0;
  EXPECT_NE(message(bad).find("s.json: field training.3.noise_variance: must be a non-negative number"), std::string::npos)
      << message(bad);
}

TEST(CaseProposal, ProposesTheHoleInTheLibraryFirst) {
  // Drop the corner phi >= 0.25, Ca <= 0.03 (all lambda): the largest variance is there.
  SyntheticGrid full;
  auto in_hole = [](double phi, double ln_ca) { return phi >= 0.245 && ln_ca <= std::log(0.031); };
  std::vector<TrainingCase> cases;
  for (const TrainingCase& c : synthetic_training_cases(full, 21))
    if (!in_hole(c.phi, c.ln_ca)) cases.push_back(c);
  const ViscositySurrogate s = ViscositySurrogate::fit(cases);
  const ParameterGrid candidates{full.phi, full.ca, full.lambda, {}};
  const std::vector<ProposedCase> proposals = propose_cases(s, candidates, 4);
  ASSERT_EQ(proposals.size(), 4u);
  for (const ProposedCase& p : proposals) {
    EXPECT_TRUE(in_hole(p.phi, std::log(p.capillary_number))) << p.phi << " " << p.capillary_number;
    EXPECT_TRUE(p.inside_hull);
  }
  // The first choice has the largest variance of the whole grid.
  for (double phi : full.phi)
    for (double ca : full.ca)
      for (double lambda : full.lambda) EXPECT_LE(s.log_viscosity_sd(phi, ca, lambda), proposals[0].relative_sd);
}

TEST(CaseProposal, NeverProposesAPointAlreadySimulated) {
  SyntheticGrid grid;
  grid.phi = {0.1, 0.25, 0.4};
  grid.ca = {0.01, 0.1, 0.8};
  const std::vector<TrainingCase> cases = synthetic_training_cases(grid, 4);
  const ViscositySurrogate s = ViscositySurrogate::fit(cases);
  // Candidates: the library's own grid; all but one point count as simulated.
  std::vector<ParameterPoint> simulated;
  for (double phi : grid.phi)
    for (double ca : grid.ca)
      for (double lambda : grid.lambda)
        if (!(phi == 0.25 && ca == 0.1)) simulated.push_back({phi, ca, lambda});
  const std::vector<ProposedCase> proposals =
      propose_cases(s, ParameterGrid{grid.phi, grid.ca, grid.lambda, {}}, 5, simulated);
  const std::size_t free_points = grid.phi.size() * grid.ca.size() * grid.lambda.size() - simulated.size();
  ASSERT_EQ(proposals.size(), free_points);
  for (const ProposedCase& p : proposals) {
    EXPECT_EQ(p.phi, 0.25);
    EXPECT_EQ(p.capillary_number, 0.1);
  }
}

TEST(CaseProposal, EachChoiceIsTheMaximumAfterAddingTheEarlierOnes) {
  SyntheticGrid grid;
  grid.phi = {0.1, 0.25, 0.4};
  grid.ca = {0.01, 0.1, 0.8};
  const std::vector<TrainingCase> cases = synthetic_training_cases(grid, 4);
  const ViscositySurrogate s = ViscositySurrogate::fit(cases);
  const ParameterGrid candidates = refined(ParameterGrid{grid.phi, grid.ca, grid.lambda, {}});
  const std::vector<ProposedCase> proposals = propose_cases(s, candidates, 3);
  ASSERT_EQ(proposals.size(), 3u);
  EXPECT_EQ(proposals[0].relative_sd_when_chosen, proposals[0].relative_sd);
  // Rebuild by hand: add the first proposal with the median noise, then the second must be the maximum.
  std::vector<double> noise;
  for (const TrainingCase& c : cases) noise.push_back(c.noise_variance);
  std::sort(noise.begin(), noise.end());
  std::vector<TrainingCase> augmented = cases;
  augmented.push_back({"p1", proposals[0].phi, std::log(proposals[0].capillary_number),
                       std::log(proposals[0].viscosity_ratio), 0.0, noise[noise.size() / 2]});
  const ViscositySurrogate after(augmented, s.process().hyperparameters());
  double largest = 0.0;
  for (double phi : candidates.phi)
    for (double ca : candidates.capillary_number)
      for (double lambda : candidates.viscosity_ratio) largest = std::max(largest, after.log_viscosity_sd(phi, ca, lambda));
  EXPECT_DOUBLE_EQ(proposals[1].relative_sd_when_chosen, largest);
  EXPECT_LT(after.log_viscosity_sd(proposals[0].phi, proposals[0].capillary_number, proposals[0].viscosity_ratio),
            0.8 * proposals[0].relative_sd);
  for (std::size_t i = 1; i < proposals.size(); ++i) {
    EXPECT_LE(proposals[i].relative_sd_when_chosen, proposals[i - 1].relative_sd_when_chosen * (1 + 1e-12));
    EXPECT_FALSE(proposals[i].phi == proposals[0].phi && proposals[i].capillary_number == proposals[0].capillary_number &&
                 proposals[i].viscosity_ratio == proposals[0].viscosity_ratio);
  }
}

// The predictive sd scale: the fitted process's held-out RMS when above 1 (else 1), applied to
// every predictive sd and covariance, kept by the file. Built from
// cases whose stated noise is a quarter of their real scatter, the scale must exceed 1 and
// equal that RMS; the mean does not change.
TEST(ViscositySurrogate, PredictiveSdScaleIsTheLeaveOneOutRmsWhenAboveOne) {
  std::vector<TrainingCase> cases = synthetic_training_cases(SyntheticGrid{}, 17);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (auto& c : cases) {
    c.ln_eta_re += 0.04 * noise(rng);  // scatter 0.04 in ln eta_re ...
    c.noise_variance = 0.01 * 0.01;    // ... stated as 0.01
  }
  const ViscositySurrogate fitted = ViscositySurrogate::fit(cases, "understated");
  const double rms = fitted.leave_one_out().rms_standardised_residual;
  ASSERT_GT(rms, 1.0);
  EXPECT_DOUBLE_EQ(fitted.predictive_sd_scale(), rms);
  const ViscositySurrogate unscaled(cases, fitted.process().hyperparameters());
  EXPECT_EQ(unscaled.predictive_sd_scale(), 1.0);
  const ViscosityPrediction a = fitted.predict(0.2, 0.1, 2.0), b = unscaled.predict(0.2, 0.1, 2.0);
  EXPECT_EQ(a.eta_re, b.eta_re);
  EXPECT_NEAR(a.sd, rms * b.sd, 1e-12 * a.sd);
  EXPECT_NEAR(fitted.predict_joint({{0.2, 0.1, 2.0}}, {}).covariance.variances()(0), a.sd * a.sd, 1e-12 * a.sd * a.sd);
  const auto file = std::filesystem::temp_directory_path() / "rbcal_sd_scale_surrogate.json";
  save_surrogate(fitted, file);
  EXPECT_EQ(load_surrogate(file).predictive_sd_scale(), fitted.predictive_sd_scale());
  EXPECT_THROW(ViscositySurrogate(cases, fitted.process().hyperparameters(), "", {}, 0.9), std::invalid_argument);

  // A noise that carries a systematic share (as the runs' offset sd does) hides the scatter from
  // leave-one-out; the held-out RMS against each run's own noise finds it.
  for (auto& c : cases) {
    c.noise_variance = 0.08 * 0.08;      // stated: the run's 0.01 and a systematic 0.08 ...
    c.run_noise_variance = 0.01 * 0.01;  // ... of which a new run adds only its own
  }
  const ViscositySurrogate hidden = ViscositySurrogate::fit(cases, "systematic share");
  EXPECT_LT(hidden.leave_one_out().rms_standardised_residual, 1.0);
  ASSERT_GT(hidden.held_out_rms(), 1.0);
  EXPECT_DOUBLE_EQ(hidden.predictive_sd_scale(), hidden.held_out_rms());
}

}  // namespace
}  // namespace rbcal::surrogate
