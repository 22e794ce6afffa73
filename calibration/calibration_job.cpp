#include "calibration/calibration_job.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "calibration/alpha_method.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/hematocrit_order.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/model_evidence.hpp"
#include "calibration/posterior.hpp"
#include "calibration/posterior_predictive_check.hpp"
#include "calibration/saved_draws.hpp"
#include "calibration/predictive_bands.hpp"
#include "calibration/sample_comparison.hpp"
#include "formats/units.hpp"
#include "formats/host_memory.hpp"
#include "formats/short_number.hpp"
#include "surrogate/fixed_nuisance_model.hpp"
#include "surrogate/offset_family_file.hpp"

namespace rbcal::calibration {

namespace fs = std::filesystem;

namespace {

std::string shown(double x) { return formats::short_number(x, 4); }

std::optional<std::pair<std::string, std::string>> compared_samples(const std::string& compare) {
  if (compare.empty()) return std::nullopt;
  const auto slash = compare.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == compare.size()) return std::nullopt;
  return std::make_pair(compare.substr(0, slash), compare.substr(slash + 1));
}

// The smallest and largest Ca of the points at (eta0, G_s): where the upper and the lower end of
// an interval put them.
std::pair<double, double> capillary_number_span(const std::vector<RelativeViscosityPoint>& points,
                                                double plasma_viscosity, double cell_radius, double shear_modulus) {
  std::pair<double, double> span{std::numeric_limits<double>::infinity(), 0.0};
  for (const auto& p : points) {
    const double ca = capillary_number(plasma_viscosity, p.shear_rate, cell_radius, shear_modulus);
    span = {std::min(span.first, ca), std::max(span.second, ca)};
  }
  return span;
}

// A warning when the lower end of a G_s interval carries fitted points beyond the model's Ca range:
// there the surrogate extrapolates (its mean function and a growing sd), which the user must know.
std::optional<std::string> extrapolation_warning(const std::string& method, const std::vector<RelativeViscosityPoint>& points,
                                                 double plasma_viscosity, double cell_radius, double lower_shear_modulus,
                                                 const surrogate::ParameterRange& range) {
  const double ca = capillary_number_span(points, plasma_viscosity, cell_radius, lower_shear_modulus).second;
  if (!(ca > range.ca_max * (1.0 + 1e-9))) return std::nullopt;
  std::ostringstream w;
  w << method << ": at the lower end of the G_s interval (" << shown(lower_shear_modulus * kMicro)
    << " uN/m) the fitted points reach Ca " << shown(ca) << ", beyond the library's " << shown(range.ca_max)
    << ": there the surrogate extrapolates, and that end of the interval rests on its extrapolation";
  return w.str();
}

// The MCMC's posterior is truncated to the model's range (posterior.hpp): an end of its interval
// that puts the fitted points within 10 % of the range's Ca edge (at the median eta0; draws differ
// in eta0) is set by the library's range rather than by the data, and is read as a limit.
std::vector<std::string> range_cut_warnings(const std::vector<RelativeViscosityPoint>& points, double plasma_viscosity,
                                            double cell_radius, const Interval& interval,
                                            const surrogate::ParameterRange& range) {
  std::vector<std::string> out;
  const double high = capillary_number_span(points, plasma_viscosity, cell_radius, interval.lower).second;
  const double low = capillary_number_span(points, plasma_viscosity, cell_radius, interval.upper).first;
  const auto say = [&](const char* end, double g_s, double ca, double edge, const char* which, const char* kind) {
    std::ostringstream w;
    w << "MCMC: the " << end << " end of the G_s interval (" << shown(g_s * kMicro) << " uN/m) puts the fitted points at Ca "
      << shown(ca) << ", at the library's " << which << " Ca " << shown(edge)
      << ", where the posterior is cut (the model is not used outside its range): that end is set by the library, "
         "not by the data; read it as a "
      << kind << " limit";
    out.push_back(w.str());
  };
  if (high >= 0.9 * range.ca_max) say("lower", interval.lower, high, range.ca_max, "largest", "lower");
  if (low <= range.ca_min / 0.9) say("upper", interval.upper, low, range.ca_min, "smallest", "upper");
  return out;
}

// Each method of one sample; a method that throws becomes a warning.
class SampleCalibration {
 public:
  SampleCalibration(const surrogate::ViscosityModel& model, const CalibrationJobOptions& o) : model_(model), o_(o) {}

