#pragma once
// A sample's MCMC draws as an ArviZ InferenceData file (NetCDF-4, libnetcdf):
// FOLDER/SAMPLE_posterior.nc with the groups
//   posterior       one variable per parameter (G_s in uN/m, eta0 in mPa s, lambda, sigma_d as
//                   values; the model's nuisances as sampled), dims (chain, draw)
//   sample_stats    lp: the log posterior of each draw
//   log_likelihood  eta: each data point's log-likelihood (calibration/saved_draws.hpp), dims
//                   (chain, draw, point)
//   observed_data   eta: each point's measured relative viscosity, with phi and shear_rate
// ArviZ's chain is one walker series (chain k, walker w -> k * walkers + w, as
// arviz.from_emcee maps walkers); the draw coordinate holds the sampler's step, so a value
// is found again in chains.csv by (chain, step, walker). arviz.from_netcdf opens the file.
#include <filesystem>

#include "calibration/calibration_report.hpp"

namespace rbcal::calibration {

// Writes the file when the sample has saved draws and returns its path (empty otherwise);
// throws std::runtime_error naming the file.
std::filesystem::path write_posterior_netcdf(const SampleReport& sample, const std::filesystem::path& folder);

}  // namespace rbcal::calibration
