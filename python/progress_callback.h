#pragma once
// A Python callable as a run's progress listener (engine/progress_reporter.h): progress(phase,
// done, total), called with the GIL held from the run's threads.

#include <pybind11/pybind11.h>

#include <optional>

#include "engine/progress_reporter.h"

namespace shockmap::python {

namespace py = pybind11;

// The listener that calls `callback` with the GIL held. An exception it raises is kept in
// `raised`, later reports are skipped; the caller raises it again once the run has ended. Both
// must outlive the run.
ProgressListener CallbackListener(const py::function& callback,
                                  std::optional<py::error_already_set>& raised);

}  // namespace shockmap::python
