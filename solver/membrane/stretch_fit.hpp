#pragma once
// Optical-tweezers measurements and the G_s that reproduces them: the measured axial and
// transverse diameters of a stretched cell versus force (e.g. Mills et al., Mech. Chem.
// Biosyst. 1 (2004) 169, data/reference/), the root-mean-square misfit of a simulated
// stretching, and a one-parameter least-squares fit of G_s by golden-section search over
// ln G_s (the misfit is unimodal in G_s: a stiffer membrane stretches less at every force).
#include <functional>
#include <string>
#include <vector>

#include "solver/membrane/cell_stretching.hpp"

namespace rbcal::solver {

struct StretchMeasurements {
  std::vector<double> force_pn, axial_um, transverse_um;
};

// CSV with '#' comment lines and the header force_pN,axial_um,transverse_um; errors read
// "FILE:LINE: field F: ...". Forces in pN, diameters in um, all non-negative.
StretchMeasurements read_stretch_measurements(const std::string& path);

// sqrt(mean over points and both diameters of (simulated - measured)^2), in um; the points
// are those of stretch_cell at the measured forces, in that order.
double rms_misfit(const std::vector<StretchPoint>& points, const StretchMeasurements& measured);

struct StretchFitOptions {
  double shear_modulus_min = 1e-6;  // N/m: the search bracket
  double shear_modulus_max = 3e-5;
  double ln_tolerance = 0.01;       // bracket width in ln G_s at the end (1 % in G_s)
  // Called after each evaluation with (G_s [N/m], misfit [um]); may be empty.
  std::function<void(double, double)> progress;
};

// The G_s [N/m] of settings.material that minimises rms_misfit; settings' own shear
// modulus is ignored.
double fit_shear_modulus(const StretchSettings& settings, const StretchMeasurements& measured,
                         const StretchFitOptions& options = {});

}  // namespace rbcal::solver
