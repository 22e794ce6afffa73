#pragma once
// The plots of a calibration report, drawn by gnuplot (PNG and SVG of each), per sample:
//   STEM_fit          eta [mPa s] vs shear rate [1/s], log-log: data with error bars, the point-wise
//                     fit and the posterior-predictive median with its band, one colour per phi
//   STEM_gs_posterior histogram of the posterior of G_s [uN/m] with median and credible interval
//   STEM_alpha        alpha vs shear rate [1/s]: measured, and the model's alpha(Ca) mapped to shear
//                     rates with the alpha method's G_s
//   STEM_gs_vs_ca     G_s [uN/m] vs Ca from the alpha method's matches, their mean, the MCMC interval
// The data is inlined in one script (plots.gp, data blocks) so that the folder re-plots with
// `gnuplot plots.gp` after editing. A missing or failing gnuplot is reported, never thrown.
#include <filesystem>
#include <string>
#include <vector>

#include "calibration/calibration_report.hpp"

namespace rbcal::calibration {

struct PlotOutcome {
  bool written = false;
  std::string message;                       // why not (gnuplot missing, failed: see gnuplot.log)
  std::vector<std::filesystem::path> files;  // plots.gp, and the images when written
};

// The gnuplot script for every plot; png_terminal is e.g. "pngcairo" or "png".
std::string report_plot_script(const CalibrationReport& report, const ReportOptions& options,
                               const std::string& png_terminal);

// Full path of the gnuplot program (options.gnuplot, searched on PATH when it has no '/'); empty if none.
std::filesystem::path find_gnuplot(const std::string& program);

PlotOutcome write_report_plots(const CalibrationReport& report, const std::filesystem::path& folder,
                               const ReportOptions& options);

}  // namespace rbcal::calibration