  SampleReport run(SampleData sample) const {
    SampleReport r;
    // Moves the points for which why(p) is not empty from the sample to r.left_out.
    auto leave_out = [&](auto why) {
      std::size_t count = 0;
      std::erase_if(sample.points, [&](const RelativeViscosityPoint& p) {
        std::string reason = why(p);
        if (reason.empty()) return false;
        r.left_out.push_back({p, std::move(reason)});
        ++count;
        return true;
      });
      return count;
    };
    const std::string above_phi_max = "phi above " + shown(o_.phi_max) + " (--phi-max)";
    if (const std::size_t n = leave_out([&](const auto& p) { return p.phi > o_.phi_max ? above_phi_max : ""; }))
      r.warnings.push_back(std::to_string(n) + " points with phi > " + shown(o_.phi_max) + " left out (--phi-max)");
    if (!o_.keep_out_of_hematocrit_order) {
      // One pass over the points for all of them (one pass per point had been O(n k)).
      std::map<std::tuple<int, double, double>, std::string> reasons;
      for (const OutOfOrderPoint& bad : points_out_of_hematocrit_order(sample.points)) {
        const std::string reason = "viscosity below the lower hematocrit's (--keep-out-of-order keeps it): " + bad.reason();
        reasons.emplace(std::tuple{bad.point.line, bad.point.phi, bad.point.shear_rate}, reason);
        r.warnings.push_back("left out, " + reason);
      }
      if (!reasons.empty())
        leave_out([&](const auto& p) {
          const auto it = reasons.find({p.line, p.phi, p.shear_rate});
          return it == reasons.end() ? std::string() : it->second;
        });
    }
    const std::string below_rate = "shear rate below " + shown(o_.min_shear_rate) +
                                   " 1/s (--min-shear-rate: aggregation, which the simulations lack)";
    if (const std::size_t n = leave_out([&](const auto& p) { return p.shear_rate < o_.min_shear_rate ? below_rate : ""; }))
      r.warnings.push_back(std::to_string(n) + " points below " + shown(o_.min_shear_rate) +
                           " 1/s left out (--min-shear-rate: aggregation, which the simulations lack)");
    leave_out_unreachable(sample, r);
    r.sample = sample;
    if (sample.points.empty()) {
      r.warnings.push_back("no point left that the model can reach: nothing to calibrate (see the lines above)");
      return r;
    }
    // Refused up front, with the numbers, instead of failing on memory half-way.
    const double need = kLikelihoodBytesPerPoint * static_cast<double>(sample.points.size());
    const auto available = static_cast<double>(formats::available_memory_bytes());
    if (sample.points.size() > kMaxFittedPoints || (available > 0.0 && need > 0.8 * available)) {
      r.warnings.push_back(std::to_string(sample.points.size()) + " points to fit: the likelihood would need about " +
                           shown(need / (1 << 30)) + " GiB (" + shown(available / (1 << 30)) +
                           " GiB available), and at most " + std::to_string(kMaxFittedPoints) +
                           " points are fitted: nothing calibrated; thin the curves (fewer shear rates per hematocrit)");
      return r;
    }
    if (sample.points.size() > kSlowFittedPoints)
      r.warnings.push_back(std::to_string(sample.points.size()) +
                           " points: the calibration takes tens of seconds (about 45 s at 2000 points on two cores)");
    if (o_.runs("alpha")) alpha(r);
    if (o_.runs("direct")) direct(r);
    if (o_.runs("mcmc")) mcmc(r);
    points_left_out(r);
    r.consistency = check_consistency(r, model_.range());
    return r;
  }

