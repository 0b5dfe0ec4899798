// Study: a study file read with the command line's checks, run into a database by the same
// engine as `shockmap study run` (resumable, leased, stoppable), on this process's threads.

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "engine/stop_request.h"
#include "engine/study_run.h"
#include "python/bindings.h"
#include "python/interrupted_run.h"
#include "python/progress_callback.h"

namespace shockmap::python {
namespace {

struct StudyHandle {
  StudyFile file;
  std::string path;
};

std::string NameOf(const StudyHandle& h) {
  return std::visit([](const auto& spec) { return spec.name; }, h.file);
}

StudyFileKind KindOf(const StudyHandle& h) {
  return std::visit(
      [](const auto& spec) {
        using Spec = std::decay_t<decltype(spec)>;
        if constexpr (std::is_same_v<Spec, StudySpec>) return StudyFileKind::kCanonical;
        if constexpr (std::is_same_v<Spec, SceneStudySpec>) return StudyFileKind::kSceneSweep;
        if constexpr (std::is_same_v<Spec, EnsembleStudySpec>) return StudyFileKind::kSceneEnsemble;
      },
      h.file);
}

py::dict SummaryDict(const StudyRunSummary& s) {
  py::dict d;
  d["study"] = s.study;
  d["points_in_study"] = s.points_in_study;
  d["points_to_compute"] = s.points_to_compute;
  d["points_computed"] = s.points_computed;
  d["ok"] = s.ok;
  d["diverged"] = s.diverged;
  d["unstable"] = s.unstable;
  d["failed"] = s.failed;
  d["reference_unconverged"] = s.reference_unconverged;
  d["references_computed"] = s.references_computed;
  d["references_reused"] = s.references_reused;
  d["points_reclaimed"] = s.points_reclaimed;
  d["jobs"] = s.jobs;
  d["wall_s"] = s.wall_s;
  d["reference_wall_s"] = s.reference_wall_s;
  d["point_wall_s"] = s.point_wall_s;
  return d;
}

// `progress`: False, True (the command line's lines on stderr) or a callable(phase, done,
// total). A SIGINT stops the run as it stops `study run`: the points computed are stored, the
// others stay pending, and KeyboardInterrupt is raised.
py::dict Run(const StudyHandle& h, const std::string& database_path, std::optional<int> jobs,
             bool retry_failed, const py::object& progress) {
  StudyRunOptions options;
  options.database_path = database_path;
  if (jobs && (*jobs < 1 || *jobs > 1024)) {
    throw InputError("jobs: " + std::to_string(*jobs) + " is outside [1, 1024]");
  }
  options.jobs = jobs.value_or(0);
  options.retry_failed = retry_failed;
  options.progress = py::isinstance<py::bool_>(progress) && progress.cast<bool>();
  std::optional<py::error_already_set> raised;
  py::function callback;
  if (PyCallable_Check(progress.ptr()) != 0) {
    callback = progress.cast<py::function>();
    options.on_progress = CallbackListener(callback, raised);
  }
  StudyRunSummary summary;
  int stop_signal = 0;  // The run's, or one that came after its last check.
  {
    py::gil_scoped_release release;
    const StopHandlersDuringRun stop_handlers;
    summary = RunStudy(h.file, options);
    stop_signal = summary.stop_signal != 0 ? summary.stop_signal : StopSignal();
  }
  if (raised) throw std::move(*raised);
  RaiseStop(stop_signal);
  return SummaryDict(summary);
}

}  // namespace

void BindStudy(py::module_& m) {
  py::class_<StudyHandle>(m, "Study", "A study file, checked whole")
      .def_static(
          "load",
          [](const std::string& path) {
            return StudyHandle{ReadStudyFile(path), path};
          },
          py::arg("path"))
      .def_property_readonly("name", &NameOf)
      .def_property_readonly("kind", [](const StudyHandle& h) { return ToString(KindOf(h)); })
      .def_property_readonly("path", [](const StudyHandle& h) { return h.path; })
      .def("run", &Run, py::arg("db"), py::arg("jobs"), py::arg("retry_failed"),
           py::arg("progress"));
}

}  // namespace shockmap::python
