#include "calibration/calibration_report.hpp"

#include <unistd.h>

#include <stdexcept>

#include "calibration/detail/posterior_netcdf.hpp"
#include "calibration/detail/report_html.hpp"
#include "calibration/detail/report_plots.hpp"
#include "calibration/report_summary.hpp"
#include "calibration/detail/report_tables.hpp"
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

namespace {

// Every file of the report, written into `folder` (which exists and is empty).
ReportFiles write_report_files(const CalibrationReport& report, const std::filesystem::path& folder,
                               const ReportOptions& options) {
  ReportFiles out;
  out.folder = folder;
  write_fits_table(report, folder / "fits.csv");
  write_alpha_table(report, folder / "alpha.csv");
  write_gs_per_ca_table(report, folder / "gs_per_ca.csv");
  write_chains_table(report, folder / "chains.csv", options.max_chain_draws);
  write_bands_table(report, folder / "bands.csv");
  for (const char* name : {"fits.csv", "alpha.csv", "gs_per_ca.csv", "chains.csv", "bands.csv"})
    out.files.push_back(folder / name);
  for (const SampleReport& s : report.samples)
    if (const std::filesystem::path nc = write_posterior_netcdf(s, folder); !nc.empty()) out.files.push_back(nc);

  if (options.plots) {
    PlotOutcome plots = write_report_plots(report, folder, options);
    out.plots_written = plots.written;
    out.plots_message = plots.message;
    out.files.insert(out.files.end(), plots.files.begin(), plots.files.end());
  } else {
    out.plots_message = "plots not requested";
  }

  // The page is listed before the summary is made, so that summary.json names it too.
  out.files.push_back(folder / "report.html");
  const std::filesystem::path summary = folder / "summary.json";
  const nlohmann::json content = report_summary(report, out);
  formats::write_json_atomically(summary, content);
  out.files.push_back(summary);
  write_report_html(content, folder);
  return out;
}

}  // namespace

ReportFiles write_calibration_report(const CalibrationReport& report, const std::filesystem::path& folder,
                                     const ReportOptions& options) {
  namespace fs = std::filesystem;
  // The report is built in a folder beside the old one and renamed into its place, so that a
  // report folder always holds one run's files: never an old summary beside new tables, or a
  // previous run's plots after a --no-plots run, whatever fails half-way (a full disk, a
  // folder that turns read-only). On failure the old report stays and nothing else is left.
  const fs::path target = folder.has_filename() ? folder : folder.parent_path();
  const std::string tag = "." + std::to_string(::getpid());
  const fs::path staging = target.string() + ".new" + tag, previous = target.string() + ".old" + tag;
  std::error_code ec;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
  fs::remove_all(staging, ec);
  if (!fs::create_directory(staging, ec) || ec)
    throw std::runtime_error("cannot create report folder " + staging.string() + (ec ? ": " + ec.message() : ""));
  ReportFiles out;
  try {
    out = write_report_files(report, staging, options);
    if (fs::exists(target)) {
      if (!fs::is_directory(target)) throw std::runtime_error(target.string() + " exists and is not a folder");
      fs::rename(target, previous);
    }
    try {
      fs::rename(staging, target);
    } catch (...) {
      if (fs::exists(previous)) fs::rename(previous, target, ec);  // put the old report back
      throw;
    }
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(staging, ec);
    throw std::runtime_error("cannot write the report into " + target.string() + ": " + e.code().message());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
  fs::remove_all(previous, ec);
  for (fs::path& f : out.files) f = target / f.lexically_relative(staging);
  out.folder = target;
  return out;
}

}  // namespace rbcal::calibration
