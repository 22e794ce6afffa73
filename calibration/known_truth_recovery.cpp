#include "calibration/known_truth_recovery.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "calibration/calibration_input.hpp"
#include "calibration/calibration_report.hpp"
#include "calibration/quantiles.hpp"
#include "calibration/rheometer_data.hpp"
#include "calibration/sample_mean.hpp"
#include "formats/units.hpp"

namespace rbcal::calibration {

namespace {

RecoveredValue recovered(double estimate, const Interval& interval, double truth) {
  return {estimate, interval, interval.contains(truth)};
}

RecoveryCase case_from(const SampleReport& r, double truth, std::uint64_t seed) {
  RecoveryCase c;
  c.truth = truth;
  c.seed = seed;
  c.warnings = r.warnings;
  if (r.alpha && r.alpha->shear_modulus.count > 0) c.alpha = r.alpha->shear_modulus.mean;
  if (r.direct && r.direct->has_interval_estimate()) c.direct = recovered(r.direct->shear_modulus, r.direct->shear_modulus_interval, truth);
  if (r.mcmc && r.mcmc->start_fit.model_edge == ModelEdge::none)
    c.mcmc = recovered(r.mcmc->shear_modulus_median, r.mcmc->shear_modulus_interval, truth);
  if (r.mcmc)
    c.nuisances = r.mcmc->nuisances;
  else if (r.direct)
    c.nuisances = r.direct->nuisances;
  const auto& compared = r.consistency.comparisons;
  c.methods_agree = c.direct && c.mcmc &&
                    std::all_of(compared.begin(), compared.end(), [](const MethodComparison& m) { return m.overlap; });
  return c;
}

MethodCoverage coverage_of(const std::string& name, const std::vector<RecoveryCase>& cases,
                           std::optional<RecoveredValue> RecoveryCase::*member) {
  MethodCoverage m{name};
  m.asked = static_cast<int>(cases.size());
  std::vector<double> widths, ln_ratios;
  for (const RecoveryCase& c : cases) {
    const auto& v = c.*member;
    if (!v) continue;
    ++m.answered;
    ln_ratios.push_back(std::log(v->estimate / c.truth));
    m.covered += v->covers ? 1 : 0;
    if (v->interval.lower > 0.0) widths.push_back(v->interval.upper / v->interval.lower);
  }
  if (!ln_ratios.empty()) {
    const SampleMean ln_bias = sample_mean(ln_ratios);
    m.bias_factor = std::exp(ln_bias.mean);
    m.bias_factor_se = m.bias_factor * ln_bias.standard_error;
  }
  if (!widths.empty()) m.median_width_factor = quantile(std::move(widths), 0.5);
  return m;
}

std::string shown_value(const std::optional<RecoveredValue>& v) {
  if (!v) return "-";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3g [%.3g, %.3g]%s", v->estimate * kMicro, v->interval.lower * kMicro,
                v->interval.upper * kMicro, v->covers ? "" : " MISSED");
  return buf;
}

std::string shown_value(const std::optional<double>& v) {
  if (!v) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", *v * kMicro);
  return buf;
}

nlohmann::json value_json(const std::optional<RecoveredValue>& v) {
  if (!v) return nullptr;
  return {{"G_s_uN_per_m", v->estimate * kMicro},
          {"interval_uN_per_m", {v->interval.lower * kMicro, v->interval.upper * kMicro}},
          {"covers_truth", v->covers}};
}

nlohmann::json nuisances_json(const std::vector<NuisanceEstimate>& nuisances) {
  nlohmann::json j = nlohmann::json::object();
  for (const NuisanceEstimate& n : nuisances)
    j[n.prior.name] = {{"value", n.value}, {"interval", {n.interval.lower, n.interval.upper}}};
  return j;
}

void write_sample(const RheometerData& data, const std::string& folder, double truth, std::uint64_t seed) {
  std::filesystem::create_directories(folder);
  char name[64];
  std::snprintf(name, sizeof name, "gs%g_seed%llu.csv", truth * kMicro, static_cast<unsigned long long>(seed));
  const std::filesystem::path path = std::filesystem::path(folder) / name;
  std::ofstream out(path);
  write_rheometer_csv(data, out);
  out.close();  // a failed final flush shows only here
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

const MethodCoverage* RecoveryReport::method(const std::string& name) const {
  for (const MethodCoverage& m : coverage)
    if (m.method == name) return &m;
  return nullptr;
}

RecoveryReport recover_known_shear_moduli(const std::vector<SimulatedViscosity>& points,
                                          const surrogate::ViscosityModel& model, const RecoveryOptions& o,
                                          std::ostream& log) {
  if (o.shear_moduli.empty()) throw std::invalid_argument("recovery: no true G_s given");
  if (o.replicates < 1) throw std::invalid_argument("recovery: replicates must be at least 1");
  for (double g : o.shear_moduli)
    if (!(g > 0.0)) throw std::invalid_argument("recovery: every true G_s must be positive");
  RecoveryReport report;
  report.points = points;
  std::ostringstream quiet;  // the methods' own progress: the case line below says what matters
  CalibrationJobOptions job = o.job;  // each synthetic sample is the input's only one
  job.samples.clear();
  job.mcmc_byproducts = false;  // the cases read the intervals only
  for (double truth : o.shear_moduli) {
    for (int r = 0; r < o.replicates; ++r) {
      SyntheticSampleOptions so = o.sample;
      so.shear_modulus = truth;
      so.seed = o.sample.seed + report.cases.size();
      const RheometerData data = synthetic_rheometer_data(points, so);
      if (!o.samples_folder.empty()) write_sample(data, o.samples_folder, truth, so.seed);
      const CalibrationInput input = make_calibration_input(data);
      const CalibrationReport calibrated = calibrate_samples(input, model, job, quiet);
      quiet.str("");
      report.cases.push_back(case_from(calibrated.samples.front(), truth, so.seed));
      const RecoveryCase& c = report.cases.back();
      log << "G_s " << truth * kMicro << " uN/m, seed " << c.seed << ": alpha " << shown_value(c.alpha)
          << "; direct " << shown_value(c.direct) << "; mcmc " << shown_value(c.mcmc)
          << (c.methods_agree || !(o.job.runs("direct") && o.job.runs("mcmc")) ? "" : "; methods disagree");
      for (const NuisanceEstimate& n : c.nuisances) log << "; " << n.prior.name << " " << n.value;
      log << "\n"
          << std::flush;
    }
  }
  for (const auto& [name, member] : {std::pair{"direct", &RecoveryCase::direct}, std::pair{"mcmc", &RecoveryCase::mcmc}})
    if (o.job.runs(name)) report.coverage.push_back(coverage_of(name, report.cases, member));
  report.methods_agree = static_cast<int>(
      std::count_if(report.cases.begin(), report.cases.end(), [](const RecoveryCase& c) { return c.methods_agree; }));
  return report;
}

nlohmann::json RecoveryReport::to_json() const {
  nlohmann::json j;
  j["schema"] = "rbcal.recovery/1";
  for (const SimulatedViscosity& p : points)
    j["points"].push_back({{"id", p.id}, {"phi", p.phi}, {"Ca", p.capillary_number}, {"lambda", p.viscosity_ratio},
                           {"eta_re", p.eta_re}, {"eta_re_se", p.eta_re_se}});
  for (const RecoveryCase& c : cases)
    j["cases"].push_back({{"truth_uN_per_m", c.truth * kMicro}, {"seed", c.seed},
                          {"alpha", c.alpha ? nlohmann::json(*c.alpha * kMicro) : nlohmann::json(nullptr)}, {"direct", value_json(c.direct)},
                          {"mcmc", value_json(c.mcmc)}, {"nuisances", nuisances_json(c.nuisances)},
                          {"methods_agree", c.methods_agree},
                          {"warnings", c.warnings}});
  for (const MethodCoverage& m : coverage)
    j["coverage"][m.method] = {{"answered", m.answered}, {"covered", m.covered}, {"asked", m.asked}, {"fraction", m.fraction()},
                               {"median_width_factor", m.median_width_factor}, {"bias_factor", m.bias_factor},
                               {"bias_factor_se", m.bias_factor_se}};
  j["methods_agree"] = methods_agree;
  j["cases_total"] = cases.size();
  return j;
}

std::string RecoveryReport::table() const {
  std::ostringstream out;
  out << "| method | truth inside its 95 % interval | no interval | median width (upper / lower) | estimate / truth "
         "(geometric mean +- its standard error) |\n|---|---|---|---|---|\n";
  char buf[192];
  for (const MethodCoverage& m : coverage) {
    std::snprintf(buf, sizeof buf, "| %s | %d of %d (%.0f %%) | %d | %.2f | %.2f +- %.2f |\n", m.method.c_str(),
                  m.covered, m.asked, 100.0 * m.fraction(), m.asked - m.answered, m.median_width_factor,
                  m.bias_factor, m.bias_factor_se);
    out << buf;
  }
  if (coverage.size() == 2)
    out << "methods agree (every pair of 95 % intervals overlaps) in " << methods_agree
        << " of " << cases.size() << " cases\n";
  return out.str();
}

}  // namespace rbcal::calibration
