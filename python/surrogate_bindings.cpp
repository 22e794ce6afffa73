// rbcal.Surrogate: a saved surrogate (rbcal.surrogate/1) evaluated on NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "python/bindings.hpp"
#include "surrogate/surrogate_file.hpp"

namespace py = pybind11;

namespace rbcal::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// eta_re, sd and derivatives at every (phi, Ca, lambda) of the broadcast inputs.
py::dict predict(const surrogate::ViscositySurrogate& s, const Array& phi, const Array& ca, const Array& lambda) {
  auto broadcast = py::module_::import("numpy").attr("broadcast_arrays")(phi, ca, lambda).cast<py::tuple>();
  const Array p = broadcast[0].cast<Array>(), c = broadcast[1].cast<Array>(), l = broadcast[2].cast<Array>();
  const py::ssize_t n = p.size();
  std::vector<py::ssize_t> shape(p.shape(), p.shape() + p.ndim());
  Array eta(shape), sd(shape), d_phi(shape), d_ln_ca(shape), d_ln_lambda(shape);
  py::array_t<bool> inside(shape);
  const double *pp = p.data(), *cp = c.data(), *lp = l.data();
  double *e = eta.mutable_data(), *s_ = sd.mutable_data(), *dp = d_phi.mutable_data(), *dc = d_ln_ca.mutable_data(),
         *dl = d_ln_lambda.mutable_data();
  bool* in = inside.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const surrogate::ViscosityPrediction r = s.predict(pp[i], cp[i], lp[i]);
    e[i] = r.eta_re;
    s_[i] = r.sd;
    dp[i] = r.d_phi;
    dc[i] = r.d_ln_ca;
    dl[i] = r.d_ln_lambda;
    in[i] = r.inside_hull;
  }
  py::dict out;
  out["eta_re"] = eta;
  out["sd"] = sd;
  out["d_phi"] = d_phi;
  out["d_ln_ca"] = d_ln_ca;
  out["d_ln_lambda"] = d_ln_lambda;
  out["inside_hull"] = inside;
  return out;
}

}  // namespace

void bind_surrogate(py::module_& m) {
  py::class_<surrogate::ViscositySurrogate>(m, "Surrogate",
                                            "Gaussian-process surrogate of eta_re(phi, Ca, lambda), from a surrogate.json")
      .def(py::init([](const std::string& path) { return surrogate::load_surrogate(path); }), py::arg("path"))
      .def("predict", &predict, py::arg("phi"), py::arg("ca"), py::arg("lam"),
           "eta_re, its sd (model uncertainty) and the derivatives d/dphi, d/dln Ca, d/dln lambda at the broadcast "
           "inputs, as a dict of arrays (with inside_hull: False outside the library's box)")
      .def_property_readonly("range",
                             [](const surrogate::ViscositySurrogate& s) {
                               const surrogate::ParameterRange r = s.range();
                               py::dict d;
                               d["phi"] = py::make_tuple(r.phi_min, r.phi_max);
                               d["Ca"] = py::make_tuple(r.ca_min, r.ca_max);
                               d["lambda"] = py::make_tuple(r.lambda_min, r.lambda_max);
                               return d;
                             })
      .def_property_readonly("training_size",
                             [](const surrogate::ViscositySurrogate& s) { return s.training_cases().size(); })
      .def_property_readonly("source_library", &surrogate::ViscositySurrogate::source_library);
}

}  // namespace rbcal::python
