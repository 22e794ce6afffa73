#include "calibration/detail/report_tables.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "formats/units.hpp"
#include "calibration/saved_draws.hpp"
#include "formats/short_number.hpp"

namespace rbcal::calibration {

namespace {

// Shortest round-trippable-enough text for a table (9 significant digits); empty for NaN.
std::string number(double x) {
  return std::isfinite(x) ? formats::short_number(x, 9) : "";
}

class CsvFile {
 public:
  CsvFile(const std::filesystem::path& file, const std::string& header) : path_(file), out_(file) {
    if (!out_) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
    out_ << header << "\n";
  }
  template <typename... Fields>
  void row(const Fields&... fields) {
    bool first = true;
    ((out_ << (first ? "" : ",") << fields, first = false), ...);
    out_ << "\n";
    ++rows_;
  }
  int close() {
    out_.flush();
    const int flush_error = out_ ? 0 : errno;
    out_.close();
    // The reason (a full disk, a folder gone read-only) is errno of the write that failed.
    if (!out_ || flush_error)
      throw std::runtime_error("error while writing " + path_.string() + ": " + std::strerror(flush_error ? flush_error : errno));
    return rows_;
  }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  int rows_ = 0;
};

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

double model_alpha_shear_rate(const AlphaMethodResult& alpha, double capillary_number, double cell_radius) {
  if (alpha.shear_modulus.count == 0 || !(alpha.plasma_viscosity > 0.0)) return 0.0;
  return capillary_number * alpha.shear_modulus.mean / (alpha.plasma_viscosity * cell_radius);
}

int write_fits_table(const CalibrationReport& report, const std::filesystem::path& file) {
  CsvFile csv(file,
              "sample,line,phi,shear_rate_per_s,eta_mPa_s,eta_se_mPa_s,eta_re,eta_re_sd,capillary_number,"
              "predicted_eta_re,predicted_sd,predicted_eta_mPa_s,residual,weighted_residual,used,reason");
  for (const SampleReport& s : report.samples) {
    const std::string name = csv_field(s.sample.name);
    const double eta0 = s.sample.plasma.eta0;
    auto unpredicted_row = [&](const RelativeViscosityPoint& p, const std::string& reason) {
      csv.row(name, p.line, number(p.phi), number(p.shear_rate), number(kMilli * measured_viscosity(p, eta0)),
              number(kMilli * measured_se(p, eta0)), number(p.eta_re), number(p.eta_re_sd), "", "", "", "", "", "", 0,
              csv_field(reason));
    };
    if (const DirectFitResult* fit = s.point_fit()) {
      // Predictions at the fit's eta0 (fitted as a nuisance parameter, or the plateau value).
      for (const FittedPoint& f : fit->points) {
        const RelativeViscosityPoint& p = f.point;
        const bool predicted = f.predicted_eta_re > 0.0;
        csv.row(name, p.line, number(p.phi), number(p.shear_rate), number(kMilli * measured_viscosity(p, eta0)),
                number(kMilli * measured_se(p, eta0)), number(p.eta_re), number(p.eta_re_sd),
                number(f.capillary_number), predicted ? number(f.predicted_eta_re) : "",
                predicted ? number(f.predicted_sd) : "",
                predicted ? number(kMilli * fit->plasma_viscosity * f.predicted_eta_re) : "",
                predicted ? number(p.eta_re - f.predicted_eta_re) : "",
                predicted ? number(f.weighted_residual) : "", f.used ? 1 : 0, csv_field(f.reason));
      }
    } else {
      for (const RelativeViscosityPoint& p : s.sample.points)
        unpredicted_row(p, "no point-wise fit (direct and mcmc not run)");
    }
    for (const LeftOutPoint& l : s.left_out) unpredicted_row(l.point, "left out: " + l.reason);
  }
  return csv.close();
}

int write_alpha_table(const CalibrationReport& report, const std::filesystem::path& file) {
  CsvFile csv(file, "sample,source,shear_rate_per_s,capillary_number,alpha,r_squared,points");
  for (const SampleReport& s : report.samples) {
    if (!s.alpha) continue;
    const std::string name = csv_field(s.sample.name);
    for (const ShearRateAlpha& m : s.alpha->measured) {
      // The Ca this shear rate was matched to, if any.
      std::string ca;
      for (const AlphaMatch& match : s.alpha->per_shear_rate)
        if (match.matched && match.shear_rate == m.shear_rate) ca = number(match.capillary_number);
      csv.row(name, "measured", number(m.shear_rate), ca, number(m.fit.alpha), number(m.fit.r_squared), m.fit.points);
    }
    for (const CapillaryAlpha& m : s.alpha->model) {
      const double rate = model_alpha_shear_rate(*s.alpha, m.capillary_number, report.cell_radius);
      csv.row(name, "model", rate > 0.0 ? number(rate) : "", number(m.capillary_number), number(m.fit.alpha),
              number(m.fit.r_squared), m.fit.points);
    }
  }
  return csv.close();
}

int write_gs_per_ca_table(const CalibrationReport& report, const std::filesystem::path& file) {
  CsvFile csv(file, "sample,direction,capillary_number,shear_rate_per_s,alpha,G_s_uN_per_m,matched,message");
  for (const SampleReport& s : report.samples) {
    if (!s.alpha) continue;
    const std::string name = csv_field(s.sample.name);
    auto write = [&](const AlphaMatch& m, const char* direction) {
      csv.row(name, direction, m.capillary_number > 0.0 ? number(m.capillary_number) : "",
              m.shear_rate > 0.0 ? number(m.shear_rate) : "", m.matched ? number(m.alpha) : "",
              m.matched ? number(kMicro * m.shear_modulus) : "", m.matched ? 1 : 0, csv_field(m.message));
    };
    for (const AlphaMatch& m : s.alpha->per_shear_rate) write(m, "shear_rate_to_ca");
    for (const AlphaMatch& m : s.alpha->per_capillary_number) write(m, "ca_to_shear_rate");
  }
  return csv.close();
}

int write_chains_table(const CalibrationReport& report, const std::filesystem::path& file, int max_draws_per_sample) {
  // Physical columns, the same for every sample; empty where a quantity was not sampled.
  CsvFile csv(file, "sample,chain,step,walker,G_s_uN_per_m,lambda,sigma_d,eta0_mPa_s,log_posterior");
  for (const SampleReport& s : report.samples) {
    if (!s.mcmc) continue;
    const McmcResult& r = s.mcmc->mcmc;
    int lambda = -1, sigma = -1, eta0 = -1;
    for (int p = 0; p < static_cast<int>(r.parameter_names.size()); ++p) {
      if (r.parameter_names[p] == "ln_lambda") lambda = p;
      if (r.parameter_names[p] == "ln_sigma_d") sigma = p;
      if (r.parameter_names[p] == "ln_eta0") eta0 = p;
    }
    const DrawThinning thinning = thin_draws(r, max_draws_per_sample);
    const std::string name = csv_field(s.sample.name);
    auto value = [](const EnsembleChain& c, int step, int walker, int p, double scale) {
      return p < 0 ? std::string() : number(scale * std::exp(c.value(step, walker, p)));
    };
    for (std::size_t k = 0; k < r.chains.size(); ++k) {
      const EnsembleChain& c = r.chains[k];
      for (int step = thinning.first; step < c.steps(); step += thinning.thin)
        for (int w = 0; w < c.walkers(); ++w)
          csv.row(name, k, step, w, value(c, step, w, 0, kMicro), value(c, step, w, lambda, 1.0),
                  value(c, step, w, sigma, 1.0), value(c, step, w, eta0, kMilli), number(c.log_density(step, w)));
    }
  }
  return csv.close();
}

int write_bands_table(const CalibrationReport& report, const std::filesystem::path& file) {
  CsvFile csv(file, "sample,phi,shear_rate_per_s,median_mPa_s,lower_mPa_s,upper_mPa_s,level");
  for (const SampleReport& s : report.samples) {
    const std::string name = csv_field(s.sample.name);
    for (const PredictiveBand& b : s.bands)
      for (std::size_t i = 0; i < b.shear_rate.size(); ++i)
        csv.row(name, number(b.phi), number(b.shear_rate[i]), number(kMilli * b.median[i]),
                number(kMilli * b.lower[i]), number(kMilli * b.upper[i]), number(s.band_level));
  }
  return csv.close();
}

}  // namespace rbcal::calibration
