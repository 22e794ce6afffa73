#include "calibration/detail/report_plots.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "calibration/quantiles.hpp"
#include "calibration/detail/report_tables.hpp"
#include "formats/units.hpp"
#include "formats/short_number.hpp"

namespace rbcal::calibration {

namespace {

namespace fs = std::filesystem;

std::string num(double x) { return formats::short_number(x, 9); }

// For legends: four significant digits.
std::string short_num(double x) { return formats::short_number(x, 4); }

// A gnuplot double-quoted string.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// A POSIX shell single-quoted word.
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// One plot: its file stem and the gnuplot commands after `set output` (data blocks apart).
struct PlotBody {
  std::string stem;
  std::string commands;
};

class ScriptBuilder {
 public:
  // A named data block of rows; returns its name.
  std::string block(const std::string& name, const std::vector<std::vector<double>>& rows) {
    data_ << "$" << name << " << EOD\n";
    for (const auto& row : rows) {
      for (std::size_t k = 0; k < row.size(); ++k) data_ << (k ? " " : "") << (std::isfinite(row[k]) ? num(row[k]) : "NaN");
      data_ << "\n";
    }
    data_ << "EOD\n";
    return "$" + name;
  }
  void add(PlotBody body) { plots_.push_back(std::move(body)); }
  const std::vector<PlotBody>& plots() const { return plots_; }
  std::string data() const { return data_.str(); }