 private:
  DirectFitOptions fit_options() const {
    DirectFitOptions fo;
    fo.setup = o_.setup;
    fo.hold_coverable_points = o_.hold_coverable_points;
    return fo;
  }

  void alpha(SampleReport& r) const {
    AlphaMethodOptions ao;
    ao.setup = o_.setup;
    ao.phi_max = o_.phi_max;
    try {
      r.alpha = estimate_by_alpha_matching(r.sample, model_, ao);
      int unmatched = 0;
      for (const auto& m : r.alpha->per_shear_rate) unmatched += m.matched ? 0 : 1;
      if (unmatched > 0)
        r.warnings.push_back("alpha: " + std::to_string(unmatched) + " of " +
                             std::to_string(r.alpha->per_shear_rate.size()) +
                             " shear rates not matched to a Ca of the surrogate (see summary.json)");
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("alpha method failed: ") + e.what());
    }
  }

  void direct(SampleReport& r) const {
    try {
      r.direct = fit_direct(r.sample, model_, fit_options());
      if (!r.direct->converged) r.warnings.push_back("direct fit: Ceres did not converge");
      if (!r.direct->covariance_ok) r.warnings.push_back("direct fit: covariance rank deficient, no interval");
      if (r.direct->at_bound) r.warnings.push_back("direct fit: an estimate sits on a bound, interval unreliable");
      if (r.direct->model_edge != ModelEdge::none) r.warnings.push_back("direct fit: " + r.direct->model_edge_reason);
      if (!r.direct->point_set_settled)
        r.warnings.push_back(std::string("direct fit: ") + kPointSetUnsettled);
      if (static_cast<int>(r.direct->used_points().size()) < r.direct->coverable_points)
        r.warnings.push_back(shed_points_warning(r));
      if (r.direct->has_interval_estimate())
        if (auto w = extrapolation_warning("direct fit", r.direct->used_points(), r.direct->plasma_viscosity,
                                           o_.setup.cell_radius,
                                           r.direct->shear_modulus_interval.lower, model_.range()))
          r.warnings.push_back(*w);
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("direct fit failed: ") + e.what());
    }
  }

  // A fit that left out points one G_s could have kept: the same fit holding them, side by side.
  std::string shed_points_warning(const SampleReport& r) const {
    std::ostringstream w;
    w << "direct fit: it fitted " << r.direct->used_points().size() << " of the " << r.direct->coverable_points
      << " points one G_s keeps inside the model's Ca range; holding them all (--hold-points) gives ";
    try {
      DirectFitOptions fo = fit_options();
      fo.hold_coverable_points = true;
      const DirectFitResult held = fit_direct(r.sample, model_, fo);
      w << "G_s " << shown(held.shear_modulus * kMicro) << " uN/m";
      if (held.model_edge != ModelEdge::none)
        w << " as an " << limit_kind(held.model_edge) << " limit (the data lie "
          << (held.model_edge == ModelEdge::largest_ca ? "below" : "above") << " the model at its Ca edge)";
      else if (held.covariance_ok)
        w << " (95 % " << shown(held.shear_modulus_interval.lower * kMicro) << "-"
          << shown(held.shear_modulus_interval.upper * kMicro) << ")";
    } catch (const std::exception& e) {
      w << "no fit (" << e.what() << ")";
    }
    w << ": the estimate rests on the points the fit kept";
    return w.str();
  }

  void mcmc(SampleReport& r) const {
    McmcCalibrationOptions mo;
    mo.posterior.setup = o_.setup;
    mo.start_fit = fit_options();
    if (r.direct) mo.fitted_start = &*r.direct;  // the same fit: the direct method's options are the start's
    mo.sampler = o_.sampler;
    try {
      r.mcmc = calibrate_mcmc(r.sample, model_, mo);
      if (!r.mcmc->mcmc.converged) r.warnings.push_back("MCMC not converged: " + r.mcmc->mcmc.stop_reason);
      if (r.mcmc->start_fit.model_edge != ModelEdge::none)
        r.warnings.push_back(std::string("MCMC: posterior truncated at the model's Ca range (the start fit is an edge fit): "
                                         "its G_s interval is an ") +
                             limit_kind(r.mcmc->start_fit.model_edge) + " limit, not an estimate");
      else
        for (std::string& w : range_cut_warnings(r.mcmc->points, r.mcmc->plasma_viscosity_median, o_.setup.cell_radius,
                                                 r.mcmc->shear_modulus_interval, model_.range()))
          r.warnings.push_back(std::move(w));
      if (!o_.mcmc_byproducts) return;
      PredictiveBandOptions bo;
      bo.seed = o_.sampler.seed + 1;
      r.band_level = bo.level;
      r.bands = predictive_bands(model_, *r.mcmc, bo);
      PredictiveCheckOptions co;
      co.seed = o_.sampler.seed + 3;
      r.predictive_check = posterior_predictive_check(model_, *r.mcmc, co);
      r.saved_draws = saved_draws(model_, *r.mcmc, o_.saved_draws);
      const LogPosterior posterior(model_, r.mcmc->plasma_viscosity, r.mcmc->points, r.mcmc->posterior,
                                   r.mcmc->plasma_viscosity_standard_error);
      ModelEvidenceOptions eo;
      eo.seed = o_.sampler.seed + 4;
      eo.threads = o_.sampler.threads;
      SamplerByproducts known{r.mcmc->mcmc.draw_log_densities(), r.mcmc->mcmc.proposal_log_weights,
                              "the MCMC's independence proposal"};
      r.evidence = model_evidence([&](const Eigen::VectorXd& theta) { return posterior(theta); }, r.mcmc->mcmc.draws(), eo,
                                  known);
      if (r.predictive_check->disagrees())
        r.warnings.push_back("posterior predictive check: " + r.predictive_check->line() +
                             ": the model does not follow these data within their errors");
    } catch (const std::exception& e) {
      r.warnings.push_back(std::string("MCMC failed: ") + e.what());
    }
  }

  // Points that the model cannot reach at any G_s (calibration/model_reach.hpp) leave the
  // fits, with one warning per phi saying by how much they miss.
  void leave_out_unreachable(SampleData& sample, SampleReport& r) const {
    const ReachDiagnosis d = diagnose_reach(sample.points, model_, o_.setup);
    if (d.unreachable_groups.empty()) return;
    std::vector<RelativeViscosityPoint> kept;
    for (const PointReach& p : d.points) {
      if (p.reachable())
        kept.push_back(p.point);
      else
        r.left_out.push_back({p.point, "out of the model's reach: " + p.reason()});
    }
    sample.points = std::move(kept);
    r.unreachable = d.unreachable_groups;
    const surrogate::ParameterRange range = model_.range();
    for (const ReachGroup& g : d.unreachable_groups) r.warnings.push_back("cannot be reached: " + g.line(range, o_.setup));
  }

  // Points the fit left out (mostly outside the surrogate's range), counted once.
  void points_left_out(SampleReport& r) const {
    const DirectFitResult* fit = r.point_fit();
    if (!fit) return;
    int skipped = 0;
    std::string first;
    for (const auto& f : fit->points)
      if (!f.used && skipped++ == 0) first = "line " + std::to_string(f.point.line) + ": " + f.reason;
    if (skipped == 0) return;
    const surrogate::ParameterRange range = model_.range();
    std::ostringstream w;
    w << skipped << " of " << fit->points.size() << " points not fitted (surrogate range phi " << range.phi_min
      << " .. " << range.phi_max << ", Ca " << range.ca_min << " .. " << range.ca_max << "); first: " << first;
    r.warnings.push_back(w.str());
  }

  const surrogate::ViscosityModel& model_;
  const CalibrationJobOptions& o_;
};

