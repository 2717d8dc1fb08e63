// One function per part of the library bound into _fogdrift (module.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace fogdrift::python {

/// The ε-SVR engine: fit, fit_path, predict (python/fogdrift/svr.py wraps them).
void bind_svr(pybind11::module_& m);

/// Recordings and compensation models: read_recording, write_recording, Model.
void bind_model(pybind11::module_& m);

/// Training on a campaign: train.
void bind_train(pybind11::module_& m);

/// Signals: denoise, features.
void bind_signal(pybind11::module_& m);

/// Evaluation: evaluate, northfind, allan_deviation, noise_terms.
void bind_eval(pybind11::module_& m);

/// The simulator: simulate.
void bind_sim(pybind11::module_& m);

/// Compensation one sample at a time: StreamingCompensator.
void bind_stream(pybind11::module_& m);

/// A UserWarning attributed to the user's line: the compiled functions are called through the
/// wrappers of python/fogdrift/_keywords.py, one frame between. Throws when warnings are errors.
inline void warn(const char* message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message, 2) != 0) throw pybind11::error_already_set();
}

}  // namespace fogdrift::python
