// One function per part of the library bound into _fogdrift (module.cpp).
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "fogdrift/base/interrupt.hpp"

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

/// Runs `work` with the GIL released, on a thread of its own, while this thread checks Python's
/// signals every 20 ms: Ctrl-C (or an alarm whose handler raises) asks the work to stop at its
/// next check (base/interrupt.hpp: every SMO round, pool task and optimizer iteration) and,
/// once it has, raises the handler's exception (KeyboardInterrupt) here. Call with the GIL held.
template <class Work>
void released_interruptibly(Work&& work) {
  clear_interrupt();
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false, signalled = false;
  {
    pybind11::gil_scoped_release release;
    std::thread worker([&] {
      try {
        work();
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock lock(mutex);
    // A short call returns as soon as it is done; a long one is looked in on every 20 ms.
    while (!finished.wait_for(lock, std::chrono::milliseconds(20), [&] { return done; })) {
      if (signalled) continue;
      lock.unlock();
      {
        pybind11::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) {
          signalled = true;  // the handler's exception stays set until it is raised below
          request_interrupt();
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  clear_interrupt();
  if (signalled) throw pybind11::error_already_set();
  if (error) std::rethrow_exception(error);
}

}  // namespace fogdrift::python
