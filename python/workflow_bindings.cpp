// The workflows of workflows/: a stored study's HTML report and the advice checked on an
// ensemble, each one library call with the GIL released, as `shockmap report` and
// `shockmap check-advice` run them.

#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "engine/stop_request.h"
#include "python/bindings.h"
#include "python/interrupted_run.h"
#include "python/progress_callback.h"
#include "views/advice_check_text.h"
#include "workflows/advice_check_ladder.h"
#include "workflows/study_report.h"

namespace shockmap::python {
namespace {

// `progress`: False (nothing told), True (each line the workflow tells printed by Python's
// print, the GIL taken for it) or a callable progress(phase, done, total), called as Study.run
// calls it, an exception it raises kept in `raised`.
struct PythonLog {
  WorkflowLog log;
  bool lines = false;
  py::function callback;
  std::optional<py::error_already_set> raised;

  explicit PythonLog(const py::object& progress) {
    if (PyCallable_Check(progress.ptr()) != 0) {
      callback = progress.cast<py::function>();
      log.progress = CallbackListener(callback, raised);
      return;
    }
    lines = progress.cast<bool>();
    if (!lines) return;
    log.say = [](const std::string& line) {
      const py::gil_scoped_acquire gil;
      py::print(line);
    };
    log.warn = [](const std::string& line) {
      const py::gil_scoped_acquire gil;
      py::print("warning: " + line);
    };
  }
  PythonLog(const PythonLog&) = delete;
  PythonLog& operator=(const PythonLog&) = delete;

  // Raises what the callable raised, once the run has ended. Call with the GIL held.
  void RaiseFromCallback() {
    if (raised) throw std::move(*raised);
  }
};

std::string Report(const std::string& database_path, const std::string& study,
                   const std::map<std::string, double, std::less<>>& thresholds,
                   const std::string& out, const py::object& progress) {
  const StudyReportRequest request{database_path, study, thresholds, out, "out"};
  PythonLog python(progress);
  std::string page;
  {
    py::gil_scoped_release release;
    page = WriteStudyReport(request, python.log).string();
  }
  python.RaiseFromCallback();
  return page;
}

// `value` within its bounds (strict or not), else InputError naming it as Python spells it.
void RequireIn(const char* name, double value, double low, bool low_strict, double high,
               bool high_strict) {
  const bool above_low = low_strict ? value > low : value >= low;
  const bool below_high = high_strict ? value < high : value <= high;
  if (!(above_low && below_high)) {
    throw InputError(fmt::format("{}: {:g} is outside {}{:g}, {:g}{}", name, value,
                                 low_strict ? "(" : "[", low, high, high_strict ? ")" : "]"));
  }
}

py::dict CheckDict(const AdviceCheckLadder& ladder, const AdviceCheckRequest& request) {
  py::dict d;
  d["dt_ratio"] = ladder.advice.dt_ratio;
  py::dict truncations;
  for (const BeamAdvice& b : ladder.advice.beams) truncations[py::str(b.name)] = b.r_ftrunc;
  d["r_ftrunc"] = truncations;
  d["warnings"] = ladder.advice.warnings;
  if (!ladder.check) return d;
  const AdviceCheck& check = *ladder.check;
  d["verdict"] = AdviceVerdict(check, request.sizing.quantile);
  d["table"] = TableDict(AdviceCheckTable(check));
  d["factors"] = check.factors;
  d["cpu_s_per_member"] = check.cpu_s_per_member;
  d["converged"] = check.converged.has_value();
  d["undecided"] = check.undecided;
  return d;
}

// The options left None take the command line's defaults; those given are checked as its flags
// are, by the same bounds.
struct CheckAdviceArguments {
  std::optional<int> members, jobs, max_rungs;
  std::optional<double> window_s, quantile, tolerance;
};

AdviceCheckRequest CheckedRequest(AdviceCheckRequest request, const CheckAdviceArguments& a) {
  if (a.members) RequireIn("members", *a.members, 1.0, false, kMaxLadderMembers, false);
  if (a.window_s) RequireIn("window_s", *a.window_s, 0.0, true, kMaxLadderWindowS, false);
  if (a.jobs) RequireIn("jobs", *a.jobs, 1.0, false, 1024.0, false);
  if (a.max_rungs)
    RequireIn("max_rungs", *a.max_rungs, kFirstLadderRungs, false, kMaxLadderRungs, false);
  if (a.quantile) RequireIn("quantile", *a.quantile, 0.0, true, 1.0, true);
  if (a.tolerance) RequireIn("tolerance", *a.tolerance, 0.0, false, 1.0, false);
  request.members = a.members.value_or(request.members);
  request.window_s = a.window_s.value_or(request.window_s);
  request.jobs = a.jobs.value_or(request.jobs);
  request.max_rungs = a.max_rungs.value_or(request.max_rungs);
  request.sizing.quantile = a.quantile.value_or(request.sizing.quantile);
  request.sizing.tolerance = a.tolerance.value_or(request.sizing.tolerance);
  request.states_name = "states";
  return request;
}

py::dict CheckAdvice(AdviceCheckRequest request, const py::object& progress) {
  PythonLog python(progress);
  request.progress_lines = python.lines;
  AdviceCheckLadder ladder;
  int stop_signal = 0;  // The run's, or one that came after its last check.
  {
    py::gil_scoped_release release;
    const StopHandlersDuringRun stop_handlers;
    ladder = CheckAdviceOnMembers(request, python.log);
    if (ladder.check && !request.record.empty()) RecordAdviceCheck(request, ladder, python.log);
    stop_signal = ladder.stop_signal != 0 ? ladder.stop_signal : StopSignal();
  }
  python.RaiseFromCallback();
  RaiseStop(stop_signal);
  if (ladder.stop_signal != 0) {
    ThrowInterrupted(fmt::format(
        "check_advice: stopped by {}: {} of the {} members to compute are stored; call "
        "check_advice again to resume",
        SignalName(ladder.stop_signal), ladder.members_computed, ladder.members_to_compute));
  }
  return CheckDict(ladder, request);
}

}  // namespace

void BindWorkflows(py::module_& m) {
  m.def("report", &Report, py::arg("db"), py::arg("study"), py::arg("thresholds"), py::arg("out"),
        py::arg("progress"));
  m.def(
      "check_advice",
      [](const std::string& study, const std::string& db, std::optional<std::string> criteria,
         std::optional<int> members, std::optional<double> window_s,
         std::vector<std::string> states, std::optional<int> jobs, std::optional<double> quantile,
         std::optional<double> tolerance, std::optional<int> max_rungs, const std::string& record,
         const std::string& write_study, const py::object& progress) {
        AdviceCheckRequest request;
        request.study_file = study;
        request.database_path = db;
        if (criteria) request.criteria_file = *criteria;
        request.states = std::move(states);
        request.record = record;
        request.write_study = write_study;
        return CheckAdvice(CheckedRequest(std::move(request), {members, jobs, max_rungs, window_s,
                                                               quantile, tolerance}),
                           progress);
      },
      py::arg("study"), py::arg("db"), py::arg("criteria"), py::arg("members"), py::arg("window_s"),
      py::arg("states"), py::arg("jobs"), py::arg("quantile"), py::arg("tolerance"),
      py::arg("max_rungs"), py::arg("record"), py::arg("write_study"), py::arg("progress"));
  m.attr("SCENE_CRITERIA") = kSceneCriteria;
}

}  // namespace shockmap::python
