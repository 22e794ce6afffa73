#include "surrogate/surrogate_file.hpp"

#include <cmath>
#include <stdexcept>

#include "formats/field_reader.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/provenance.hpp"
#include "surrogate/simulation_library.hpp"

namespace rbcal::surrogate {

namespace {

const char* const kDimensionNames[3] = {"phi", "ln_Ca", "ln_lambda"};

nlohmann::json vector_json(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v(i));
  return a;
}

}  // namespace

nlohmann::json surrogate_to_json(const ViscositySurrogate& s) {
  const GaussianProcessHyperparameters& hp = s.process().hyperparameters();
  nlohmann::json j;
  j["schema"] = formats::kSurrogateSchema;
  j["model"] = "universal kriging of ln eta_re over (phi_actual, ln Ca, ln lambda); mean phi (b0 + b1 ln Ca + "
               "b2 ln lambda), GLS; anisotropic Matern-5/2 kernel; noise (eta_re_sem/eta_re)^2 + nugget + 1e-10";
  j["source_library"] = s.source_library();

  nlohmann::json h;
  h["log_signal_variance"] = hp.log_signal_variance;
  h["log_length_scales"] = vector_json(hp.log_length_scales);
  h["log_nugget_variance"] = hp.log_nugget_variance;
  h["signal_sd"] = std::exp(0.5 * hp.log_signal_variance);
  for (int d = 0; d < 3; ++d) h["length_scales"][kDimensionNames[d]] = std::exp(hp.log_length_scales(d));
  h["nugget_sd"] = std::exp(0.5 * hp.log_nugget_variance);
  j["hyperparameters"] = h;
  j["predictive_sd_scale"] = s.predictive_sd_scale();

  j["fit"] = {{"log_marginal_likelihood", s.fit_info().log_marginal_likelihood},
              {"starts_tried", s.fit_info().starts_tried},
              {"starts_converged", s.fit_info().starts_converged}};
  j["mean"] = {{"terms", s.mean_terms()},
               {"coefficients", vector_json(s.mean_coefficients())},
               {"sd", vector_json(s.mean_coefficient_sds())}};
  const ParameterRange r = s.range();
  j["range"] = {{"phi", {r.phi_min, r.phi_max}}, {"Ca", {r.ca_min, r.ca_max}}, {"lambda", {r.lambda_min, r.lambda_max}}};

  nlohmann::json training = nlohmann::json::array();
  for (const TrainingCase& c : s.training_cases())
    training.push_back({{"id", c.id},
                        {"phi", c.phi},
                        {"ln_Ca", c.ln_ca},
                        {"ln_lambda", c.ln_lambda},
                        {"ln_eta_re", c.ln_eta_re},
                        {"noise_variance", c.noise_variance}});
  j["training"] = training;

  const LeaveOneOutReport loo = s.leave_one_out();
  nlohmann::json cases = nlohmann::json::array();
  for (const LeaveOneOutCase& c : loo.cases)
    cases.push_back({{"id", c.id},
                     {"eta_re", c.eta_re},
                     {"eta_re_predicted", c.eta_re_predicted},
                     {"sd", c.sd},
                     {"standardised_residual", c.standardised_residual}});
  j["leave_one_out"] = {{"rms_relative_error", loo.rms_relative_error},
                        {"rms_standardised_residual", loo.rms_standardised_residual},
                        {"max_abs_standardised_residual", loo.max_abs_standardised_residual},
                        {"cases", cases}};

  j["provenance"] = formats::provenance_block();
  return j;
}

ViscositySurrogate surrogate_from_json(const nlohmann::json& j, const std::string& source) {
  const formats::FieldReader r(j, source);
  r.expect_schema(formats::kSurrogateSchema);

  GaussianProcessHyperparameters hp;
  hp.log_signal_variance = r.number("hyperparameters.log_signal_variance");
  const std::vector<double> lengths = r.numbers("hyperparameters.log_length_scales", 3);
  if (lengths.size() != 3) r.fail("hyperparameters.log_length_scales", "must hold 3 numbers (phi, ln Ca, ln lambda)");
  hp.log_length_scales = Eigen::Map<const Eigen::VectorXd>(lengths.data(), 3);
  hp.log_nugget_variance = r.number("hyperparameters.log_nugget_variance");

  const nlohmann::json& training = r.require("training");
  if (!training.is_array() || training.empty()) r.fail("training", "must be a non-empty array of cases");
  std::vector<TrainingCase> cases;
  for (std::size_t i = 0; i < training.size(); ++i) {
    const std::string at = "training." + std::to_string(i) + ".";
    TrainingCase t;
    t.id = r.text(at + "id");
    t.phi = r.number(at + "phi");
    t.ln_ca = r.number(at + "ln_Ca");
    t.ln_lambda = r.number(at + "ln_lambda");
    t.ln_eta_re = r.number(at + "ln_eta_re");
    t.noise_variance = r.non_negative(at + "noise_variance");
    cases.push_back(t);
  }
  SurrogateFitInfo info;
  if (r.find("fit.log_marginal_likelihood")) info.log_marginal_likelihood = r.number("fit.log_marginal_likelihood");
  if (r.find("fit.starts_tried")) info.starts_tried = static_cast<int>(r.integer("fit.starts_tried", 0));
  if (r.find("fit.starts_converged")) info.starts_converged = static_cast<int>(r.integer("fit.starts_converged", 0));
  const std::string library = r.find("source_library") ? r.text("source_library") : "";
  // Absent in files written before it existed: 1 (the sd as fitted).
  const double sd_scale = r.number_or("predictive_sd_scale", 1.0, 1.0, 1e6);
  try {
    return ViscositySurrogate(std::move(cases), hp, library, info, sd_scale);
  } catch (const std::exception& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

void save_surrogate(const ViscositySurrogate& surrogate, const std::filesystem::path& file) {
  formats::write_json_atomically(file, surrogate_to_json(surrogate));
}

ViscositySurrogate load_surrogate(const std::filesystem::path& file) {
  return surrogate_from_json(formats::read_json_file(file), file.string());
}

ViscositySurrogate build_surrogate(const std::filesystem::path& library_root) {
  return ViscositySurrogate::fit(training_cases(read_library(library_root)), library_root.string());
}

ViscositySurrogate build_surrogate_like(const std::filesystem::path& library_root,
                                        const std::filesystem::path& reference_file) {
  return build_surrogate_like(library_root, load_surrogate(reference_file));
}

ViscositySurrogate build_surrogate_like(const std::filesystem::path& library_root, const ViscositySurrogate& reference) {
  return ViscositySurrogate::with_hyperparameters_of(training_cases(read_library(library_root)), reference,
                                                     library_root.string());
}

}  // namespace rbcal::surrogate