// The samples to calibrate: those named (every one when none is), plus the two of
// --compare; std::invalid_argument naming the file and the known samples for a missing one.
std::vector<const SampleData*> selected_samples(const CalibrationInput& input, const CalibrationJobOptions& o) {
  std::vector<std::string> names = o.samples;
  if (names.empty())
    for (const auto& s : input.samples) names.push_back(s.name);
  const auto compare = compared_samples(o.compare);
  if (compare)
    for (const std::string& n : {compare->first, compare->second})
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  std::vector<const SampleData*> selected;
  for (const auto& n : names) {
    try {
      selected.push_back(&input.sample(n));
    } catch (const std::out_of_range& e) {
      throw std::invalid_argument(e.what());  // names the file and the known samples
    }
  }
  return selected;
}

const SampleReport& report_of(const CalibrationReport& report, const std::string& name) {
  for (const auto& r : report.samples)
    if (r.sample.name == name) return r;
  throw std::logic_error("sample " + name + " not calibrated");
}

}  // namespace

std::string CalibrationJobOptions::invalid_reason() const {
  if (method != "all" && method != "alpha" && method != "direct" && method != "mcmc")
    return "--method " + method + ": expected alpha, direct, mcmc or all";
  if (const std::string why = setup.invalid_reason(); !why.empty()) return why;
  if (!(phi_max > 0.0 && phi_max <= 1.0)) return "--phi-max must lie in (0, 1]";
  if (!(min_shear_rate >= 0.0)) return "--min-shear-rate must be >= 0";
  if (!(plasma.plateau_min_shear_rate >= 0.0)) return "--plateau-min-shear-rate must be >= 0";
  if (sampler.chains < 1 || (sampler.walkers != 0 && sampler.walkers < 2) || sampler.max_steps < 1)
    return "MCMC needs at least one chain, two walkers (or 0: automatic) and one step";
  if (!compare.empty()) {
    if (!compared_samples(compare)) return "--compare " + compare + ": expected NUMERATOR/DENOMINATOR sample names";
    if (!runs("mcmc")) return "--compare needs the mcmc method (--method mcmc or all)";
  }
  if (joint && !runs("mcmc")) return "--joint needs the mcmc method (--method mcmc or all)";
  if ((shared_lambda || hierarchical) && !joint) return "--shared-lambda and --hierarchical need --joint";
  return "";
}

