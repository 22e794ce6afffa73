#include "calibration/detail/posterior_netcdf.hpp"

#include <netcdf.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "formats/units.hpp"
#include "formats/provenance.hpp"

namespace rbcal::calibration {

namespace {

// One NetCDF-4 file open for writing; every call checked, errors name the file.
class NetcdfFile {
 public:
  explicit NetcdfFile(std::filesystem::path path) : path_(std::move(path)) {
    check(nc_create(path_.c_str(), NC_NETCDF4 | NC_CLOBBER, &id_), "create");
    const nlohmann::json provenance = formats::provenance_block();
    created_at_ = provenance.value("date", "");
    library_version_ = provenance.value("rbcal_version", "") + " (" + provenance.value("git_revision", "") + ")";
  }
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;
  ~NetcdfFile() {
    if (id_ >= 0) nc_close(id_);
  }
  void close() {
    const int id = id_;
    id_ = -1;
    check(nc_close(id), "close");
  }
  int id() const { return id_; }
  void check(int status, const std::string& what) const {
    if (status != NC_NOERR)
      throw std::runtime_error(path_.string() + ": NetCDF " + what + ": " + nc_strerror(status));
  }
  int group(const std::string& name) {
    int g = -1;
    check(nc_def_grp(id_, name.c_str(), &g), "group " + name);
    text(g, NC_GLOBAL, "created_at", created_at_);
    text(g, NC_GLOBAL, "inference_library", "rbcal");
    text(g, NC_GLOBAL, "inference_library_version", library_version_);
    return g;
  }
  // A dimension with an integer coordinate variable of the same name.
  int dimension(int group, const std::string& name, const std::vector<long long>& values) {
    int dim = -1, var = -1;
    check(nc_def_dim(group, name.c_str(), values.size(), &dim), "dimension " + name);
    check(nc_def_var(group, name.c_str(), NC_INT64, 1, &dim, &var), "coordinate " + name);
    check(nc_put_var_longlong(group, var, values.data()), "coordinate " + name);
    return dim;
  }
  int variable(int group, const std::string& name, const std::vector<int>& dims, const std::vector<double>& values) {
    int var = -1;
    check(nc_def_var(group, name.c_str(), NC_DOUBLE, static_cast<int>(dims.size()), dims.data(), &var), "variable " + name);
    check(nc_put_var_double(group, var, values.data()), "variable " + name);
    return var;
  }
  void text(int group, int var, const std::string& name, const std::string& value) {
    check(nc_put_att_text(group, var, name.c_str(), value.size(), value.c_str()), "attribute " + name);
  }

 private:
  std::filesystem::path path_;
  int id_ = -1;
  std::string created_at_, library_version_;  // the same in every group
};

// A sampled parameter as the report shows it: name, units, and its value from the sampled one.
struct ShownParameter {
  std::string name, units;
  double scale = 1.0;
  bool logarithm = false;
};

ShownParameter shown(const std::string& sampled) {
  if (sampled == "ln_G_s") return {"G_s", "uN/m", kMicro, true};
  if (sampled == "ln_eta0") return {"eta0", "mPa s", kMilli, true};
  if (sampled.rfind("ln_", 0) == 0) return {sampled.substr(3), "1", 1.0, true};
  return {sampled, "", 1.0, false};
}

std::vector<long long> counting(std::size_t n) {
  std::vector<long long> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<long long>(i);
  return v;
}

}  // namespace

std::filesystem::path write_posterior_netcdf(const SampleReport& sample, const std::filesystem::path& folder) {
  if (!sample.saved_draws || sample.saved_draws->steps.empty()) return {};
  const SavedDraws& s = *sample.saved_draws;
  const std::filesystem::path path = folder / (sample_file_stem(sample.sample.name) + "_posterior.nc");
  NetcdfFile file(path);
  const std::size_t series = static_cast<std::size_t>(s.chains) * static_cast<std::size_t>(s.walkers);
  const std::size_t draws = s.steps.size(), points = s.points.size();
  const std::vector<long long> steps(s.steps.begin(), s.steps.end());
  file.text(file.id(), NC_GLOBAL, "sample", sample.sample.name);
  file.text(file.id(), NC_GLOBAL, "chain_is", "walker series: chain k, walker w of the sampler -> k * walkers + w");
  file.text(file.id(), NC_GLOBAL, "walkers_per_chain", std::to_string(s.walkers));
  file.text(file.id(), NC_GLOBAL, "draw_is", "the sampler's step (chains.csv's step column)");

  // Rows of s.parameters are series-major, then draw: the (chain, draw) layout as it is.
  const int posterior = file.group("posterior");
  const int p_chain = file.dimension(posterior, "chain", counting(series));
  const int p_draw = file.dimension(posterior, "draw", steps);
  for (std::size_t p = 0; p < s.parameter_names.size(); ++p) {
    const ShownParameter how = shown(s.parameter_names[p]);
    std::vector<double> v(series * draws);
    for (std::size_t row = 0; row < v.size(); ++row) {
      const double x = s.parameters(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(p));
      v[row] = how.scale * (how.logarithm ? std::exp(x) : x);
    }
    const int var = file.variable(posterior, how.name, {p_chain, p_draw}, v);
    if (!how.units.empty()) file.text(posterior, var, "units", how.units);
    file.text(posterior, var, "sampled_as", s.parameter_names[p]);
  }

  const int stats = file.group("sample_stats");
  const int s_chain = file.dimension(stats, "chain", counting(series));
  const int s_draw = file.dimension(stats, "draw", steps);
  file.variable(stats, "lp", {s_chain, s_draw}, std::vector<double>(s.log_posterior.data(), s.log_posterior.data() + s.log_posterior.size()));

  const int likelihood = file.group("log_likelihood");
  const int l_chain = file.dimension(likelihood, "chain", counting(series));
  const int l_draw = file.dimension(likelihood, "draw", steps);
  const int l_point = file.dimension(likelihood, "point", counting(points));
  std::vector<double> ll(series * draws * points);
  for (std::size_t row = 0; row < series * draws; ++row)
    for (std::size_t i = 0; i < points; ++i)
      ll[row * points + i] = s.log_likelihood(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(i));
  const int ll_var = file.variable(likelihood, "eta", {l_chain, l_draw, l_point}, ll);
  file.text(likelihood, ll_var, "meaning",
            "marginal normal log density of each point's eta_re (model sd, discrepancy and measurement error in "
            "quadrature); the likelihood correlates the model's errors across points, so these do not sum to it");

  const int observed = file.group("observed_data");
  const int o_point = file.dimension(observed, "point", counting(points));
  std::vector<double> phi, rate;
  for (const RelativeViscosityPoint& p : s.points) phi.push_back(p.phi), rate.push_back(p.shear_rate);
  const int eta = file.variable(observed, "eta", {o_point}, s.observed_eta_re);
  file.text(observed, eta, "units", "1 (relative viscosity, over the plateau's plasma viscosity)");
  file.text(observed, eta, "coordinates", "phi shear_rate");
  file.variable(observed, "phi", {o_point}, phi);
  const int rate_var = file.variable(observed, "shear_rate", {o_point}, rate);
  file.text(observed, rate_var, "units", "1/s");
  file.close();
  return path;
}

}  // namespace rbcal::calibration
