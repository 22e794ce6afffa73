#include "calibration/calibration_input.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcal::calibration {

const SampleData& CalibrationInput::sample(const std::string& name) const {
  std::string known;
  for (const auto& s : samples) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw std::out_of_range("no sample '" + name + "' in " + source + " (samples: " + known + ")");
}

CalibrationInput make_calibration_input(const RheometerData& data, const PlasmaViscosityOptions& options) {
  CalibrationInput input;
  input.source = data.source;
  input.provenance = data.provenance;
  for (const auto& name : data.sample_names()) {
    SampleData sample;
    sample.name = name;
    std::vector<RheometerRow> plasma_rows;
    const RheometerRow* assumption = nullptr;
    for (const auto& row : data.rows) {
      if (row.sample != name) continue;
      if (row.kind == MeasurementKind::plasma) plasma_rows.push_back(row);
      if (row.kind == MeasurementKind::plasma_assumed) assumption = &row;
    }
    if (assumption) {
      sample.plasma.eta0 = assumption->viscosity;
      sample.plasma.standard_error = assumption->viscosity_sd;
      sample.plasma.assumed = true;
    } else {
      sample.plasma = estimate_plasma_viscosity(plasma_rows, data.source, options);
    }
    const double eta0 = sample.plasma.eta0;
    const double relative_se0 = sample.plasma.standard_error / eta0;
    for (const auto& row : data.rows) {
      if (row.sample != name || row.kind != MeasurementKind::suspension) continue;
      RelativeViscosityPoint point;
      point.phi = row.phi;
      point.shear_rate = row.shear_rate;
      point.eta_re = row.viscosity / eta0;
      const double relative_se = row.viscosity_sd / std::sqrt(static_cast<double>(row.repeats)) / row.viscosity;
      point.eta_re_sd = point.eta_re * std::hypot(relative_se, relative_se0);
      point.viscosity = row.viscosity;
      point.viscosity_se = relative_se * row.viscosity;
      point.line = row.line;
      sample.points.push_back(point);
    }
    input.samples.push_back(std::move(sample));
  }
  return input;
}

CalibrationInput read_calibration_input(const std::filesystem::path& csv, const PlasmaViscosityOptions& options) {
  return make_calibration_input(read_rheometer_csv(csv), options);
}

}  // namespace rbcal::calibration
