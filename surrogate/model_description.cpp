#include "surrogate/model_description.hpp"

#include <cmath>
#include <cstdio>

#include "formats/printf_string.hpp"

namespace rbcal::surrogate {

using formats::printf_string;

std::string describe_surrogate(const ViscositySurrogate& s) {
  const auto& hp = s.process().hyperparameters();
  const ParameterRange r = s.range();
  std::string out = printf_string("  training cases      %zu\n", s.training_cases().size());
  out += printf_string("  range               phi %.4g .. %.4g, Ca %.4g .. %.4g, lambda %.4g .. %.4g\n", r.phi_min,
                       r.phi_max, r.ca_min, r.ca_max, r.lambda_min, r.lambda_max);
  out += printf_string("  signal sd           %.4g (ln eta_re)\n", std::exp(0.5 * hp.log_signal_variance));
  out +=
      printf_string("  length scales       phi %.4g, ln Ca %.4g, ln lambda %.4g\n", std::exp(hp.log_length_scales(0)),
                    std::exp(hp.log_length_scales(1)), std::exp(hp.log_length_scales(2)));
  out += printf_string("  nugget sd           %.3g (ln eta_re, on top of each case's SEM)\n",
                std::exp(0.5 * hp.log_nugget_variance));
  out += printf_string("  log marginal lik.   %.6g (%d of %d starts converged)\n", s.fit_info().log_marginal_likelihood,
                s.fit_info().starts_converged, s.fit_info().starts_tried);
  out += printf_string(
      "  predictive sd scale %.4g (held-out RMS %.3g: leave-one-out residuals against each run's own scatter, "
      "if above 1)\n",
      s.predictive_sd_scale(), s.held_out_rms());
  out += "  mean ln eta_re      ";
  const Eigen::VectorXd b = s.mean_coefficients(), sd = s.mean_coefficient_sds();
  for (std::size_t k = 0; k < s.mean_terms().size(); ++k)
    out += printf_string("%s(%.4g +- %.2g) %s", k ? " + " : "", b(static_cast<Eigen::Index>(k)),
                  sd(static_cast<Eigen::Index>(k)), s.mean_terms()[k].c_str());
  return out + "\n";
}

std::string describe_family(const OffsetFamilyModel& family, const std::string& box_source) {
  const ModelNuisance& c = family.offset_prior();
  std::string out =
      printf_string("  offset prior        normal(%.4g, %.4g) truncated to %.4g .. %.4g lattice spacings\n", c.mean,
                    c.sd, c.min, c.max);
  if (const auto& box = family.box_correction()) {
    out += printf_string("  box correction      beta normal(%.4g, %.4g), integrated out (%s)\n", box->mean, box->sd,
                  box_source.c_str());
    if (box->depends_on_ca())
      out += printf_string("                      above Ca %.4g: + slope ln(Ca / %.4g), slope normal(%.4g, %.4g)\n",
                           box->ca_knee, box->ca_knee, box->ca_slope, box->ca_slope_sd);
  }
  const ParameterRange r = family.range();
  out += printf_string("  common range        phi %.4g .. %.4g, Ca %.4g .. %.4g, lambda %.4g .. %.4g\n", r.phi_min,
                       r.phi_max, r.ca_min, r.ca_max, r.lambda_min, r.lambda_max);
  out += "  phi 0.41, Ca 0.8, lambda 5 (eta_re per member):";
  for (const auto& m : family.members())
    out += printf_string(" c %.3g: %.3f", m.offset, m.model->predict(0.41, 0.8, 5.0).eta_re);
  return out + "\n";
}

}  // namespace rbcal::surrogate
