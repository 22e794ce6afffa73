#include <chrono>
#include <cstdio>
#include <cmath>
#include <random>
#include <Eigen/Dense>
#include "surrogate/offset_family_file.hpp"
#include "surrogate/offset_family.hpp"
#include "calibration/joint_likelihood.hpp"
using namespace rbcal::surrogate;
using namespace rbcal::calibration;
// Exact against low-rank joint covariance of the shipped family: ln L (3 % measurement error,
// a random residual of 5 %), the largest entry difference and the times of both forms.
// Usage: compare_forms PER_LINE  (four hematocrit lines of PER_LINE shear rates, 40-1260 1/s)
int main(int argc, char** argv) {
  auto model = load_viscosity_model("data/library/default/surrogate_family.json");
  int per = argc > 1 ? std::atoi(argv[1]) : 60;
  std::mt19937_64 rng(3); std::normal_distribution<double> nd;
  for (double gs : {0.5e-6, 1.3e-6, 4e-6}) for (double c : {0.6, 0.95}) {
    std::vector<ParameterPoint> q;
    for (double phi : {0.25, 0.35, 0.45, 0.55}) for (int i = 0; i < per; ++i) {
      double gd = std::pow(10.0, 1.6 + 1.5 * i / (per - 1.0));
      q.push_back({phi, 1.2e-3 * gd * 3.91e-6 / gs, 5.0});
    }
    auto t0 = std::chrono::steady_clock::now();
    auto e = model->predict_joint(q, {{"offset_c", c}}, CovarianceForm::exact);
    auto t1 = std::chrono::steady_clock::now();
    auto l = model->predict_joint(q, {{"offset_c", c}}, CovarianceForm::low_rank);
    auto t2 = std::chrono::steady_clock::now();
    const Eigen::Index n = q.size();
    Eigen::VectorXd noise(n), r(n);
    for (Eigen::Index i = 0; i < n; ++i) { double eta = e.points[i].eta_re; noise(i) = std::pow(0.03 * eta, 2); r(i) = 0.05 * eta * nd(rng); }
    JointResiduals je{r, e.covariance}, jl{r, l.covariance};
    je.covariance.add_diagonal(noise); jl.covariance.add_diagonal(noise);
    auto t3 = std::chrono::steady_clock::now();
    auto we = whiten(je);
    auto t4 = std::chrono::steady_clock::now();
    auto wl = whiten(jl);
    auto t5 = std::chrono::steady_clock::now();
    // same covariance, forced through the dense path
    JointResiduals jd{r, {}}; jd.covariance.full = jl.covariance.dense();
    auto wd = whiten(jd);
    Eigen::MatrixXd diff = e.covariance.dense() - l.covariance.dense();
    std::printf("Gs %.2g c %.2f n %ld rank %ld: logL exact %.4f lowrank %.4f (woodbury vs dense same cov %.2e); max|dC|/maxC %.3g; times: pred %.1f/%.1f ms whiten %.1f/%.1f ms\n",
      gs, c, (long)n, (long)l.covariance.rank(), we.log_likelihood(), wl.log_likelihood(), wl.log_likelihood() - wd.log_likelihood(),
      diff.cwiseAbs().maxCoeff() / e.covariance.dense().cwiseAbs().maxCoeff(),
      1e3*std::chrono::duration<double>(t1-t0).count(), 1e3*std::chrono::duration<double>(t2-t1).count(),
      1e3*std::chrono::duration<double>(t4-t3).count(), 1e3*std::chrono::duration<double>(t5-t4).count());
  }
}
