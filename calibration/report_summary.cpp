#include "calibration/report_summary.hpp"

#include <algorithm>
#include <cmath>

#include "formats/units.hpp"
#include "formats/library_schema.hpp"
#include "formats/provenance.hpp"

namespace rbcal::calibration {

namespace {

using nlohmann::json;

json interval_json(const Interval& i, double scale) { return {{"lower", scale * i.lower}, {"upper", scale * i.upper}, {"level", i.level}}; }

json alpha_match_json(const AlphaMatch& m) {
  json j = {{"shear_rate_per_s", m.shear_rate}, {"matched", m.matched}};
  if (m.matched) {
    j["alpha"] = m.alpha;
    j["capillary_number"] = m.capillary_number;
    j["G_s_uN_per_m"] = kMicro * m.shear_modulus;
  } else if (m.capillary_number > 0.0) {
    j["capillary_number"] = m.capillary_number;
  }
  if (!m.message.empty()) j["message"] = m.message;
  return j;
}

json alpha_json(const AlphaMethodResult& a) {
  json j;
  const ShearModulusSummary& g = a.shear_modulus;
  j["G_s_uN_per_m"] = g.count > 0 ? json(kMicro * g.mean) : json(nullptr);
  j["G_s_sd_uN_per_m"] = kMicro * g.sd;
  j["G_s_standard_error_uN_per_m"] = kMicro * g.standard_error;
  // Mean +- 1.96 standard errors of the per-shear-rate values: their scatter, not a posterior.
  j["interval_uN_per_m"] = {{"lower", kMicro * (g.mean - 1.96 * g.standard_error)},
                            {"upper", kMicro * (g.mean + 1.96 * g.standard_error)},
                            {"level", 0.95},
                            {"kind", "mean +- 1.96 standard errors over matched shear rates"}};
  j["matched_shear_rates"] = g.count;
  j["G_s_mean_over_ca_uN_per_m"] = a.shear_modulus_per_ca.count > 0 ? json(kMicro * a.shear_modulus_per_ca.mean) : json(nullptr);
  j["eta0_mPa_s"] = kMilli * a.plasma_viscosity;
  json per_rate = json::array();
  for (const ShearRateAlpha& m : a.measured) {
    json r = {{"shear_rate_per_s", m.shear_rate}, {"alpha", m.fit.alpha}, {"r_squared", m.fit.r_squared},
              {"points", m.fit.points}};
    for (const AlphaMatch& match : a.per_shear_rate)
      if (match.shear_rate == m.shear_rate) r["match"] = alpha_match_json(match);
    per_rate.push_back(r);
  }
  j["alpha_per_shear_rate"] = per_rate;
  json model = json::array();
  for (const CapillaryAlpha& m : a.model)
    model.push_back({{"capillary_number", m.capillary_number}, {"alpha", m.fit.alpha}, {"r_squared", m.fit.r_squared}});
  j["model_alpha_per_ca"] = model;
  json per_ca = json::array();
  for (const AlphaMatch& m : a.per_capillary_number) {
    json r = alpha_match_json(m);
    r["capillary_number"] = m.capillary_number;
    per_ca.push_back(r);
  }
  j["G_s_per_ca"] = per_ca;
  j["messages"] = a.messages;
  return j;
}

// The model's nuisance parameters by name: value (estimate or posterior median), interval, prior.
json nuisances_json(const std::vector<NuisanceEstimate>& list) {
  json j = json::object();
  for (const NuisanceEstimate& n : list)
    j[n.prior.name] = {{"value", n.value},
                       {"interval", interval_json(n.interval, 1.0)},
                       {"what", n.prior.what},
                       {"prior", {{"mean", n.prior.mean}, {"sd", n.prior.sd}, {"min", n.prior.min}, {"max", n.prior.max}}}};
  return j;
}

json direct_json(const DirectFitResult& d) {
  json j = {{"G_s_uN_per_m", kMicro * d.shear_modulus},
            {"interval_uN_per_m", interval_json(d.shear_modulus_interval, kMicro)},
            {"ln_G_s_sd", d.ln_shear_modulus_sd},
            {"lambda", d.lambda},
            {"eta0_mPa_s", kMilli * d.plasma_viscosity},
            {"eta0_fitted", d.plasma_viscosity_fitted},
            {"chi_square", d.chi_square},
            {"degrees_of_freedom", d.degrees_of_freedom},
            {"converged", d.converged},
            {"covariance_ok", d.covariance_ok},
            {"at_bound", d.at_bound},
            {"points_used", d.used_points().size()},
            {"coverable_points", d.coverable_points},  // more than points_used: points left out by the fit
            {"model_edge", d.model_edge == ModelEdge::none          ? "none"
                           : d.model_edge == ModelEdge::largest_ca ? "largest_ca (G_s is an upper limit)"
                                                                   : "smallest_ca (G_s is a lower limit)"},
            {"parameters", d.parameter_names},
            {"messages", d.messages}};
  const bool lambda_fitted =
      std::find(d.parameter_names.begin(), d.parameter_names.end(), "ln_lambda") != d.parameter_names.end();
  j["lambda_fitted"] = lambda_fitted;
  if (lambda_fitted) j["lambda_interval"] = interval_json(d.lambda_interval, 1.0);
  j["model_nuisances"] = nuisances_json(d.nuisances);
  return j;
}

json mcmc_json(const McmcCalibration& m) {
  const McmcResult& r = m.mcmc;
  json j = {{"G_s_uN_per_m", kMicro * m.shear_modulus_median},
            {"G_s_statistic", "posterior median"},
            {"interval_uN_per_m", interval_json(m.shear_modulus_interval, kMicro)},
            {"lambda", m.lambda_median},
            {"lambda_fitted", m.posterior.setup.fit_lambda},
            {"eta0_mPa_s", kMilli * m.plasma_viscosity_median},
            {"eta0_interval_mPa_s", interval_json(m.plasma_viscosity_interval, kMilli)},
            {"points_in_likelihood", m.points.size()}};
  if (m.posterior.setup.fit_lambda) j["lambda_interval"] = interval_json(m.lambda_interval, 1.0);
  j["model_nuisances"] = nuisances_json(m.nuisances);
  if (m.posterior.fit_discrepancy) {
    j["sigma_d"] = m.discrepancy_median;
    j["sigma_d_interval"] = interval_json(m.discrepancy_interval, 1.0);
  }
  int walkers = r.chains.empty() ? 0 : r.chains.front().walkers();
  json parameters = json::array();
  for (const ParameterSummary& p : r.parameters)
    parameters.push_back({{"name", p.name},
                          {"mean", p.mean},
                          {"sd", p.sd},
                          {"median", p.median},
                          {"interval", interval_json(p.interval, 1.0)},
                          {"rhat", p.rhat},
                          {"classic_rhat", p.classic_rhat},
                          {"bulk_ess", p.bulk_ess},
                          {"tail_ess", p.tail_ess},
                          {"autocorrelation_time", p.autocorrelation_time}});
  json diagnostics = {{"sampler", r.sampler},
                      {"pilot_steps", r.pilot_steps},
                      {"converged", r.converged},
                      {"stop_reason", r.stop_reason},
                      {"steps", r.steps},
                      {"burn_in_steps", r.burn_in_steps},
                      {"chains", r.chains.size()},
                      {"walkers_per_chain", walkers},
                      {"acceptance_fraction", r.acceptance_fraction},
                      {"seconds", r.seconds},
                      {"parameters", parameters}};
  // The headline numbers are those of ln G_s, the parameter the stopping rule watches.
  if (!r.parameters.empty()) {
    diagnostics["rhat"] = r.parameters.front().rhat;
    diagnostics["ess"] = r.parameters.front().bulk_ess;
    diagnostics["tail_ess"] = r.parameters.front().tail_ess;
    diagnostics["tau"] = r.parameters.front().autocorrelation_time;
  }
  j["diagnostics"] = diagnostics;
  return j;
}

json points_json(const SampleReport& s) {
  json j = {{"total", s.sample.points.size()}};
  const DirectFitResult* fit = s.point_fit();
  if (!fit) return j;
  int used = 0;
  json skipped = json::array();
  for (const FittedPoint& f : fit->points) {
    if (f.used) {
      ++used;
      continue;
    }
    skipped.push_back({{"line", f.point.line},
                       {"phi", f.point.phi},
                       {"shear_rate_per_s", f.point.shear_rate},
                       {"capillary_number", f.capillary_number},
                       {"reason", f.reason}});
  }
  j["used"] = used;
  j["skipped"] = skipped;
  return j;
}

}  // namespace

nlohmann::json sample_summary(const SampleReport& s) {
  json j;
  j["name"] = s.sample.name;
  const PlasmaViscosity& p = s.sample.plasma;
  j["plasma"] = {{"eta0_mPa_s", kMilli * p.eta0},
                 {"eta0_standard_error_mPa_s", kMilli * p.standard_error},
                 {"plateau_rows", p.plateau_rows},
                 {"assumed", p.assumed}};
  j["points"] = points_json(s);
  json left_out = json::array();
  for (const LeftOutPoint& l : s.left_out)
    left_out.push_back({{"line", l.point.line},
                        {"phi", l.point.phi},
                        {"shear_rate_per_s", l.point.shear_rate},
                        {"eta_re", l.point.eta_re},
                        {"reason", l.reason}});
  j["left_out"] = left_out;
  json unreachable = json::array();
  for (const ReachGroup& g : s.unreachable) {
    json group = {{"phi", g.phi}, {"verdict", to_string(g.reach)}, {"points", g.points}};
    if (g.reach != Reach::phi_outside_model) {
      group["measured_eta_re"] = {g.measured_min, g.measured_max};
      group["model_eta_re"] = {g.model_min, g.model_max};
      group["relative_gap"] = {g.gap_min, g.gap_max};
    }
    unreachable.push_back(group);
  }
  j["reach"] = {{"reachable_points", s.sample.points.size()}, {"unreachable", unreachable}};
  json methods = json::object();
  if (s.alpha) methods["alpha"] = alpha_json(*s.alpha);
  if (s.direct) methods["direct"] = direct_json(*s.direct);
  if (s.mcmc) methods["mcmc"] = mcmc_json(*s.mcmc);
  j["methods"] = methods;
  j["warnings"] = s.warnings;
  j["consistency"] = s.consistency.to_json();
  if (s.predictive_check) j["posterior_predictive_check"] = s.predictive_check->to_json();
  if (s.evidence) j["evidence"] = s.evidence->to_json();
  if (!s.model_variants.empty()) {
    json variants = json::array();
    for (const auto& m : s.model_variants)
      variants.push_back({{"model", m.label},
                          {"evidence", m.evidence.to_json()},
                          {"G_s_median_uN_per_m", kMicro * m.shear_modulus_median},
                          {"G_s_interval_uN_per_m", {kMicro * m.shear_modulus_interval.lower, kMicro * m.shear_modulus_interval.upper}}});
    j["model_comparison"] = variants;
  }
  return j;
}

json joint_summary(const JointReport& joint) {
  const JointCalibration& jc = joint.calibration;
  json per_sample = json::array();
  for (const JointSampleEstimate& e : jc.samples)
    per_sample.push_back({{"sample", e.name},
                          {"shear_modulus_median_uN_per_m", e.shear_modulus_median * kMicro},
                          {"shear_modulus_interval_uN_per_m", interval_json(e.shear_modulus_interval, kMicro)}});
  json nuisances = json::array();
  for (const NuisanceEstimate& n : jc.nuisances)
    nuisances.push_back({{"name", n.prior.name}, {"median", n.value}, {"interval", interval_json(n.interval, 1.0)}});
  json parameters = json::array();
  for (const ParameterSummary& p : jc.mcmc.parameters)
    parameters.push_back({{"name", p.name},
                          {"median", p.median},
                          {"interval", interval_json(p.interval, 1.0)},
                          {"rhat", p.rhat},
                          {"bulk_ess", p.bulk_ess}});
  json j = {{"samples", per_sample},
            {"shared_nuisances", nuisances},
            {"shared_lambda", joint.shared_lambda},
            {"hierarchical", jc.hierarchical},
            {"parameters", parameters},
            {"mcmc",
             {{"sampler", jc.mcmc.sampler},
              {"steps", jc.mcmc.steps},
              {"converged", jc.mcmc.converged},
              {"stop_reason", jc.mcmc.stop_reason},
              {"evaluations", jc.mcmc.evaluations}}}};
  if (jc.hierarchical)
    j["population"] = {{"median_shear_modulus_uN_per_m", jc.mu_median * kMicro},
                       {"median_shear_modulus_interval_uN_per_m", interval_json(jc.mu_interval, kMicro)},
                       {"tau", jc.tau_median},
                       {"tau_interval", interval_json(jc.tau_interval, 1.0)}};
  return j;
}

json comparison_summary(const SampleComparisonReport& comparison) {
  const ShearModulusRatio& r = comparison.ratio;
  return {{"numerator", comparison.numerator},
          {"denominator", comparison.denominator},
          {"source", comparison.source},
          {"ratio_median", r.median},
          {"ratio_mean", r.mean},
          {"interval", interval_json(r.interval, 1.0)},
          {"probability_numerator_greater", r.probability_greater_than_one},
          {"pairs", r.draws.size()}};
}

nlohmann::json report_summary(const CalibrationReport& report, const ReportFiles& files) {
  json j;
  j["schema"] = formats::kCalibrationReportSchema;
  j["units"] = {{"G_s", "uN/m"}, {"viscosity", "mPa s"}, {"shear_rate", "1/s"}, {"cell_radius", "um"}};
  const ReportProvenance& p = report.provenance;
  j["provenance"] = formats::provenance_block();
  j["provenance"].update({{"data_file", p.data_file},
                          {"surrogate_file", p.surrogate_file},
                          {"command_line", p.command_line},
                          {"options", p.options},
                          {"seed", p.seed}});
  j["cell_radius_um"] = report.cell_radius * kMicro;
  json samples = json::array();
  for (const SampleReport& s : report.samples) samples.push_back(sample_summary(s));
  j["samples"] = samples;
  if (report.joint) j["joint"] = joint_summary(*report.joint);
  if (report.comparison) j["comparison"] = comparison_summary(*report.comparison);
  json listed = json::array();
  for (const auto& f : files.files) listed.push_back(f.lexically_relative(files.folder).generic_string());
  listed.push_back("summary.json");
  j["files"] = listed;
  j["plots"] = {{"written", files.plots_written}, {"message", files.plots_message}};
  return j;
}

}  // namespace rbcal::calibration
