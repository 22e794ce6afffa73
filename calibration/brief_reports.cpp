// The brief text reports of the calibration's result types (what `rbcal calibrate`
// prints), in SI internally and uN/m, mPa s on screen.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "calibration/calibration_report.hpp"
#include "formats/units.hpp"
#include "formats/printf_string.hpp"

namespace rbcal::calibration {

using formats::printf_string;

namespace {

std::string interval_text(const Interval& i, double scale) {
  return printf_string("%.0f", 100 * i.level) + " % [" + printf_string("%.4g", scale * i.lower) + ", " +
         printf_string("%.4g", scale * i.upper) + "]";
}

// Marks a result held at the model's Ca edge (direct_fit.hpp, ModelEdge) on its headline.
std::string edge_note(ModelEdge edge) {
  if (edge == ModelEdge::largest_ca) return " -- UPPER LIMIT at the model's largest Ca, not an estimate";
  if (edge == ModelEdge::smallest_ca) return " -- LOWER LIMIT at the model's smallest Ca, not an estimate";
  return "";
}

}  // namespace

std::string SampleReport::brief_report() const {
  const SampleData& s = sample;
  const std::string counts =
      printf_string("%zu of %zu points used", s.points.size(), s.points.size() + left_out.size());
  std::string out =
      s.plasma.assumed
          ? printf_string("sample %s: %s, eta0 = %.4g +- %.2g mPa s (ASSUMED, not measured: plasma_assumed row)\n",
                          s.name.c_str(), counts.c_str(), kMilli * s.plasma.eta0, kMilli * s.plasma.standard_error)
          : printf_string("sample %s: %s, eta0 = %.4g +- %.2g mPa s (%d plateau rows)\n", s.name.c_str(),
                          counts.c_str(), kMilli * s.plasma.eta0, kMilli * s.plasma.standard_error,
                          s.plasma.plateau_rows);
  if (alpha) {
    const auto& g = alpha->shear_modulus;
    if (g.count > 0)
      out += printf_string("  G_s alpha   %.4g uN/m  95 %% [%.4g, %.4g] (mean +- 1.96 se over %d shear rates)\n",
                    kMicro * g.mean, kMicro * (g.mean - 1.96 * g.standard_error),
                    kMicro * (g.mean + 1.96 * g.standard_error), g.count);
    else
      out += "  G_s alpha   none: no shear rate matched\n";
  }
  if (direct) {
    const auto& d = *direct;
    const auto used = std::count_if(d.points.begin(), d.points.end(), [](const auto& f) { return f.used; });
    out += printf_string("  G_s direct  %.4g uN/m  %s (Laplace, %ld points, chi^2/dof %.3g)%s\n",
                         kMicro * d.shear_modulus, interval_text(d.shear_modulus_interval, kMicro).c_str(),
                         static_cast<long>(used), d.degrees_of_freedom > 0 ? d.chi_square / d.degrees_of_freedom : 0.0,
                         edge_note(d.model_edge).c_str());
    if (std::find(d.parameter_names.begin(), d.parameter_names.end(), "ln_lambda") != d.parameter_names.end())
      out += printf_string("  lambda direct %.4g  %s\n", d.lambda, interval_text(d.lambda_interval, 1.0).c_str());
    for (const auto& n : d.nuisances)
      out += printf_string("  %s direct %.3g  %s (%s; prior %.3g +- %.3g)\n", n.prior.name.c_str(), n.value,
                    interval_text(n.interval, 1.0).c_str(), n.prior.what.c_str(), n.prior.mean, n.prior.sd);
  }
  if (mcmc) {
    const auto& m = *mcmc;
    out += printf_string("  G_s mcmc    %.4g uN/m  %s (posterior median)%s\n", kMicro * m.shear_modulus_median,
                  interval_text(m.shear_modulus_interval, kMicro).c_str(), edge_note(m.start_fit.model_edge).c_str());
    if (m.posterior.setup.fit_lambda)
      out += printf_string("  lambda mcmc %.4g  %s\n", m.lambda_median, interval_text(m.lambda_interval, 1.0).c_str());
    for (const auto& n : m.nuisances)
      out +=
          printf_string("  %s mcmc %.3g  %s\n", n.prior.name.c_str(), n.value, interval_text(n.interval, 1.0).c_str());
    const auto& mc = m.mcmc;
    const auto& p = mc.parameters.front();
    out += printf_string(
        "  MCMC        R-hat %.4f, ESS %.0f, tau %.3g, acceptance %.2f, %d steps x %zu chains x %d walkers, %s\n",
        p.rhat, p.bulk_ess, p.autocorrelation_time, mc.acceptance_fraction, mc.steps, mc.chains.size(),
        mc.chains.empty() ? 0 : mc.chains.front().walkers(), mc.converged ? "converged" : "NOT converged");
    out += "  sampler     " + mc.sampler + "\n";
  }
  if (predictive_check) out += "  PPC         " + predictive_check->line() + "\n";
  if (evidence) out += "  evidence    " + evidence->line() + "\n";
  if (!model_variants.empty()) {
    out += "  models      ranked by ln Z (importance sampling; a difference of 1 is a factor e):\n";
    for (const auto& m : model_variants)
      out += printf_string("    %-32s ln Z %.4g +- %.2g   G_s mcmc %.4g uN/m  %s\n", m.label.c_str(),
                           m.evidence.importance, m.evidence.importance_error, kMicro * m.shear_modulus_median,
                           interval_text(m.shear_modulus_interval, kMicro).c_str());
  }
  for (const auto& w : warnings) out += "  warning: " + w + "\n";
  for (const auto& line : consistency.lines()) out += "  consistency: " + line + "\n";
  return out;
}

std::string SampleComparisonReport::brief_report() const {
  return printf_string("G_s ratio %s / %s: %.4g  %s, P(%s > %s) = %.3f (%s)\n", numerator.c_str(), denominator.c_str(),
                ratio.median, interval_text(ratio.interval, 1.0).c_str(), numerator.c_str(), denominator.c_str(),
                ratio.probability_greater_than_one, source.c_str());
}

std::string JointReport::brief_report() const {
  const JointCalibration& j = calibration;
  std::string out = printf_string("joint posterior over %zu samples (model nuisances shared%s%s):\n", j.samples.size(),
                           shared_lambda ? ", lambda shared" : "", j.hierarchical ? ", ln G_s ~ N(mu, tau)" : "");
  for (const JointSampleEstimate& e : j.samples)
    out += printf_string("  G_s %-10s %.4g uN/m  %s\n", e.name.c_str(), e.shear_modulus_median * kMicro,
                  interval_text(e.shear_modulus_interval, kMicro).c_str());
  for (const NuisanceEstimate& n : j.nuisances)
    out += printf_string("  %s %.4g  %s (shared)\n", n.prior.name.c_str(), n.value,
                         interval_text(n.interval, 1.0).c_str());
  if (j.hierarchical)
    out += printf_string("  population median G_s %.4g uN/m  %s; tau (sd of ln G_s) %.3g  %s\n", j.mu_median * kMicro,
                         interval_text(j.mu_interval, kMicro).c_str(), j.tau_median,
                         interval_text(j.tau_interval, 1.0).c_str());
  const McmcResult& m = j.mcmc;
  double worst_rhat = 0.0, least_ess = 1e300;
  for (const ParameterSummary& p : m.parameters)
    worst_rhat = std::max(worst_rhat, p.rhat), least_ess = std::min(least_ess, p.bulk_ess);
  out += printf_string("  MCMC        worst R-hat %.4f, least ESS %.0f, %d steps, %s\n", worst_rhat, least_ess, m.steps,
                       m.converged ? "converged" : ("NOT converged: " + m.stop_reason).c_str());
  return out;
}

std::string ReportFiles::brief_report(bool plots_requested) const {
  std::string out = printf_string("report: %s (%zu files)%s\n", folder.string().c_str(), files.size(),
                           plots_written ? ", plots as PNG and SVG" : "");
  if (!plots_written && plots_requested) out += "warning: " + plots_message + "\n";
  return out;
}

}  // namespace rbcal::calibration
