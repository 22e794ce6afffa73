#pragma once
// The `mcmc` method for one sample: the direct fit gives the start point and the points inside the
// model's range; the posterior (posterior.hpp) over those points is sampled with several
// stretch-move ensembles until converged (mcmc_sampling.hpp).
#include <vector>

#include "calibration/calibration_input.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_sampling.hpp"
#include "calibration/posterior.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

// Walkers per ensemble when McmcOptions::walkers is 0: 8 per parameter, at least 16. Fewer
// left the pilot of a four-parameter posterior (G_s, eta0, the offset and the box correction,
// then sampled; now integrated out, surrogate/offset_family.hpp) with walkers stranded in a tail, and the independence proposal fitted to it failed
// (docs/library.md, "The box twins").
int automatic_walkers(int parameters);

struct McmcCalibrationOptions {
  PosteriorOptions posterior;  // parameters, priors, a, lambda
  McmcOptions sampler;         // walkers 0: automatic_walkers(dimension)
  // Start fit; its cell radius, lambda and bounds are taken from `posterior`.
  DirectFitOptions start_fit;
  // When given, a fit already made with those options (e.g. the `direct` method's), used instead
  // of fitting again; it must outlive the call.
  const DirectFitResult* fitted_start = nullptr;
};

struct McmcCalibration {
  DirectFitResult start_fit;                   // MAP-like start (weighted least squares)
  std::vector<RelativeViscosityPoint> points;  // the points in the likelihood
  PosteriorOptions posterior;                  // as used
  double plasma_viscosity = 0.0;                 // eta0's plateau estimate [Pa s]
  double plasma_viscosity_standard_error = 0.0;  // and its standard error [Pa s]
  McmcResult mcmc;
  double shear_modulus_median = 0.0;  // [N/m]
  Interval shear_modulus_interval;    // central credible interval of G_s [N/m]
  double lambda_median = 0.0;         // the fixed lambda when not fitted
  Interval lambda_interval;
  double discrepancy_median = 0.0;  // sigma_d (0 without it)
  Interval discrepancy_interval;
  double plasma_viscosity_median = 0.0;  // eta0 [Pa s] (the plateau estimate when fixed)
  Interval plasma_viscosity_interval;
  std::vector<NuisanceEstimate> nuisances;  // the model's nuisance parameters: median, credible interval
  std::vector<double> shear_modulus_draws() const;  // exp(ln G_s) of every post-burn-in draw [N/m]
};

McmcCalibration calibrate_mcmc(const SampleData& sample, const surrogate::ViscosityModel& model,
                               const McmcCalibrationOptions& options = {});

}  // namespace rbcal::calibration