 private:
  std::ostringstream data_;
  std::vector<PlotBody> plots_;
};

std::string header(const std::string& title) {
  // The legend below the plot, in rows: at the right it took half the width of the figure.
  return "reset\nset title " + quoted(title) + "\nset grid\nset key below center horizontal\nset datafile missing 'NaN'\n";
}

// (a) eta vs shear rate per phi: data, point-wise fit, posterior-predictive median and band.
void fit_plot(ScriptBuilder& b, const SampleReport& s, const std::string& stem, int index) {
  const DirectFitResult* fit = s.point_fit();
  std::map<double, std::vector<const RelativeViscosityPoint*>> by_phi;
  for (const auto& p : s.sample.points) by_phi[p.phi].push_back(&p);
  std::map<double, std::vector<const RelativeViscosityPoint*>> left_out_by_phi;  // drawn open
  for (const auto& l : s.left_out) {
    left_out_by_phi[l.point.phi].push_back(&l.point);
    by_phi[l.point.phi];  // a phi with left-out points only still gets its colour
  }
  std::string plot;
  int colour = 0;
  bool has_band = false;
  // The viscosity axis spans what is drawn, not the decades around it (a log axis would
  // otherwise show 1-10 mPa s for data between 3 and 8).
  double y_lo = 1e300, y_hi = 0.0;
  auto extend = [&](double y) {
    if (std::isfinite(y) && y > 0.0) y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
  };
  for (const auto& [phi, points] : by_phi) {
    ++colour;
    const std::string id = "s" + std::to_string(index) + "_phi" + std::to_string(colour);
    const std::string lt = " lt " + std::to_string(colour);
    const std::string phi_text = "phi = " + num(phi);
    for (const PredictiveBand& band : s.bands) {
      if (band.phi != phi) continue;
      std::vector<std::vector<double>> rows;
      for (std::size_t i = 0; i < band.shear_rate.size(); ++i)
        rows.push_back({band.shear_rate[i], kMilli * band.median[i], kMilli * band.lower[i], kMilli * band.upper[i]});
      for (const auto& r : rows) extend(r[2]), extend(r[3]);
      const std::string name = b.block(id + "_band", rows);
      plot += name + " using 1:3:4 with filledcurves" + lt + " fs transparent solid 0.2 noborder notitle, \\\n  ";
      plot += name + " using 1:2 with lines" + lt + " lw 2 notitle, \\\n  ";
      has_band = true;
    }
    // Data (filled: used by the fit, open: skipped) and the point-wise fit, by shear rate.
    std::vector<std::vector<double>> rows;
    const double eta0 = s.sample.plasma.eta0;
    auto add_row = [&](const RelativeViscosityPoint& p, bool used, double predicted) {
      const double eta = kMilli * measured_viscosity(p, eta0), se = kMilli * measured_se(p, eta0);
      rows.push_back({p.shear_rate, eta, se, used ? 1.0 : 0.0, predicted});
      extend(eta - se), extend(eta + se), extend(predicted);
    };
    if (fit) {
      for (const FittedPoint& f : fit->points)
        if (f.point.phi == phi)
          add_row(f.point, f.used,
                  f.predicted_eta_re > 0.0 ? kMilli * fit->plasma_viscosity * f.predicted_eta_re : NAN);
    } else {
      for (const RelativeViscosityPoint* p : points) add_row(*p, true, NAN);
    }
    for (const RelativeViscosityPoint* p : left_out_by_phi[phi]) add_row(*p, false, NAN);
    std::sort(rows.begin(), rows.end());
    const std::string data = b.block(id + "_data", rows);
    if (fit)
      plot += data + " using 1:5 with lines" + lt + " dt 2 lw 1.5 notitle, \\\n  ";
    // The phi's title goes with whichever symbol it has (all its points may be left out).
    const bool any_used = std::any_of(rows.begin(), rows.end(), [](const auto& r) { return r[3] > 0.0; });
    plot += data + " using 1:($4 > 0 ? $2 : NaN):3 with yerrorbars" + lt + " pt 7 ps 0.8 " +
            (any_used ? "title " + quoted(phi_text) : std::string("notitle")) + ", \\\n  ";
    plot += data + " using 1:($4 > 0 ? NaN : $2):3 with yerrorbars" + lt + " pt 6 ps 0.8 " +
            (any_used ? std::string("notitle") : "title " + quoted(phi_text)) + ", \\\n  ";
  }
  if (plot.empty()) return;
  // One legend entry per line style instead of one per phi and style.
  if (has_band)
    plot += "keyentry with filledcurves fc \"gray\" fs solid 0.3 title " +
            quoted("posterior-predictive " + num(100 * s.band_level) + " % band") + ", \\\n  " +
            "keyentry with lines lc \"black\" lw 2 title \"posterior median\", \\\n  ";
  if (fit)
    plot += std::string("keyentry with lines lc \"black\" dt 2 title ") + (s.direct ? "\"direct fit\"" : "\"MCMC start fit\"") +
            ", \\\n  ";
  plot += "keyentry with points lc \"black\" pt 6 title \"not fitted (left out: fits.csv says why)\", \\\n  ";
  plot.erase(plot.size() - 6);  // the last ", \\\n  "
  std::string y_range;
  if (y_hi > y_lo) {
    // Within a decade a log axis has no labelled tick: label 1, 1.5, 2, 3, 4, 5, 6, 8 x 10^k.
    const double lo = y_lo / 1.06, hi = y_hi * 1.06;
    std::string tics;
    for (int k = static_cast<int>(std::floor(std::log10(lo))); k <= static_cast<int>(std::ceil(std::log10(hi))); ++k)
      for (double m : {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0}) {
        const double t = m * std::pow(10.0, k);
        if (t >= lo && t <= hi) tics += (tics.empty() ? "" : ", ") + num(t);
      }
    y_range = "set yrange [" + num(lo) + ":" + num(hi) + "]\n" + (tics.empty() ? "" : "set ytics (" + tics + ")\n");
  }
  b.add({stem + "_fit", header(s.sample.name + ": suspension viscosity, fit and band per phi") +
                            "set logscale xy\nset xlabel \"shear rate [1/s]\"\n" + y_range +
                            "set ylabel \"viscosity eta [mPa s]\"\nplot " + plot + "\n"});
}

// Tics of a logarithmic G_s axis [uN/m]: 1, 2, 5 per decade.
constexpr const char* kShearModulusTics = "(0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100)";

// (b) posterior histogram of G_s with median and credible interval (and the direct estimate).
void posterior_plot(ScriptBuilder& b, const SampleReport& s, const std::string& stem, int index, int bins) {
  if (!s.mcmc) return;
  std::vector<double> draws = s.mcmc->shear_modulus_draws();
  if (draws.size() < 2) return;
  for (double& x : draws) x *= kMicro;
  // Range from the 0.1 % and 99.9 % quantiles so that a few stray draws do not squeeze the bars.
  const double lo = quantile(draws, 0.001), hi = quantile(draws, 0.999);
  if (!(hi > lo && lo > 0.0)) return;
  // A posterior spread over more than a factor 4 is drawn over ln G_s (bins equal in ln G_s,
  // density per unit of ln G_s, a logarithmic axis): on a linear axis its long right tail
  // squeezed the bulk into a fifth of the width.
  const bool logarithmic = hi / lo > 4.0;
  auto axis = [&](double x) { return logarithmic ? std::log(x) : x; };
  auto value = [&](double u) { return logarithmic ? std::exp(u) : u; };
  bins = std::max(5, bins);
  const double width = (axis(hi) - axis(lo)) / bins;
  std::vector<double> counts(static_cast<std::size_t>(bins), 0.0);
  for (double x : draws) {
    if (x < lo || x > hi) continue;
    counts[static_cast<std::size_t>(std::min(bins - 1, static_cast<int>((axis(x) - axis(lo)) / width)))] += 1.0;
  }
  // x, density, bin edges: boxes drawn edge to edge on either axis.
  std::vector<std::vector<double>> rows;
  for (int k = 0; k < bins; ++k)
    rows.push_back({value(axis(lo) + (k + 0.5) * width), counts[static_cast<std::size_t>(k)] / (draws.size() * width),
                    value(axis(lo) + k * width), value(axis(lo) + (k + 1) * width)});
  const std::string hist = b.block("s" + std::to_string(index) + "_hist", rows);
  const double median = kMicro * s.mcmc->shear_modulus_median;
  const Interval& ci = s.mcmc->shear_modulus_interval;
  std::string c = header(s.sample.name + ": posterior of G_s");
  c += logarithmic ? "set logscale x\nset xtics " + std::string(kShearModulusTics) +
                         "\nset ylabel \"posterior density [per unit of ln G_s]\"\n"
                   : std::string("set ylabel \"posterior density [1/(uN/m)]\"\n");
  c += "set xlabel \"G_s [uN/m]\"\nset xrange [" + num(lo) + ":" + num(hi) + "]\nset style fill solid 0.5\n";
  std::string plot = hist + " using 1:(0.5*$2):3:4:(0):2 with boxxyerror lt 1 title \"posterior (" +
                     std::to_string(draws.size()) + " draws)\"";
  // Vertical lines as parametric curves x = const, y = t over the histogram's height.
  auto vertical = [&](double x, const std::string& style, const std::string& title) {
    plot += ", \\\n  " + num(x) + ",t with lines " + style + (title.empty() ? " notitle" : " title " + quoted(title));
  };
  double top = 0.0;
  for (const auto& r : rows) top = std::max(top, r[1]);
  c += "set parametric\nset trange [0:" + num(1.05 * top) + "]\nset yrange [0:" + num(1.1 * top) + "]\n";
  vertical(median, "lt 2 lw 2", "median " + short_num(median) + " uN/m");
  vertical(kMicro * ci.lower, "lt 2 dt 2", num(100 * ci.level) + " % interval");
  vertical(kMicro * ci.upper, "lt 2 dt 2", "");
  if (s.direct) vertical(kMicro * s.direct->shear_modulus, "lt 3 lw 2 dt 4", "direct fit");
  b.add({stem + "_gs_posterior", c + "plot " + plot + "\n"});
}

// (c) alpha vs shear rate: measured alpha, and the model's alpha(Ca) at gamma_dot = Ca G_s / (eta0 a).
void alpha_plot(ScriptBuilder& b, const SampleReport& s, const std::string& stem, int index, double cell_radius) {
  if (!s.alpha || s.alpha->measured.empty()) return;
  std::vector<std::vector<double>> measured, model;
  for (const ShearRateAlpha& m : s.alpha->measured) measured.push_back({m.shear_rate, m.fit.alpha, m.fit.r_squared});
  for (const CapillaryAlpha& m : s.alpha->model) {
    const double rate = model_alpha_shear_rate(*s.alpha, m.capillary_number, cell_radius);
    if (rate > 0.0) model.push_back({rate, m.fit.alpha});
  }
  const std::string id = "s" + std::to_string(index);
  std::string plot = b.block(id + "_alpha_measured", measured) + " using 1:2 with points lt 1 pt 7 title \"measured (fit of exp(alpha phi))\"";
  if (!model.empty())
    plot += ", \\\n  " + b.block(id + "_alpha_model", model) + " using 1:2 with lines lt 2 lw 2 title " +
            quoted("model, Ca mapped with G_s = " + short_num(kMicro * s.alpha->shear_modulus.mean) + " uN/m");
  b.add({stem + "_alpha", header(s.sample.name + ": alpha in eta_re = exp(alpha phi)") +
                              "set logscale x\nset xlabel \"shear rate [1/s]\"\nset ylabel \"alpha [-]\"\nplot " +
                              plot + "\n"});
}

// (d) G_s vs Ca from the alpha method's matches, with their mean and the MCMC's interval; G_s on a
// log axis, as it is inferred (an interval of 0.5-4.5 about points near 1 squeezes them on a linear one).
void gs_ca_plot(ScriptBuilder& b, const SampleReport& s, const std::string& stem, int index) {
  if (!s.alpha) return;
  std::vector<std::vector<double>> per_rate, per_ca;
  for (const AlphaMatch& m : s.alpha->per_shear_rate)
    if (m.matched) per_rate.push_back({m.capillary_number, kMicro * m.shear_modulus});
  for (const AlphaMatch& m : s.alpha->per_capillary_number)
    if (m.matched) per_ca.push_back({m.capillary_number, kMicro * m.shear_modulus});
  if (per_rate.empty() && per_ca.empty()) return;
  std::sort(per_rate.begin(), per_rate.end());
  std::sort(per_ca.begin(), per_ca.end());
  const std::string id = "s" + std::to_string(index);
  std::vector<std::string> parts;
  if (!per_rate.empty())
    parts.push_back(b.block(id + "_gs_rate", per_rate) + " using 1:2 with linespoints lt 1 pt 7 title \"each measured shear rate\"");
  if (!per_ca.empty())
    parts.push_back(b.block(id + "_gs_ca", per_ca) + " using 1:2 with points lt 4 pt 5 title \"each model Ca\"");
  if (s.alpha->shear_modulus.count > 0)
    parts.push_back(num(kMicro * s.alpha->shear_modulus.mean) + " with lines lt 1 dt 2 title " +
                    quoted("alpha method mean " + short_num(kMicro * s.alpha->shear_modulus.mean) + " uN/m"));
  if (s.mcmc) {
    const Interval& ci = s.mcmc->shear_modulus_interval;
    parts.push_back(num(kMicro * ci.lower) + " with lines lt 2 dt 3 title " + quoted("MCMC " + num(100 * ci.level) + " % interval"));
    parts.push_back(num(kMicro * ci.upper) + " with lines lt 2 dt 3 notitle");
  }
  std::string plot;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (k) plot += ", \\\n  ";  // appended in two steps: GCC 12 misreports `literal + string` (-Wrestrict, PR 105329)
    plot += parts[k];
  }
  b.add({stem + "_gs_vs_ca", header(s.sample.name + ": G_s per capillary number (alpha method)") +
                                 "set logscale xy\nset autoscale yfix\nset offsets 0, 0, graph 0.08, graph 0.08\n"
                                 "set ytics " + std::string(kShearModulusTics) + "\n"
                                 "set xlabel \"Ca = eta0 gamma_dot a / G_s [-]\"\n"
                                 "set ylabel \"G_s [uN/m]\"\nplot " + plot + "\n"});
}

// (e) posterior-predictive check: each used point's PIT (the share of its predictive draws
// below the measured value) against shear rate, one colour per phi, with the 95 % band's
// edges. Points agree with the model where they scatter evenly between the edges.
void predictive_check_plot(ScriptBuilder& b, const SampleReport& s, const std::string& stem, int index) {
  if (!s.predictive_check || s.predictive_check->points.empty()) return;
  const PredictiveCheck& check = *s.predictive_check;
  std::map<double, std::vector<std::vector<double>>> by_phi;
  for (const PredictiveCheckPoint& p : check.points) by_phi[p.point.phi].push_back({p.point.shear_rate, p.pit});
  const double tail = 0.5 * (1.0 - check.level);
  std::string plot;
  int colour = 0;
  for (auto& [phi, rows] : by_phi) {
    ++colour;
    std::sort(rows.begin(), rows.end());
    plot += b.block("s" + std::to_string(index) + "_ppc" + std::to_string(colour), rows) + " using 1:2 with points lt " +
            std::to_string(colour) + " pt 7 ps 0.9 title " + quoted("phi = " + num(phi)) + ", \\\n  ";
  }
  plot += num(tail) + " with lines lc \"black\" dt 2 title " +
          quoted("edges of the central " + num(100 * check.level) + " % predictive interval") + ", \\\n  " +
          num(1.0 - tail) + " with lines lc \"black\" dt 2 notitle";
  const std::string title = s.sample.name + ": posterior-predictive check, " + std::to_string(check.outside()) + " of " +
                            std::to_string(check.points.size()) + " points outside (expected " +
                            short_num(check.expected_outside()) + ")";
  b.add({stem + "_ppc", header(title) + "set logscale x\nset xlabel \"shear rate [1/s]\"\n"
                                        "set ylabel \"PIT: share of predictive draws below the measurement\"\n"
                                        "set yrange [-0.02:1.02]\nplot " + plot + "\n"});
}

ScriptBuilder build_plots(const CalibrationReport& report, const ReportOptions& options) {
  ScriptBuilder b;
  for (std::size_t i = 0; i < report.samples.size(); ++i) {
    const SampleReport& s = report.samples[i];
    // Distinct stems even if two names sanitise alike.
    std::string stem = sample_file_stem(s.sample.name);
    for (std::size_t j = 0; j < i; ++j)
      if (sample_file_stem(report.samples[j].sample.name) == stem) stem.append("_").append(std::to_string(i));
    const int index = static_cast<int>(i);
    fit_plot(b, s, stem, index);
    posterior_plot(b, s, stem, index, options.histogram_bins);
    alpha_plot(b, s, stem, index, report.cell_radius);
    gs_ca_plot(b, s, stem, index);
    predictive_check_plot(b, s, stem, index);
  }
  return b;
}

}  // namespace

