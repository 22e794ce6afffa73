#pragma once
// What every calibration method works on: per sample, the plasma viscosity and the relative
// viscosities eta_re = eta / eta0 of its suspension rows with propagated errors (docs/reference.md, "Rheometer CSV").
#include <filesystem>
#include <string>
#include <vector>

#include "calibration/plasma_viscosity.hpp"
#include "calibration/rheometer_data.hpp"

namespace rbcal::calibration {

struct RelativeViscosityPoint {
  double phi = 0.0;         // volume fraction
  double shear_rate = 0.0;  // [1/s]
  double eta_re = 1.0;      // eta / eta0
  // Standard deviation of eta_re: first-order propagation of the standard error of the mean
  // viscosity (sd / sqrt(n)) and of eta0's standard error, treated as independent:
  // sd(eta_re) = eta_re * sqrt((se_eta / eta)^2 + (se_eta0 / eta0)^2).
  // This sd treats eta0 as known up to independent per-point errors; the methods that take eta0
  // as a nuisance parameter use viscosity and viscosity_se below instead (eta0's error is common
  // to every point of a sample and, since eta_re depends weakly on Ca, dominates G_s's error).
  double eta_re_sd = 0.0;
  double viscosity = 0.0;     // measured mean viscosity [Pa s] (0 for points given as eta_re only)
  double viscosity_se = 0.0;  // its standard error sd / sqrt(n) [Pa s]
  int line = 0;               // source line, 0 for synthetic points
};

// The measured viscosity of a point [Pa s]: as read, or eta_re eta0 for points given as eta_re.
inline double measured_viscosity(const RelativeViscosityPoint& p, double eta0) {
  return p.viscosity > 0.0 ? p.viscosity : p.eta_re * eta0;
}

// Its standard error [Pa s]: sd / sqrt(n) as read, or eta_re_sd eta0 (which holds eta0's error too).
inline double measured_se(const RelativeViscosityPoint& p, double eta0) {
  return p.viscosity > 0.0 ? p.viscosity_se : p.eta_re_sd * eta0;
}

struct SampleData {
  std::string name;
  PlasmaViscosity plasma;
  std::vector<RelativeViscosityPoint> points;  // suspension rows, in file order
};

struct CalibrationInput {
  std::string source;
  std::vector<std::string> provenance;
  std::vector<SampleData> samples;  // in order of first appearance
  // Throws std::out_of_range with the known names if there is no such sample.
  const SampleData& sample(const std::string& name) const;
};

CalibrationInput make_calibration_input(const RheometerData& data, const PlasmaViscosityOptions& options = {});
CalibrationInput read_calibration_input(const std::filesystem::path& csv, const PlasmaViscosityOptions& options = {});

}  // namespace rbcal::calibration
