#include "solver/membrane/stretch_fit.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rbcal::solver {

StretchMeasurements read_stretch_measurements(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  StretchMeasurements m;
  std::string line;
  int line_no = 0;
  bool header_seen = false;
  const char* fields[] = {"force_pN", "axial_um", "transverse_um"};
  auto where = [&] { return path + ":" + std::to_string(line_no) + ": "; };
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {
      if (line != "force_pN,axial_um,transverse_um")
        throw std::runtime_error(where() + "header must be force_pN,axial_um,transverse_um");
      header_seen = true;
      continue;
    }
    std::stringstream ss(line);
    std::string cell;
    double values[3];
    for (int k = 0; k < 3; ++k) {
      if (!std::getline(ss, cell, ',')) throw std::runtime_error(where() + "missing field " + fields[k]);
      std::size_t used = 0;
      try {
        values[k] = std::stod(cell, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != cell.size() || !std::isfinite(values[k]) || values[k] < 0.0)
        throw std::runtime_error(where() + "field " + fields[k] + " is not a non-negative number: '" + cell + "'");
    }
    m.force_pn.push_back(values[0]);
    m.axial_um.push_back(values[1]);
    m.transverse_um.push_back(values[2]);
  }
  if (m.force_pn.empty()) throw std::runtime_error(path + ": no data rows");
  return m;
}

double rms_misfit(const std::vector<StretchPoint>& pts, const StretchMeasurements& m) {
  if (pts.size() != m.force_pn.size()) throw std::invalid_argument("rms_misfit: one point per measured force");
  double sum = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double da = pts[i].axial_diameter * 1e6 - m.axial_um[i];
    const double dt = pts[i].transverse_diameter * 1e6 - m.transverse_um[i];
    sum += da * da + dt * dt;
  }
  return std::sqrt(sum / (2.0 * pts.size()));
}

double fit_shear_modulus(const StretchSettings& settings, const StretchMeasurements& measured,
                         const StretchFitOptions& options) {
  if (!(options.shear_modulus_min > 0.0 && options.shear_modulus_max > options.shear_modulus_min))
    throw std::invalid_argument("stretch fit: need 0 < shear_modulus_min < shear_modulus_max");
  std::vector<double> forces;
  for (double f : measured.force_pn) forces.push_back(f * 1e-12);
  auto misfit = [&](double ln_gs) {
    StretchSettings s = settings;
    s.material.shear_modulus = std::exp(ln_gs);
    const double r = rms_misfit(stretch_cell(s, forces), measured);
    if (options.progress) options.progress(s.material.shear_modulus, r);
    return r;
  };
  // Golden-section search over ln G_s.
  double lo = std::log(options.shear_modulus_min), hi = std::log(options.shear_modulus_max);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
  double f1 = misfit(m1), f2 = misfit(m2);
  while (hi - lo > options.ln_tolerance) {
    if (f1 < f2) {
      hi = m2, m2 = m1, f2 = f1;
      m1 = hi - g * (hi - lo);
      f1 = misfit(m1);
    } else {
      lo = m1, m1 = m2, f1 = f2;
      m2 = lo + g * (hi - lo);
      f2 = misfit(m2);
    }
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace rbcal::solver
