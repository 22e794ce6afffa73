// The Python module `rbcal`: the surrogate, rheometer data and the calibrations of the C++
// library, with the same checks and messages as the command line. Errors in input files
// raise rbcal.FormatError or rbcal.RheometerDataError (both ValueError), whose messages
// name the file, line and field.
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "formats/format_error.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace {

// $RBCAL_DATA; else the installed layout next to the module (PREFIX/lib/python3/
// dist-packages/rbcal.so -> PREFIX/share/rbcal/data), as the command line finds it next to
// its executable; else the source tree's data/ (the module in the build tree).
std::filesystem::path data_folder() {
  if (const char* env = std::getenv("RBCAL_DATA")) return env;
  const std::filesystem::path module = py::module_::import("rbcal").attr("__file__").cast<std::string>();
  const std::filesystem::path installed = module.parent_path() / "../../../share/rbcal/data";
  if (std::filesystem::is_directory(installed)) return std::filesystem::weakly_canonical(installed);
  return RBCAL_SOURCE_DATA;
}

}  // namespace

PYBIND11_MODULE(rbcal, m) {
  m.doc() = "rbcal: red blood cell deformability (membrane shear modulus G_s) from rheometer curves";
  py::register_exception<rbcal::formats::FormatError>(m, "FormatError", PyExc_ValueError);
  m.def("data_folder", [] { return data_folder().string(); },
        "Folder of the shipped data (samples/, library/default/): $RBCAL_DATA, the installed copy or the source tree");
  m.def("shipped_file", [](const std::string& relative) { return (data_folder() / relative).string(); },
        py::arg("relative"), "Path of a shipped file, e.g. 'library/default/surrogate.json'");
  rbcal::python::bind_surrogate(m);
  rbcal::python::bind_rheometer(m);
  rbcal::python::bind_calibration(m);
  rbcal::python::bind_diagnostics(m);
}
