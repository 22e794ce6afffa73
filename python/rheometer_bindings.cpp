// rbcal.read_rheometer_csv: a rheometer CSV (docs/reference.md) checked as the command
// line checks it; a bad file raises rbcal.RheometerDataError (a ValueError) whose
// attributes file, line and field name the culprit.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "calibration/calibration_input.hpp"
#include "calibration/rheometer_data.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace rbcal::python {

namespace {

template <typename Get>
py::array_t<double> column(const std::vector<calibration::RelativeViscosityPoint>& points, Get get) {
  py::array_t<double> a(static_cast<py::ssize_t>(points.size()));
  double* out = a.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = get(points[i]);
  return a;
}

py::dict sample_dict(const calibration::SampleData& s) {
  using P = calibration::RelativeViscosityPoint;
  py::dict plasma;
  plasma["eta0_mPa_s"] = 1e3 * s.plasma.eta0;
  plasma["eta0_standard_error_mPa_s"] = 1e3 * s.plasma.standard_error;
  plasma["plateau_rows"] = s.plasma.plateau_rows;
  plasma["assumed"] = s.plasma.assumed;
  py::dict points;
  points["line"] = column(s.points, [](const P& p) { return static_cast<double>(p.line); }).attr("astype")("int64");
  points["phi"] = column(s.points, [](const P& p) { return p.phi; });
  points["shear_rate_per_s"] = column(s.points, [](const P& p) { return p.shear_rate; });
  points["eta_re"] = column(s.points, [](const P& p) { return p.eta_re; });
  points["eta_re_sd"] = column(s.points, [](const P& p) { return p.eta_re_sd; });
  points["viscosity_mPa_s"] = column(s.points, [](const P& p) { return 1e3 * p.viscosity; });
  points["viscosity_se_mPa_s"] = column(s.points, [](const P& p) { return 1e3 * p.viscosity_se; });
  py::dict d;
  d["name"] = s.name;
  d["plasma"] = plasma;
  d["points"] = points;
  return d;
}

}  // namespace

void bind_rheometer(py::module_& m) {
  static py::exception<calibration::RheometerDataError> error(m, "RheometerDataError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const calibration::RheometerDataError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(error.ptr())(e.what());
      instance.attr("file") = e.file();
      instance.attr("line") = e.line();
      instance.attr("field") = e.field();
      PyErr_SetObject(error.ptr(), instance.ptr());
    }
  });
  m.def(
      "read_rheometer_csv",
      [](const std::string& path, double plateau_min_shear_rate) {
        calibration::PlasmaViscosityOptions options;
        options.plateau_min_shear_rate = plateau_min_shear_rate;
        const calibration::CalibrationInput input = calibration::read_calibration_input(path, options);
        py::dict d;
        d["source"] = input.source;
        d["provenance"] = input.provenance;
        py::list samples;
        for (const auto& s : input.samples) samples.append(sample_dict(s));
        d["samples"] = samples;
        return d;
      },
      py::arg("path"), py::arg("plateau_min_shear_rate") = 10.0,
      "Samples of a rheometer CSV: name, plasma viscosity (mPa s), and per point phi, shear rate (1/s), eta_re "
      "with its sd, viscosity (mPa s); raises RheometerDataError naming file, line and field");
}

}  // namespace rbcal::python