std::string report_plot_script(const CalibrationReport& report, const ReportOptions& options,
                               const std::string& png_terminal) {
  const ScriptBuilder b = build_plots(report, options);
  std::string script = "# Plots of an rbcal calibration report; re-run with `gnuplot plots.gp` in this folder.\n" + b.data();
  const std::string png = "set terminal " + png_terminal + " size 1000,650 noenhanced" +
                          (png_terminal == "pngcairo" ? " font \",11\"" : "") + "\n";
  const std::string svg = "set terminal svg size 1000,650 noenhanced font \"Helvetica,13\"\n";
  for (const PlotBody& p : b.plots()) {
    script += "\n# " + p.stem + "\n" + png + "set output " + quoted(p.stem + ".png") + "\n" + p.commands + "unset output\n";
    script += svg + "set output " + quoted(p.stem + ".svg") + "\n" + p.commands + "unset output\n";
  }
  return script;
}

fs::path find_gnuplot(const std::string& program) {
  if (program.empty()) return {};
  auto executable = [](const fs::path& p) {
    std::error_code ec;
    const auto st = fs::status(p, ec);
    return !ec && fs::is_regular_file(st) && (st.permissions() & fs::perms::owner_exec) != fs::perms::none;
  };
  if (program.find('/') != std::string::npos) return executable(program) ? fs::path(program) : fs::path();
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && executable(fs::path(dir) / program)) return fs::path(dir) / program;
  return {};
}

