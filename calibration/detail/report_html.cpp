#include "calibration/detail/report_html.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/calibration_report.hpp"
#include "formats/json_file.hpp"
#include "formats/short_number.hpp"

namespace rbcal::calibration {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string number(const json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? formats::short_number(j[key].get<double>(), 4) : "-";
}

std::string interval(const json& method, const char* key) {
  if (!method.contains(key)) return "-";
  const json& i = method[key];
  return "[" + number(i, "lower") + ", " + number(i, "upper") + "] (" +
         formats::short_number(100.0 * i.value("level", 0.95), 3) + " %)";
}

// An SVG file's drawing, without the XML prologue, for inlining.
std::string inline_svg(const fs::path& file) {
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto start = text.find("<svg");
  return start == std::string::npos ? "" : text.substr(start);
}

void method_rows(std::ostringstream& h, const json& methods) {
  h << "<table><tr><th>method</th><th>G<sub>s</sub> [uN/m]</th><th>interval</th><th>lambda</th>"
       "<th>eta0 [mPa s]</th><th>notes</th></tr>\n";
  if (methods.contains("alpha")) {
    const json& a = methods["alpha"];
    h << "<tr><td>alpha method</td><td>" << number(a, "G_s_uN_per_m") << "</td><td>sd " << number(a, "G_s_sd_uN_per_m")
      << " over the matched shear rates</td><td>-</td><td>-</td><td>the seed study's method</td></tr>\n";
  }
  if (methods.contains("direct")) {
    const json& d = methods["direct"];
    h << "<tr><td>direct fit</td><td>" << number(d, "G_s_uN_per_m") << "</td><td>" << interval(d, "interval_uN_per_m")
      << "</td><td>" << number(d, "lambda") << "</td><td>" << number(d, "eta0_mPa_s") << "</td><td>"
      << (d.value("converged", false) ? "converged" : "not converged") << ", chi<sup>2</sup> " << number(d, "chi_square")
      << " on " << number(d, "degrees_of_freedom") << " degrees of freedom</td></tr>\n";
  }
  if (methods.contains("mcmc")) {
    const json& m = methods["mcmc"];
    const json diagnostics = m.value("diagnostics", json::object());
    h << "<tr><td>MCMC</td><td>" << number(m, "G_s_uN_per_m") << "</td><td>" << interval(m, "interval_uN_per_m")
      << "</td><td>" << number(m, "lambda") << "</td><td>" << number(m, "eta0_mPa_s") << "</td><td>"
      << escaped(m.value("G_s_statistic", "")) << "; R-hat " << number(diagnostics, "rhat") << ", ESS "
      << number(diagnostics, "ess") << "</td></tr>\n";
  }
  h << "</table>\n";
}

void sample_section(std::ostringstream& h, const json& sample, const fs::path& folder) {
  const std::string name = sample.value("name", "");
  h << "<h2>" << escaped(name) << "</h2>\n";
  if (sample.contains("methods")) method_rows(h, sample["methods"]);
  std::vector<std::string> notes;
  for (const json& w : sample.value("warnings", json::array())) notes.push_back("warning: " + w.get<std::string>());
  if (sample.contains("consistency")) {
    const json& c = sample["consistency"];
    for (const json& b : c.value("at_bounds", json::array()))
      notes.push_back("consistency: " + b.value("parameter", std::string()) + " (" + b.value("method", std::string()) +
                      ") " + number(b, "value") + " sits at the " + b.value("bound", std::string()) +
                      " end of its range: the data push it against the model's range");
    for (const json& m : c.value("method_comparisons", json::array()))
      if (!m.value("overlap", true))
        notes.push_back("consistency: the intervals of " + m["methods"][0].get<std::string>() + " and " +
                        m["methods"][1].get<std::string>() + " do not overlap");
  }
  if (sample.contains("posterior_predictive_check")) {
    const json& p = sample["posterior_predictive_check"];
    notes.push_back("posterior-predictive check: " + number(p, "points_outside") + " points outside their " +
                    formats::short_number(100.0 * p.value("level", 0.95), 3) + " % predictive intervals (" +
                    number(p, "expected_outside") + " expected; tail probability " + number(p, "tail_probability") +
                    ")" + (p.value("disagrees", false) ? ": the model does not follow these data" : ""));
  }
  if (sample.contains("evidence")) {
    const json& e = sample["evidence"];
    notes.push_back("evidence: ln Z " + number(e, "laplace") + " (Laplace), " + number(e, "importance_sampling") + " +- " +
                    number(e, "importance_sampling_error") + " (importance sampling)");
  }
  if (!notes.empty()) {
    h << "<ul>\n";
    for (const std::string& n : notes) h << "<li>" << escaped(n) << "</li>\n";
    h << "</ul>\n";
  }
  // The plots of this sample, in reading order.
  const std::string stem = sample_file_stem(name);
  for (const char* plot : {"_fit", "_gs_posterior", "_ppc", "_alpha", "_gs_vs_ca"}) {
    const fs::path svg = folder / (stem + plot + ".svg");
    if (fs::exists(svg)) h << "<figure>" << inline_svg(svg) << "</figure>\n";
  }
}

// The joint posterior over the samples (--joint, --compare): G_s per sample, the shared
// nuisances, the population layer, and the comparison's ratio in words.
void joint_section(std::ostringstream& h, const json& summary) {
  if (summary.contains("joint")) {
    const json& j = summary["joint"];
    h << "<h2>Joint posterior over the samples</h2>\n<p>One posterior over all selected samples: the model's "
         "nuisances shared, G<sub>s</sub> and eta0 per sample, lambda "
      << (j.value("shared_lambda", false) ? "shared" : "per sample")
      << (j.value("hierarchical", false) ? ", with a population layer ln G<sub>s</sub> ~ N(mu, tau)" : "")
      << ".</p>\n<table><tr><th>sample</th><th>G<sub>s</sub> [uN/m]</th><th>interval</th></tr>\n";
    for (const json& s : j.value("samples", json::array()))
      h << "<tr><td>" << escaped(s.value("sample", "")) << "</td><td>" << number(s, "shear_modulus_median_uN_per_m")
        << "</td><td>" << interval(s, "shear_modulus_interval_uN_per_m") << "</td></tr>\n";
    for (const json& n : j.value("shared_nuisances", json::array()))
      h << "<tr><td>" << escaped(n.value("name", "")) << " (shared)</td><td>" << number(n, "median") << "</td><td>"
        << interval(n, "interval") << "</td></tr>\n";
    if (j.contains("population")) {
      const json& p = j["population"];
      h << "<tr><td>population median exp(mu)</td><td>" << number(p, "median_shear_modulus_uN_per_m") << "</td><td>"
        << interval(p, "median_shear_modulus_interval_uN_per_m") << "</td></tr>\n<tr><td>tau (sd of ln G<sub>s</sub>)"
        << "</td><td>" << number(p, "tau") << "</td><td>" << interval(p, "tau_interval") << "</td></tr>\n";
    }
    h << "</table>\n";
    if (j.contains("mcmc"))
      h << "<p>Sampler: " << escaped(j["mcmc"].value("sampler", "")) << "; " << escaped(j["mcmc"].value("stop_reason", ""))
        << ".</p>\n";
  }
  if (summary.contains("comparison")) {
    const json& c = summary["comparison"];
    h << "<h2>Comparison</h2>\n<p>G<sub>s</sub>(" << escaped(c.value("numerator", "")) << ") / G<sub>s</sub>("
      << escaped(c.value("denominator", "")) << ") = " << number(c, "ratio_median") << ", " << interval(c, "interval")
      << "; probability that the ratio exceeds 1: " << number(c, "probability_numerator_greater") << " ("
      << number(c, "pairs") << " draws; " << escaped(c.value("source", "")) << ").</p>\n";
  }
}

}  // namespace

