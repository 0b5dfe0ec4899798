#include "python/interrupted_run.h"

#include <pybind11/pybind11.h>

#include <csignal>

namespace shockmap::python {

void RaiseStop(int signal) {
  if (signal == 0) return;
  std::raise(signal);
  if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
}

void ThrowInterrupted(const std::string& message) {
  PyErr_SetString(PyExc_InterruptedError, message.c_str());
  throw pybind11::error_already_set();
}

}  // namespace shockmap::python
