// rbcal.chain_diagnostics: rbcal's convergence diagnostics of any set of chains (the ones the
// MCMC's stopping rule uses), so that notebooks and the tests can apply them to other
// samplers' chains (emcee) and check them against other implementations.
#include <pybind11/numpy.h>

#include "calibration/chain_diagnostics.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace rbcal::python {

void bind_diagnostics(py::module_& m) {
  m.def(
      "chain_diagnostics",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& chains) {
        if (chains.ndim() != 2 || chains.shape(0) < 1 || chains.shape(1) < 4)
          throw py::value_error("chains must be a 2-D array: chains x draws, at least 4 draws");
        calibration::ChainSet set(static_cast<std::size_t>(chains.shape(0)));
        auto a = chains.unchecked<2>();
        for (py::ssize_t k = 0; k < chains.shape(0); ++k)
          for (py::ssize_t d = 0; d < chains.shape(1); ++d) set[k].push_back(a(k, d));
        py::dict out;
        out["rhat"] = calibration::rank_normalized_split_rhat(set);
        out["split_rhat"] = calibration::split_rhat(set);
        out["bulk_ess"] = calibration::bulk_effective_sample_size(set);
        out["tail_ess"] = calibration::tail_effective_sample_size(set);
        out["ess"] = calibration::effective_sample_size(set);
        return out;
      },
      py::arg("chains"),
      "Rank-normalised split R-hat, classic split R-hat, bulk, tail and plain ESS of chains x draws of one scalar "
      "(Vehtari et al. 2021; the estimators behind the MCMC's stopping rule)");
}

}  // namespace rbcal::python