void write_report_html(const json& summary, const fs::path& folder) {
  std::ostringstream h;
  const json provenance = summary.value("provenance", json::object());
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>rbcal calibration report</title>\n"
       "<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}"
       "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:4px 8px;text-align:left}"
       "th{background:#eee}figure{margin:1em 0}figure svg{max-width:100%;height:auto}"
       "code{background:#f4f4f4;padding:1px 3px}</style></head><body>\n"
       "<h1>rbcal calibration report</h1>\n<p>Membrane shear elasticity G<sub>s</sub> of the cells of each sample, "
       "from its viscosity curves. Data: <code>"
    << escaped(provenance.value("data_file", "")) << "</code>; model: <code>"
    << escaped(provenance.value("surrogate_file", "")) << "</code>.</p>\n";
  for (const json& sample : summary.value("samples", json::array())) sample_section(h, sample, folder);
  joint_section(h, summary);
  h << "<h2>Provenance</h2>\n<table>\n";
  for (const char* key : {"rbcal_version", "git_revision", "date", "host", "command_line", "seed"})
    if (provenance.contains(key))
      h << "<tr><th>" << key << "</th><td><code>"
        << escaped(provenance[key].is_string() ? provenance[key].get<std::string>() : provenance[key].dump())
        << "</code></td></tr>\n";
  h << "</table>\n<p>Files of this report: ";
  for (const json& f : summary.value("files", json::array())) {
    const std::string file = f.get<std::string>();
    h << "<a href=\"" << escaped(file) << "\">" << escaped(file) << "</a> ";
  }
  h << "</p>\n</body></html>\n";
  formats::write_file_atomically(folder / "report.html", h.str());
}

}  // namespace rbcal::calibration
