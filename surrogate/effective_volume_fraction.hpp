#pragma once
// Converged eta_re from runs at any resolution, by the immersed boundary's thickening
// (docs/library.md, "The effective volume fraction"):
//
// A membrane spread by the immersed boundary acts thicker than its mesh: a sphere of
// radius a acts as one of radius a + c dx (c about 0.75-0.79, docs/validation.md), and the
// resolution error of eta_re at every volume fraction measured so far is what that extra
// volume gives. A suspension run at volume fraction phi with N_a lattice spacings per
// radius therefore stands for the continuum suspension at
//     phi_eff = g phi,   g = V(c a / N_a) / V   (solver/membrane/thickened_volume.hpp),
// the cell's volume thickened outwards by c lattice spacings. Each run keeps its eta_re
// and moves to phi_eff; runs at several resolutions land on one continuum surface.
//
// Uncertainty: c is known to about +-0.05 (the shipped recipe's sd: the width within which
// samples of known G_s made from the dense anchors are recovered; +-0.15 before those runs).
// Through the exponential law eta_re = exp(alpha
// phi), which holds locally for these suspensions, an error s_g in g moves ln eta_re by
// ln(eta_re) s_g / g. That enters each case's sd in quadrature with its standard error
// (raised by the seed-scatter floor of resolution_extrapolation.hpp). The error is one c for
// every run, not independent per run; entered per run it acts on the surrogate as a
// smoothness prior (without it the default loses its shear thinning at dense, low Ca and
// the main job's fit turns bimodal; with it new dense runs are predicted a little worse:
// studies/library-v2-development/README.md,
// "The first dense runs at phi_eff 0.41-0.55, out of sample"). Its effect on eta_re itself is
// measured by rebuilding at other c (studies/library-v2-development/effective_phi_check.py).
#include <functional>
#include <string>
#include <vector>

#include "surrogate/resolution_extrapolation.hpp"
#include "surrogate/simulation_library.hpp"

namespace rbcal::surrogate {

struct EffectiveVolumeFractionOptions {
  // c in lattice spacings, from the single sphere's intrinsic viscosity at N_a 6 to 16
  // (0.75-0.79). The red cells' runs prefer 0.6 (the runs at N_a 10 and 12 predicted from
  // those at 6 and 8) to 0.9 (N_a 6 and 8 agreeing best with each other) (docs/library.md).
  double offset = 0.75;
  // How c changes with resolution: c(N_a) = offset + offset_slope (1 / N_a - 1 / 8), so that
  // offset is c at N_a 8. Rigid bodies of known intrinsic viscosity need a c that falls with
  // N_a (studies/ib-thickening): the sphere about 1.1, the red cell's oblate spheroid about
  // 2 lattice spacings per unit of 1 / N_a. 0: one c for every resolution.
  double offset_slope = 0.0;
  // c at a given resolution.
  double offset_at(int nodes_per_radius) const { return offset + offset_slope * (1.0 / nodes_per_radius - 1.0 / 8.0); }
  // The sd of c entered in each case's sd (see above; 0: not entered). The default is the
  // shipped recipe's (and `rbcal library effective-phi`'s).
  double offset_sd = 0.05;
  // Runs whose g phi_actual exceeds this are left out (they stand for no physiological sample).
  double phi_max = 0.62;
  // Seed-scatter floor (only these three fields of ExtrapolationOptions are used).
  ExtrapolationOptions scatter;
};

// g as a function of the offset in cell radii, c / N_a (the caller owns the cell's shape).
using VolumeRatio = std::function<double(double offset_over_radius)>;

struct MappedCase {
  LibraryCase raw;
  double volume_ratio = 1.0;     // g
  double volume_ratio_sd = 0.0;  // half the spread of g over c +- sd_c
  double phi = 0.0;              // g params.phi
  double phi_actual = 0.0;       // g result.phi_actual: the surrogate's input, compared with phi_max
  double eta_re_sd = 0.0;        // standard error, scatter floor and the offset's uncertainty
  double run_sd = 0.0;           // the run's own error: standard error and scatter floor only
};

struct MappedLibrary {
  std::vector<MappedCase> cases;
  std::vector<LibraryCase> left_out;  // g phi_actual above phi_max
};

// Throws std::invalid_argument (naming the files) when the tiers' cases differ in anything
// of the numerics signature but N_a, when a case is already extrapolated or mapped, or when
// an option is out of range.
MappedLibrary map_to_effective_volume_fraction(const std::vector<SimulationLibrary>& tiers,
                                               const VolumeRatio& volume_ratio,
                                               const EffectiveVolumeFractionOptions& options = {});

// The id of a mapped case: the raw id with its resolution, e.g. "phi0.21_Ca0.2_lambda5_n8".
std::string mapped_case_id(const MappedCase& c);

// The raw case file with params.phi, result.phi_actual and result.eta_re_sem replaced, and
// a block "extrapolation" (method "effective volume fraction", the offset, g, the raw
// volume fractions and the raw result).
nlohmann::json mapped_case_json(const MappedCase& c, const EffectiveVolumeFractionOptions& options);

}  // namespace rbcal::surrogate