PlotOutcome write_report_plots(const CalibrationReport& report, const fs::path& folder, const ReportOptions& options) {
  PlotOutcome out;
  const fs::path gnuplot = find_gnuplot(options.gnuplot);
  if (gnuplot.empty()) {
    out.message = "plots skipped: gnuplot (" + options.gnuplot + ") not found on PATH; install gnuplot-nox";
    return out;
  }
  // pngcairo draws antialiased text and transparent bands; plain png is the fallback.
  const std::string probe = shell_quoted(gnuplot.string()) + " -e 'set terminal pngcairo' >/dev/null 2>&1";
  const std::string png = std::system(probe.c_str()) == 0 ? "pngcairo" : "png";
  const fs::path script = folder / "plots.gp";
  {
    std::ofstream f(script);
    if (!f) throw std::runtime_error("cannot write " + script.string());
    f << report_plot_script(report, options, png);
    if (!f) throw std::runtime_error("error while writing " + script.string());
  }
  out.files.push_back(script);
  const fs::path log = folder / "gnuplot.log";
  const std::string command = "cd " + shell_quoted(folder.string()) + " && " + shell_quoted(gnuplot.string()) +
                              " plots.gp > gnuplot.log 2>&1";
  const int status = std::system(command.c_str());
  const int code = status == -1 ? -1 : (WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
  if (code != 0) {
    out.message = "plots failed: gnuplot exited with status " + std::to_string(code) + ", see " + log.string();
    return out;
  }
  const ScriptBuilder b = build_plots(report, options);
  if (b.plots().empty()) {
    out.message = "no plots: no sample has points to fit (see its warnings)";
    return out;
  }
  for (const PlotBody& p : b.plots())
    for (const char* ext : {".png", ".svg"}) {
      const fs::path image = folder / (p.stem + ext);
      std::error_code ec;
      if (!fs::exists(image, ec) || fs::file_size(image, ec) == 0) {
        out.message = "plots failed: gnuplot did not write " + image.string() + ", see " + log.string();
        return out;
      }
      out.files.push_back(image);
    }
  std::error_code ec;
  fs::remove(log, ec);  // empty on success apart from harmless warnings
  out.written = true;
  return out;
}

}  // namespace rbcal::calibration
