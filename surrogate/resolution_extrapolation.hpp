#pragma once
// Converged eta_re from two libraries of the same design points at two resolutions
// (docs/library.md, "Extrapolation to the continuum"): a coarse library (N_a = n_c, every point) and a fine one (N_a = n_f,
// a subset). With h = 1 / N_a and r = n_f / n_c:
//  - a point in both: Richardson extrapolation of order p,
//        eta = eta_f + g (eta_f - eta_c),  g = 1 / (r^p - 1),
//    with sd^2 = (1 + g)^2 sem_f^2 + g^2 sem_c^2 + s_p^2, where s_p, half the difference
//    between the extrapolations of orders p and p_low, carries the uncertainty of the
//    order itself (measured between 1 and 2 so far: docs/library.md);
//  - a point in the coarse library only: its log correction c = ln eta - ln eta_c is
//    predicted by a Gaussian process fitted to the corrections of the paired points (the
//    viscosity surrogate's machinery: the mean phi (b0 + b1 ln Ca + b2 ln lambda) suits a
//    correction that vanishes with phi), so eta = eta_c exp(c) with sd from the process
//    and the coarse case's own error.
// The extrapolated values feed the surrogate like any library; the raw values stay with them.
#include <string>
#include <vector>

#include "surrogate/simulation_library.hpp"

namespace rbcal::surrogate {

struct ExtrapolationOptions {
  // p: the convergence order of the estimate. Measured at two points with N_a 6, 8, 10
  // (phi 0.21 and 0.55: orders 2.7 and 2.85), where p = 2.8 makes the (6, 8) and (8, 10)
  // estimates agree within 0.01 (studies/library-v2-development/README.md, "Membrane overlaps").
  double order = 2.8;
  // p_low: the low end of the plausible orders; half the distance between the two estimates
  // enters the sd. 1.5 is the lowest order any C 10 triplet showed (dilute high Ca from N_a
  // 8, 10, 12; phi 0.55, Ca 0.02 from 6, 8, 10), and with it the (6, 8) estimates of the
  // points run to N_a 10-12 lie within 0.7 sd of their finest pairs' values, but one dilute
  // point at 2.3 sd (studies/library-v2-development/extrapolation_check.py, docs/library.md).
  double order_low = 1.5;
  // Seed scatter: dense suspensions fluctuate slowly, so one run's blocking error
  // understates the error of its window mean (seed twins, docs/library.md). Each raw
  // case's sem is raised to hypot(sem, s(phi) eta_re), with the relative floor s rising
  // linearly from 0 at phi <= scatter_phi_low to scatter_floor at phi >= scatter_phi_high.
  double scatter_floor = 0.0;
  double scatter_phi_low = 0.21;
  double scatter_phi_high = 0.41;
};

// The raw case's standard error with the seed-scatter floor of `options` (see above).
double error_with_scatter_floor(const LibraryCase& c, const ExtrapolationOptions& options);

struct ExtrapolatedCase {
  LibraryCase coarse;
  bool paired = false;  // a fine case exists: Richardson; otherwise the correction model
  LibraryCase fine;     // when paired
  double eta_re = 0.0;  // extrapolated to h = 0
  double eta_re_sd = 0.0;
  double log_correction = 0.0;     // ln eta_re - ln eta_re(coarse)
  double log_correction_sd = 0.0;  // its sd (correction model) or that of the Richardson value, relative
  std::string method() const { return paired ? "richardson" : "correction model"; }
};

// Throws std::invalid_argument (naming the libraries) if either library mixes resolutions,
// the fine one is not finer, a fine case has no coarse twin, or fewer than 3 points are
// paired while some are not (too few to fit the correction model).
std::vector<ExtrapolatedCase> extrapolate_to_continuum(const SimulationLibrary& coarse, const SimulationLibrary& fine,
                                                       const ExtrapolationOptions& options = {});

// The case file of an extrapolated library: the coarse case's file with result.eta_re and
// result.eta_re_sem replaced by the extrapolated value and its sd, and a block
// "extrapolation" (method, orders, raw results per resolution, log correction).
nlohmann::json extrapolated_case_json(const ExtrapolatedCase& c, const ExtrapolationOptions& options);

}  // namespace rbcal::surrogate
