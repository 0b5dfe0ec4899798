#pragma once
// NumPy arrays over the signals of a result the module holds in a shared pointer: no copy is
// made, and each array keeps the result alive, so that it outlives the Python object it was
// taken from. The arrays are read-only: the result is shared.

#include <pybind11/numpy.h>

#include <memory>
#include <vector>

#include "core/uniform_signal.h"

namespace shockmap::python {

namespace py = pybind11;

// A read-only array over `values`, which `owner` holds.
py::array ArrayOver(const std::shared_ptr<const void>& owner, const std::vector<double>& values);

// Sample times t0_s + i dt_s for i < n (s), a new array.
py::array SampleTimes(double t0_s, double dt_s, std::size_t n);

// The sample times of `signal`.
inline py::array TimesOf(const UniformSignal& signal) {
  return SampleTimes(signal.t0_s, signal.dt_s, signal.values.size());
}

}  // namespace shockmap::python
