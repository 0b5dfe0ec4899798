#include "python/interrupted_run.h"

#include <pybind11/pybind11.h>

#include <csignal>

namespace shockmap::python {

void RaiseStop(int signal) {
  if (signal == SIGINT) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw pybind11::error_already_set();
  }
  if (signal != 0) std::raise(signal);
}

}  // namespace shockmap::python
