#include "calibration/synthetic_sample.hpp"

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

#include "formats/units.hpp"

namespace rbcal::calibration {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("synthetic sample: " + what);
}

}  // namespace

RheometerData synthetic_rheometer_data(const std::vector<SimulatedViscosity>& points,
                                       const SyntheticSampleOptions& o) {
  require(!points.empty(), "no simulated points");
  require(o.shear_modulus > 0.0, "shear modulus must be positive");
  require(o.plasma_viscosity > 0.0, "plasma viscosity must be positive");
  require(o.plasma_viscosity_relative_sd > 0.0, "the plasma viscosity's relative sd must be positive");
  require(o.cell_radius > 0.0, "cell radius must be positive");
  require(o.relative_noise >= 0.0, "relative noise must not be negative");
  require(!o.name.empty() && o.name.find(',') == std::string::npos, "sample name must be non-empty, without commas");

  RheometerData data;
  data.source = "synthetic sample '" + o.name + "'";
  data.provenance.push_back("Synthetic sample (simulated truth): G_s " + std::to_string(o.shear_modulus * kMicro) +
                            " uN/m, eta0 " + std::to_string(o.plasma_viscosity * kMilli) + " mPa s, a " +
                            std::to_string(o.cell_radius * kMicro) + " um, relative noise " +
                            std::to_string(o.relative_noise) + ", seed " + std::to_string(o.seed));
  RheometerRow plasma;
  plasma.sample = o.name;
  plasma.kind = MeasurementKind::plasma_assumed;
  plasma.viscosity = o.plasma_viscosity;
  plasma.viscosity_sd = o.plasma_viscosity_relative_sd * o.plasma_viscosity;
  data.rows.push_back(plasma);

  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> normal;
  std::set<std::pair<double, double>> seen;
  for (const auto& p : points) {
    data.provenance.push_back("run " + p.id + ": phi " + std::to_string(p.phi) + ", Ca " +
                              std::to_string(p.capillary_number) + ", eta_re " + std::to_string(p.eta_re) +
                              " +- " + std::to_string(p.eta_re_se));
    require(p.phi > 0.0 && p.phi < 1.0, p.id + ": phi must lie in (0, 1)");
    require(p.capillary_number > 0.0, p.id + ": Ca must be positive");
    require(p.eta_re > 0.0 && p.eta_re_se >= 0.0, p.id + ": eta_re must be positive and its se not negative");
    RheometerRow row;
    row.sample = o.name;
    row.kind = MeasurementKind::suspension;
    row.phi = p.phi;
    row.shear_rate =
        shear_rate_from_capillary_number(o.plasma_viscosity, o.cell_radius, o.shear_modulus, p.capillary_number);
    require(seen.emplace(row.phi, row.shear_rate).second, p.id + ": a second point at the same phi and Ca");
    const double truth = o.plasma_viscosity * p.eta_re;
    row.viscosity = truth * (1.0 + o.relative_noise * normal(rng));
    require(row.viscosity > 0.0, p.id + ": the noise made the viscosity negative (noise too large)");
    row.viscosity_sd = truth * std::hypot(o.relative_noise, p.eta_re_se / p.eta_re);
    data.rows.push_back(row);
  }
  return data;
}

}  // namespace rbcal::calibration
