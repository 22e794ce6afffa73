#pragma once
// The CSV tables of a calibration report, one row per item, every sample in one file with a
// `sample` column first. Units in the column names (uN_per_m, mPa_s, per_s).
//   fits.csv       per measured point: data, the point-wise fit's prediction, residual, used / why not
//   alpha.csv      alpha per measured shear rate (source measured) and of the model per Ca (source model)
//   gs_per_ca.csv  the alpha method's matches: shear rate <-> Ca -> G_s, both directions
//   chains.csv     thinned post-burn-in MCMC draws with chain, step and walker
//   bands.csv      posterior-predictive median and central band of eta(gamma_dot) per phi
// Each writer returns the number of data rows and throws std::runtime_error naming the file.
#include <filesystem>
#include <string>

#include "calibration/calibration_report.hpp"

namespace rbcal::calibration {

int write_fits_table(const CalibrationReport& report, const std::filesystem::path& file);
int write_alpha_table(const CalibrationReport& report, const std::filesystem::path& file);
int write_gs_per_ca_table(const CalibrationReport& report, const std::filesystem::path& file);
// At most max_draws_per_sample rows per sample: every k-th step, all walkers of all chains.
int write_chains_table(const CalibrationReport& report, const std::filesystem::path& file, int max_draws_per_sample);
int write_bands_table(const CalibrationReport& report, const std::filesystem::path& file);

// A CSV field: quoted (with doubled quotes) when it holds a comma, quote or line break.
std::string csv_field(const std::string& text);

// The shear rate [1/s] at which the alpha method's model alpha(Ca) is plotted: gamma_dot =
// Ca G_s / (eta0 a) with the method's own mean G_s; 0 when it has none.
double model_alpha_shear_rate(const AlphaMethodResult& alpha, double capillary_number, double cell_radius);

}  // namespace rbcal::calibration
