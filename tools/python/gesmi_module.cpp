// The gesmi Python module: reading and writing missions and results, simulate,
// solve (every mode of SolveOptions), kalman, localize and estimate. docs/python.md
// shows a session. Bad input raises gesmi.FormatError, a ValueError carrying the same
// one-line message as the command line.

#include "io/format_error.h"
#include "io/io_version.h"
#include "tools/python/bindings.h"

PYBIND11_MODULE(gesmi, m) {
  namespace py = pybind11;
  m.doc() = "gesmi: guaranteed estimation of seamarks with intervals";
  m.attr("__version__") = std::string(gesmi::io::version());
  static py::exception<gesmi::io::FormatError> format_error(m, "FormatError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const gesmi::io::FormatError& e) {
      format_error(e.what());
    }
  });
  gesmi::python::bind_mission(m);
  gesmi::python::bind_solve(m);
  gesmi::python::bind_kalman(m);
  gesmi::python::bind_localize(m);
  gesmi::python::bind_estimate(m);
}