nlohmann::json CalibrationJobOptions::to_json() const {
  return {{"method", method},
          {"samples", samples},
          {"lambda", setup.lambda},
          {"fit_lambda", setup.fit_lambda},
          {"lambda_prior_log_sd", setup.lambda_prior_log_sd},
          {"held_nuisances", held_nuisances},
          {"cell_radius_um", setup.cell_radius * kMicro},
          {"plateau_min_shear_rate_per_s", plasma.plateau_min_shear_rate},
          {"phi_max", phi_max},
          {"min_shear_rate_per_s", min_shear_rate},
          {"keep_out_of_hematocrit_order", keep_out_of_hematocrit_order},
          {"hold_coverable_points", hold_coverable_points},
          {"sampler", to_string(sampler.sampler)},
          {"seed", sampler.seed},
          {"threads", sampler.threads},
          {"compare", compare},
          {"compare_models", compare_models},
          {"alternative_models", [&] {
             std::vector<std::string> v;
             for (const auto& f : alternative_models) v.push_back(f.string());
             return v;
           }()},
          {"joint", joint},
          {"shared_lambda", shared_lambda},
          {"hierarchical", hierarchical},
          {"mcmc_max_steps", sampler.max_steps},
          {"chains", sampler.chains},
          {"walkers", sampler.walkers},
          {"plots", report.plots}};
}

