#pragma once
// The parts of the Python module `rbcal`, one per concept; module.cpp puts them together.
#include <pybind11/pybind11.h>

namespace rbcal::python {

void bind_surrogate(pybind11::module_& m);    // Surrogate: load, predict on NumPy arrays, range
void bind_rheometer(pybind11::module_& m);    // read_rheometer_csv, RheometerDataError
void bind_calibration(pybind11::module_& m);  // calibrate, Calibration, LogPosterior
void bind_diagnostics(pybind11::module_& m);  // chain_diagnostics: R-hat and ESS of any chains

}  // namespace rbcal::python
