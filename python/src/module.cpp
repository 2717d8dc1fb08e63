// The extension module _fogdrift: fogdrift's C++ library for the Python package (python/fogdrift,
// docs/python.md). The estimators and their scikit-learn conventions live in Python; this module
// converts arrays and errors and releases the GIL around the work.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/memory.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_fogdrift, m) {
  m.doc() = "fogdrift's C++ library (use the package fogdrift, not this module)";
  m.attr("__version__") = FOGDRIFT_VERSION;
  // Errors carry the message the CLI prints: bad data and options are ValueError, a job larger
  // than the memory left is MemoryError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const fogdrift::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const fogdrift::OptionError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const fogdrift::ResourceError& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    } catch (const fogdrift::Interrupted&) {
      PyErr_SetString(PyExc_KeyboardInterrupt, "interrupted");
    }
  });
  fogdrift::python::bind_svr(m);
  fogdrift::python::bind_model(m);
  fogdrift::python::bind_train(m);
  fogdrift::python::bind_signal(m);
  fogdrift::python::bind_eval(m);
  fogdrift::python::bind_sim(m);
  fogdrift::python::bind_stream(m);
}
