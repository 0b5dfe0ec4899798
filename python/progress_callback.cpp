#include "python/progress_callback.h"

#include <string>
#include <utility>

namespace shockmap::python {

ProgressListener CallbackListener(const py::function& callback,
                                  std::optional<py::error_already_set>& raised) {
  return [&callback, &raised](std::string_view phase, double done, double total) {
    const py::gil_scoped_acquire gil;
    if (raised) return;
    try {
      callback(std::string(phase), done, total);
    } catch (py::error_already_set& e) {
      raised = std::move(e);
    }
  };
}

}  // namespace shockmap::python
