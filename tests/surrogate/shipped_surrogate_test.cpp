// The shipped default surrogate is what `rbcal surrogate build data/library/default` makes
// from the shipped library (issue 6: "reproduces the shipped surrogate"). Built with
// -march=native, a rebuild on another CPU may round differently inside the Ceres fit, so
// hyper-parameters and predictions are compared to a relative 1e-5, far below the
// surrogate's own predictive sd (about 1 %), not bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "surrogate/surrogate_file.hpp"

namespace rbcal::surrogate {
namespace {

const std::filesystem::path kLibrary = RBCAL_DEFAULT_LIBRARY;

TEST(ShippedSurrogate, IsRebuiltFromTheShippedLibrary) {
  const ViscositySurrogate shipped = load_surrogate(kLibrary / "surrogate.json");
  const ViscositySurrogate rebuilt = build_surrogate(kLibrary);

  ASSERT_EQ(rebuilt.training_cases().size(), shipped.training_cases().size());
  const Eigen::VectorXd a = shipped.process().hyperparameters().packed();
  const Eigen::VectorXd b = rebuilt.process().hyperparameters().packed();
  ASSERT_EQ(a.size(), b.size());
  // Packed hyper-parameters are logarithms: an absolute difference is a relative one.
  for (Eigen::Index i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5) << "hyper-parameter " << i;

  // Predictions on a grid inside the library, including points between the training cases.
  for (double phi : {0.05, 0.15, 0.3, 0.41})
    for (double ca : {0.01, 0.03, 0.2, 0.8})
      for (double lambda : {0.1, 2.0, 10.0}) {
        const ViscosityPrediction p = shipped.predict(phi, ca, lambda);
        const ViscosityPrediction q = rebuilt.predict(phi, ca, lambda);
        EXPECT_NEAR(q.eta_re / p.eta_re, 1.0, 1e-5) << phi << " " << ca << " " << lambda;
        EXPECT_NEAR(q.sd / p.sd, 1.0, 1e-4) << phi << " " << ca << " " << lambda;
      }
}

}  // namespace
}  // namespace rbcal::surrogate
