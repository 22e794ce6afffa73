#pragma once
// The box correction's prior from anchor runs: runs in a box twice the library's height (the
// dense anchors, data/library/anchors/). At a resolution the library has, a run at phi as run
// stands for the library's runs at that phi as run, whatever the offset c (the mapping moves
// both alike), so the model at phi_eff = g_c(N_a) phi_actual predicts what the run would give
// in the library's box, and
//     beta = ln eta_run / ln eta_model - 1
// is the step from the model to the bigger box: the box itself and the model's own error at
// that point together (the twins of box_twins.hpp see the box alone). At a finer resolution
// the run stands, under the same mapping, for the continuum at its own phi_eff, so its beta
// also carries the mapping's error at that resolution: the step the calibration needs, from
// the model to the finer level (the anchors' N_a 8, 12 and 16 tiers give the same mean step
// at the shipped offset: docs/library.md, "The box twins"). Runs coarser than the library's
// are refused. For the calibration the sum is what counts. The prior for the bulk adds what
// lies between the doubled box and the bulk by the twins' rule (bulk_prior in box_twins.hpp,
// with the twins' mean m):
//     mean = n + 0.5 m,   sd = sqrt(s^2 + (0.5 m)^2 + se_n^2),
// n the anchors' mean beta, s their scatter, se_n the mean's standard error from the runs.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "surrogate/box_twins.hpp"
#include "surrogate/library_case.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

struct BoxAnchor {
  LibraryCase run;
  double phi_eff = 0.0;       // where the model is asked
  double model_eta_re = 0.0;  // the model there (the library's box)
  double beta = 0.0, beta_se = 0.0;
};

// The anchors of one resolution: whether the tiers ask the same step.
struct ResolutionStep {
  int nodes_per_radius = 0;
  std::size_t count = 0;
  BetaSpread spread;
};

struct BoxAnchorPrior {
  std::vector<BoxAnchor> anchors;
  std::vector<ResolutionStep> by_resolution;  // ascending N_a
  double mean_beta = 0.0, scatter = 0.0, mean_se = 0.0;  // n, s, se_n
  double twins_mean_beta = 0.0;                         // m
  double mean = 0.0, sd = 0.0;                          // the prior for the bulk
};

// The phi_eff at which a run stands (the recipe's mapping at the run's own resolution).
using EffectivePhi = std::function<double(const LibraryCase&)>;

// Throws std::invalid_argument naming the file when a run cannot be read, when it is coarser
// than every one of `library_resolutions`, when the model does not cover its point, or when no
// anchor is given.
BoxAnchorPrior box_anchor_prior(const std::vector<std::filesystem::path>& anchors, const ViscosityModel& model,
                                const EffectivePhi& phi_eff, const std::vector<int>& library_resolutions,
                                const BoxTwinPrior& twins);

// One line per anchor (N_a, phi_actual, phi_eff, run, model, beta), then n, s, se_n, the same
// per resolution when there are several, and the prior.
std::string describe_box_anchors(const BoxAnchorPrior& prior);

}  // namespace rbcal::surrogate
