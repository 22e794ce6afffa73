#pragma once
// The seed study's method (Takeishi et al., section "Estimation of G_s"): fit eta_re = exp(alpha phi)
// to the measurements at each shear rate and to the model at each Ca, match the alphas to map
// shear rate <-> Ca, and convert with G_s = eta0 gamma_dot a / Ca.
#include <string>
#include <vector>

#include "calibration/calibration_input.hpp"
#include "calibration/model_setup.hpp"
#include "calibration/exponential_alpha_fit.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct AlphaMethodOptions {
  ModelSetup setup;  // a, and the lambda at which the model is evaluated (fit_lambda unused)
  double phi_min = 0.0;                     // measured points with phi_min <= phi <= phi_max are fitted
  double phi_max = 1.0;                     // the seed study used phi <= 0.4 for hardened cells
  AlphaFitSpace fit_space = AlphaFitSpace::linear;
  int min_points_per_shear_rate = 2;  // shear rates with fewer phi values are skipped
  // The model's alpha at the sample's hematocrits (true), or on a uniform grid of
  // model_phi_points over the model's phi range within the cut-offs (false, or fewer than two).
  bool model_at_sample_hematocrits = true;
  int model_phi_points = 9;
  int model_ca_points = 41;           // ln-uniform Ca grid over the model's Ca range
  // The seed study's direction: each of these Ca is mapped to a shear rate (seven values in
  // 0.01 - 0.8 as in the study, whose exact values are not stated). Values outside the model's
  // range are skipped with a message.
  std::vector<double> capillary_numbers = {0.01, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8};
};

struct ShearRateAlpha {
  double shear_rate = 0.0;  // [1/s]
  ExponentialAlphaFit fit;
};

struct CapillaryAlpha {
  double capillary_number = 0.0;
  ExponentialAlphaFit fit;
};

// One matched pair (shear rate, Ca) with the G_s it implies.
struct AlphaMatch {
  double shear_rate = 0.0;        // [1/s]
  double alpha = 0.0;             // the matched alpha
  double capillary_number = 0.0;  // Ca with the same alpha
  double shear_modulus = 0.0;     // G_s = eta0 gamma_dot a / Ca [N/m]
  bool matched = false;           // false: no match (see message), other fields partly unset
  std::string message;            // why not matched, or a warning (several crossings)
};

struct ShearModulusSummary {
  double mean = 0.0;            // [N/m] mean over matched entries
  double sd = 0.0;              // sample standard deviation
  double standard_error = 0.0;  // sd / sqrt(count)
  int count = 0;
};

struct AlphaMethodResult {
  double plasma_viscosity = 0.0;  // eta0 used [Pa s]
  std::vector<ShearRateAlpha> measured;       // alpha per measured shear rate, ascending
  std::vector<CapillaryAlpha> model;          // alpha of the model per Ca, ascending
  std::vector<AlphaMatch> per_shear_rate;     // each measured shear rate -> Ca -> G_s
  std::vector<AlphaMatch> per_capillary_number;  // each options.capillary_numbers -> shear rate -> G_s
  ShearModulusSummary shear_modulus;              // over per_shear_rate (the headline value)
  ShearModulusSummary shear_modulus_per_ca;       // over per_capillary_number (the study's average)
  bool curves_interpolated = false;  // no shared shear rates: curves read at one curve's rates
  std::vector<std::string> messages;
};

// All x at which the piecewise-linear curve through (x_i, y_i) (x ascending) takes the value target.
std::vector<double> level_crossings(const std::vector<double>& x, const std::vector<double>& y, double target);

AlphaMethodResult estimate_by_alpha_matching(const SampleData& sample, const surrogate::ViscosityModel& model,
                                             const AlphaMethodOptions& options = {});

}  // namespace rbcal::calibration