namespace {

// The sample calibrated by MCMC under each variant of the model; the variants ranked by ln Z
// (importance sampling), best first.
// A model file of --alternative-model, loaded once for all samples.
struct AlternativeModel {
  std::filesystem::path file;
  std::unique_ptr<surrogate::ViscosityModel> model;
};

// An alternative model is ranked with lambda as the job's setup has it.
struct ModelVariant {
  std::string label;
  const surrogate::ViscosityModel* model;
  ModelSetup setup;
};

void compare_model_variants(const SampleData& sample, const surrogate::ViscosityModel& model,
                            const std::vector<AlternativeModel>& alternatives, const CalibrationJobOptions& o,
                            SampleReport& r) {
  std::vector<ModelVariant> variants;
  ModelSetup fitted = o.setup, fixed = o.setup;
  fitted.fit_lambda = true;
  fixed.fit_lambda = false;
  variants.push_back({"lambda fitted under its prior", &model, fitted});
  variants.push_back({"lambda fixed at " + shown(o.setup.lambda), &model, fixed});
  for (const AlternativeModel& a : alternatives)
    variants.push_back({"model " + a.file.string() + (o.setup.fit_lambda ? ", lambda fitted" : ", lambda fixed"),
                        a.model.get(), o.setup});
  for (const auto& [label, variant_model, setup] : variants) {
    CalibrationJobOptions v = o;
    v.method = "mcmc";
    v.setup = setup;
    v.compare_models = false;
    v.alternative_models.clear();
    const SampleReport one = SampleCalibration(*variant_model, v).run(sample);
    if (!one.evidence || !one.mcmc) {
      r.warnings.push_back("--compare-models: " + label + ": no evidence (the MCMC failed; see a run of it alone)");
      continue;
    }
    r.model_variants.push_back({label, *one.evidence, one.mcmc->shear_modulus_median, one.mcmc->shear_modulus_interval});
  }
  std::sort(r.model_variants.begin(), r.model_variants.end(),
            [](const auto& a, const auto& b) { return a.evidence.importance > b.evidence.importance; });
}

// The joint posterior over the named samples, each started from its direct fit (the MCMC's
// start fit when the direct method did not run) over the points that fit used.
JointReport joint_posterior_of(const CalibrationReport& report, const std::vector<std::string>& names,
                               const surrogate::ViscosityModel& model, const CalibrationJobOptions& o) {
  std::vector<JointSample> samples;
  std::vector<DirectFitResult> fits;
  for (const std::string& name : names) {
    const SampleReport& r = report_of(report, name);
    const DirectFitResult* fit = r.point_fit();
    if (!fit) throw std::invalid_argument("sample " + name + " has no fit to start from");
    samples.push_back({name, fit->used_points(), r.sample.plasma.eta0, r.sample.plasma.standard_error});
    fits.push_back(*fit);
  }
  JointPosteriorOptions jo;
  jo.posterior.setup = o.setup;
  jo.shared_lambda = o.shared_lambda;
  jo.hierarchical = o.hierarchical;
  McmcOptions sampler = o.sampler;
  sampler.seed = o.sampler.seed + 2;
  return JointReport{calibrate_joint(samples, fits, model, jo, sampler), o.shared_lambda};
}

}  // namespace

