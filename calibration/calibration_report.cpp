#include "calibration/calibration_report.hpp"

#include <stdexcept>

#include "calibration/report_plots.hpp"
#include "calibration/report_summary.hpp"
#include "calibration/report_tables.hpp"
#include "formats/json_file.hpp"

namespace rbcal::calibration {

bool SampleReport::has_estimate() const {
  return (alpha && alpha->shear_modulus.count > 0) || (direct && direct->shear_modulus > 0.0) ||
         (mcmc && mcmc->shear_modulus_median > 0.0);
}

const DirectFitResult* SampleReport::point_fit() const {
  if (direct) return &*direct;
  if (mcmc) return &mcmc->start_fit;
  return nullptr;
}

std::string sample_file_stem(const std::string& sample_name) {
  std::string stem;
  for (char c : sample_name) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                      c == '_' || c == '.';
    stem += safe ? c : '_';
  }
  if (stem.empty() || stem.front() == '.') stem.insert(stem.begin(), '_');  // never hidden, never empty
  return stem;
}

ReportFiles write_calibration_report(const CalibrationReport& report, const std::filesystem::path& folder,
                                     const ReportOptions& options) {
  ReportFiles out;
  out.folder = folder;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw std::runtime_error("cannot create report folder " + folder.string() + (ec ? ": " + ec.message() : ""));

  write_fits_table(report, folder / "fits.csv");
  write_alpha_table(report, folder / "alpha.csv");
  write_gs_per_ca_table(report, folder / "gs_per_ca.csv");
  write_chains_table(report, folder / "chains.csv", options.max_chain_draws);
  write_bands_table(report, folder / "bands.csv");
  for (const char* name : {"fits.csv", "alpha.csv", "gs_per_ca.csv", "chains.csv", "bands.csv"})
    out.files.push_back(folder / name);

  if (options.plots) {
    PlotOutcome plots = write_report_plots(report, folder, options);
    out.plots_written = plots.written;
    out.plots_message = plots.message;
    out.files.insert(out.files.end(), plots.files.begin(), plots.files.end());
  } else {
    out.plots_message = "plots not requested";
  }

  const std::filesystem::path summary = folder / "summary.json";
  formats::write_json_atomically(summary, report_summary(report, out));
  out.files.push_back(summary);
  return out;
}

}  // namespace rbcal::calibration
