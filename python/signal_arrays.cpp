#include "python/signal_arrays.h"

namespace shockmap::python {

py::array ArrayOver(const std::shared_ptr<const void>& owner, const std::vector<double>& values) {
  // The capsule holds a copy of the shared pointer and drops it with the last array.
  py::capsule keeper(new std::shared_ptr<const void>(owner),
                     [](void* p) { delete static_cast<std::shared_ptr<const void>*>(p); });
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()), values.data(), keeper);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

py::array SampleTimes(double t0_s, double dt_s, std::size_t n) {
  py::array_t<double> times(static_cast<py::ssize_t>(n));
  auto t = times.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < t.shape(0); ++i) t(i) = t0_s + static_cast<double>(i) * dt_s;
  return times;
}

}  // namespace shockmap::python