CalibrationReport calibrate_samples(const CalibrationInput& input, const surrogate::ViscosityModel& model,
                                    const CalibrationJobOptions& options, std::ostream& log) {
  const std::vector<const SampleData*> selected = selected_samples(input, options);
  const auto compare = compared_samples(options.compare);
  // A model built at one lambda has nothing to say about lambda: it is held there, and said so.
  CalibrationJobOptions o = options;
  const surrogate::ParameterRange range = model.range();
  std::string lambda_note;
  if (o.setup.fit_lambda && !(range.lambda_max > range.lambda_min * (1.0 + 1e-9))) {
    o.setup.fit_lambda = false;
    lambda_note = " (held: the model covers lambda " + shown(range.lambda_min) + " only)";
  }
  log << "rbcal calibrate: " << o.data_file.string() << " (" << selected.size() << " of " << input.samples.size()
      << " samples), surrogate " << o.surrogate_file.string() << ", method " << o.method << ", lambda "
      << (o.setup.fit_lambda ? "fitted, prior median " + shown(o.setup.lambda) +
                                   (o.setup.lambda_prior_log_sd > 0.0 ? ", ln sd " + shown(o.setup.lambda_prior_log_sd)
                                                                      : std::string(", uniform in ln lambda"))
                             : shown(o.setup.lambda) + lambda_note)
      << "\n";

  CalibrationReport report;
  report.cell_radius = o.setup.cell_radius;
  report.provenance = {o.data_file.string(), o.surrogate_file.string(), o.command_line, o.to_json(), o.sampler.seed};
  const SampleCalibration calibrate(model, o);
  std::vector<AlternativeModel> alternatives;
  for (const std::filesystem::path& f : o.alternative_models)
    alternatives.push_back({f, surrogate::load_viscosity_model(f)});
  for (const SampleData* s : selected) {
    report.samples.push_back(calibrate.run(*s));
    if (o.compare_models || !alternatives.empty()) compare_model_variants(*s, model, alternatives, o, report.samples.back());
    log << report.samples.back().brief_report() << std::flush;
  }
  if (o.joint || compare) {
    std::vector<std::string> names;
    if (o.joint)
      for (const SampleReport& r : report.samples) names.push_back(r.sample.name);
    else
      names = {compare->first, compare->second};
    try {
      report.joint = joint_posterior_of(report, names, model, o);
      log << report.joint->brief_report();
    } catch (const std::exception& e) {
      log << "warning: joint posterior skipped: " << e.what() << "\n";
    }
  }
  if (compare && report.joint) {
    const JointCalibration& j = report.joint->calibration;
    report.comparison = SampleComparisonReport{compare->first, compare->second,
                                               j.ratio(j.index_of(compare->first), j.index_of(compare->second)),
                                               "joint posterior, model nuisances shared"};
    log << report.comparison->brief_report();
  }
  return report;
}

CalibrationJobResult run_calibration_job(const CalibrationJobOptions& o, std::ostream& log) {
  if (const std::string why = o.invalid_reason(); !why.empty()) throw std::invalid_argument(why);
  if (!fs::exists(o.data_file))
    throw std::invalid_argument("data file " + o.data_file.string() +
           " not found; give a rheometer CSV (sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n) as "
           "`rbcal calibrate DATA.csv`");
  if (!fs::exists(o.surrogate_file))
    throw std::invalid_argument("surrogate file " + o.surrogate_file.string() +
           " not found; build one with `rbcal surrogate build LIBRARY -o FILE` and pass --surrogate FILE");
  const CalibrationInput input = read_calibration_input(o.data_file, o.plasma);
  selected_samples(input, o);  // a typo in --sample fails before the surrogate is loaded
  const std::unique_ptr<surrogate::ViscosityModel> loaded = surrogate::load_viscosity_model(o.surrogate_file);
  // Each held nuisance wraps the model once more (--hold NAME=VALUE).
  std::vector<std::unique_ptr<surrogate::ViscosityModel>> held;
  const surrogate::ViscosityModel* model = loaded.get();
  for (const auto& [name, value] : o.held_nuisances) {
    try {
      held.push_back(std::make_unique<surrogate::FixedNuisanceModel>(*model, name, value));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--hold " + name + "=" + shown(value) + ": " + o.surrogate_file.string() + ": " + e.what());
    }
    model = held.back().get();
  }
  CalibrationJobResult out;
  out.report = calibrate_samples(input, *model, o, log);
  out.files = write_calibration_report(out.report, o.report_folder, o.report);
  log << out.files.brief_report(o.report.plots);
  return out;
}

}  // namespace rbcal::calibration
