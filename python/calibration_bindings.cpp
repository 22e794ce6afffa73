// rbcal.calibrate and what it returns: the command line's calibration job (same options,
// same defaults, same numbers for the same seed), as plain Python objects: the per-sample
// summaries of summary.json, MCMC chains as arrays (chains x draws x parameters), and the
// log posterior of a sample as a callable (for other samplers, e.g. emcee).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <sstream>

#include "calibration/calibration_job.hpp"
#include "calibration/chain_diagnostics.hpp"
#include "calibration/posterior.hpp"
#include "calibration/report_summary.hpp"
#include "python/bindings.hpp"
#include "surrogate/offset_family_file.hpp"

namespace py = pybind11;

namespace rbcal::python {

namespace {

namespace cal = rbcal::calibration;

py::object to_python(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

// A calibration and the model it ran on (kept alive for log_posterior).
struct Calibration {
  std::shared_ptr<const surrogate::ViscosityModel> model;  // a surrogate or a surrogate family
  cal::CalibrationReport report;
  cal::CalibrationJobOptions options;
  std::string log;

  const cal::SampleReport& sample(const std::string& name) const {
    for (const auto& s : report.samples)
      if (s.sample.name == name) return s;
    throw py::key_error("no sample '" + name + "' in this calibration");
  }
  const cal::McmcCalibration& mcmc(const std::string& name) const {
    const cal::SampleReport& s = sample(name);
    if (!s.mcmc) throw py::value_error("sample '" + name + "' has no MCMC result (method, or see its warnings)");
    return *s.mcmc;
  }
};

// The posterior the MCMC sampled, as a callable of theta (a 1-D array).
struct PosteriorFunction {
  std::shared_ptr<const surrogate::ViscosityModel> model;  // a surrogate or a surrogate family
  cal::LogPosterior posterior;
  double operator()(const Eigen::VectorXd& theta) const {
    if (theta.size() != posterior.dimension())
      throw py::value_error("theta has " + std::to_string(theta.size()) + " entries, the posterior " +
                            std::to_string(posterior.dimension()));
    return posterior(theta);
  }
};

Calibration calibrate(const std::string& data, const std::string& surrogate_file, const std::string& method,
                      const std::vector<std::string>& samples, double lambda, bool fit_lambda, double lambda_prior_sd,
                      double cell_radius_um,
                      double plateau_min_shear_rate, double phi_max, double min_shear_rate, bool keep_out_of_order,
                      bool hold_points,
                      std::uint64_t seed, int threads, int mcmc_max_steps, int chains, int walkers,
                      const std::string& sampler, const std::string& compare, bool joint, bool shared_lambda,
                      bool hierarchical, const std::string& report, bool plots) {
  Calibration c;
  cal::CalibrationJobOptions& o = c.options;
  o.data_file = data;
  o.surrogate_file = surrogate_file;
  o.method = method;
  o.samples = samples;
  o.setup.lambda = lambda;
  o.setup.fit_lambda = fit_lambda;
  o.setup.lambda_prior_log_sd = lambda_prior_sd;
  o.setup.cell_radius = cell_radius_um * 1e-6;
  o.plasma.plateau_min_shear_rate = plateau_min_shear_rate;
  o.phi_max = phi_max;
  o.min_shear_rate = min_shear_rate;
  o.keep_out_of_hematocrit_order = keep_out_of_order;
  o.hold_coverable_points = hold_points;
  o.sampler.seed = seed;
  o.sampler.threads = threads;
  o.sampler.max_steps = mcmc_max_steps;
  o.sampler.chains = chains;
  o.sampler.walkers = walkers;
  try {
    o.sampler.sampler = cal::sampler_from_string(sampler);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  o.compare = compare;
  o.joint = joint;
  o.shared_lambda = shared_lambda;
  o.hierarchical = hierarchical;
  o.report.plots = plots;
  o.command_line = "rbcal.calibrate (Python)";
  if (const std::string why = o.invalid_reason(); !why.empty()) throw py::value_error(why);
  c.model = surrogate::load_viscosity_model(surrogate_file);
  std::ostringstream log;
  {
    py::gil_scoped_release release;  // long MCMC runs; the C++ side touches no Python object
    if (report.empty()) {
      const cal::CalibrationInput input = cal::read_calibration_input(data, o.plasma);
      c.report = cal::calibrate_samples(input, *c.model, o, log);
    } else {
      o.report_folder = report;
      c.report = cal::run_calibration_job(o, log).report;
    }
  }
  c.log = log.str();
  return c;
}

}  // namespace

void bind_calibration(py::module_& m) {
  py::class_<PosteriorFunction>(m, "LogPosterior",
                                "Log posterior of one sample's parameters theta (see parameter_names), as the MCMC "
                                "samples it: -inf outside the prior's support")
      .def("__call__", &PosteriorFunction::operator(), py::arg("theta"))
      .def_property_readonly("dimension", [](const PosteriorFunction& f) { return f.posterior.dimension(); })
      .def_property_readonly("parameter_names",
                             [](const PosteriorFunction& f) { return f.posterior.parameter_names(); });

  py::class_<Calibration>(m, "Calibration", "The result of rbcal.calibrate")
      .def_property_readonly("samples",
                             [](const Calibration& c) {
                               py::list out;
                               for (const auto& s : c.report.samples) out.append(to_python(cal::sample_summary(s)));
                               return out;
                             },
                             "Per sample, the dict that summary.json holds under 'samples' (G_s in uN/m, intervals, "
                             "diagnostics, left-out points, warnings)")
      .def_property_readonly("log", [](const Calibration& c) { return c.log; }, "What the command line would print")
      .def_property_readonly(
          "joint",
          [](const Calibration& c) -> py::object {
            return c.report.joint ? to_python(cal::joint_summary(*c.report.joint)) : py::none();
          },
          "The joint posterior over the samples (joint=True, or with compare): the dict summary.json holds under "
          "'joint' (G_s per sample in uN/m, shared nuisances, population layer, every parameter); None without it")
      .def_property_readonly(
          "comparison",
          [](const Calibration& c) -> py::object {
            return c.report.comparison ? to_python(cal::comparison_summary(*c.report.comparison)) : py::none();
          },
          "The G_s ratio of compare='A/B' from the joint posterior: median, mean, interval, probability that it "
          "exceeds 1; None without compare")
      .def(
          "comparison_draws",
          [](const Calibration& c) {
            if (!c.report.comparison) throw py::value_error("no comparison: pass compare='NUMERATOR/DENOMINATOR'");
            const std::vector<double>& d = c.report.comparison->ratio.draws;
            return py::array_t<double>(static_cast<py::ssize_t>(d.size()), d.data());
          },
          "The draws of the G_s ratio (numerator over denominator), one per joint posterior draw")
      .def(
          "parameter_names", [](const Calibration& c, const std::string& s) { return c.mcmc(s).mcmc.parameter_names; },
          py::arg("sample"))
      .def(
          "chains",
          [](const Calibration& c, const std::string& s) {
            const cal::McmcResult& r = c.mcmc(s).mcmc;
            std::vector<cal::ChainSet> series;  // per parameter: chains x draws
            for (std::size_t p = 0; p < r.parameter_names.size(); ++p)
              series.push_back(r.ensemble_series(static_cast<int>(p)));
            const py::ssize_t n_chains = static_cast<py::ssize_t>(series[0].size());
            const py::ssize_t n_draws = n_chains ? static_cast<py::ssize_t>(series[0][0].size()) : 0;
            const py::ssize_t n_params = static_cast<py::ssize_t>(series.size());
            py::array_t<double> out({n_chains, n_draws, n_params});
            auto a = out.mutable_unchecked<3>();
            for (py::ssize_t p = 0; p < n_params; ++p)
              for (py::ssize_t k = 0; k < n_chains; ++k)
                for (py::ssize_t d = 0; d < n_draws; ++d) a(k, d, p) = series[p][k][d];
            return out;
          },
          py::arg("sample"),
          "Post-burn-in MCMC draws, chains x draws x parameters (each chain an ensemble, its walkers pooled step by "
          "step; parameters as parameter_names, in log space)")
      .def(
          "log_posterior",
          [](const Calibration& c, const std::string& s) {
            const cal::McmcCalibration& r = c.mcmc(s);
            return PosteriorFunction{c.model, cal::LogPosterior(*c.model, r.plasma_viscosity, r.points, r.posterior,
                                                                r.plasma_viscosity_standard_error)};
          },
          py::arg("sample"), "The sample's log posterior as a callable of theta (the one its MCMC sampled)");

  m.def("calibrate", &calibrate, py::arg("data"), py::arg("surrogate"), py::arg("method") = "all",
        py::arg("samples") = std::vector<std::string>{}, py::arg("lam") = cal::kDefaultViscosityRatio,
        py::arg("fit_lambda") = true, py::arg("lambda_prior_sd") = cal::kLambdaPriorLogSd, py::arg("cell_radius_um") = cal::kDefaultCellRadius * 1e6,
        py::arg("plateau_min_shear_rate") = 10.0, py::arg("phi_max") = 1.0, py::arg("min_shear_rate") = 40.0,
        py::arg("keep_out_of_order") = false, py::arg("hold_points") = false, py::arg("seed") = 20240601ULL, py::arg("threads") = 0,
        py::arg("mcmc_max_steps") = 20000, py::arg("chains") = 4, py::arg("walkers") = 0, py::arg("sampler") = "independence", py::arg("compare") = "",
        py::arg("joint") = false, py::arg("shared_lambda") = false, py::arg("hierarchical") = false,
        py::arg("report") = "", py::arg("plots") = false,
        "G_s of each sample in a rheometer CSV against a surrogate or surrogate-family file, by the alpha method, the direct fit and MCMC "
        "(the options and defaults of `rbcal calibrate`); compare='A/B': their G_s ratio from a joint posterior; joint: one "
        "posterior over all samples (shared_lambda, hierarchical as --shared-lambda, --hierarchical); report: also write "
        "the report folder there");
}

}  // namespace rbcal::python
