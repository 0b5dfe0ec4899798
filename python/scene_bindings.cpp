// Scene and simulate(): a scene file read with the file reader's checks and messages, its
// parameters set by path as study files set them, and one simulation with its outputs.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "compare/scene_run.h"
#include "engine/progress_reporter.h"
#include "engine/stop_request.h"
#include "formats/json_reader.h"
#include "formats/parameter_path.h"
#include "formats/scene_file.h"
#include "formats/scene_outputs.h"
#include "python/bindings.h"
#include "python/interrupted_run.h"
#include "python/signal_arrays.h"

namespace shockmap::python {
namespace {

// A scene as its JSON (what set() edits) and as validated (what runs); `path` names it in
// messages and locates its data files.
struct SceneHandle {
  nlohmann::json json;
  std::string path;
  Scene scene;

  static SceneHandle Parse(nlohmann::json json, const std::string& path) {
    Scene scene = ParseScene(json, path);
    return {std::move(json), path, std::move(scene)};
  }

  // The parameter `key` ("bundle.wire.stiffness_n_per_m", "zones[0].gap_m") set to `value`
  // (JSON text of a number or a boolean, the type the scene holds there); the scene is checked
  // again and left as it was when refused.
  void Set(const std::string& key, const std::string& value_text) {
    const nlohmann::json value = ParseJsonText(value_text, path + ": set(" + key + ")");
    const auto where = SceneParameter(json, key, value, path, "set(\"" + key + "\")");
    nlohmann::json changed = json;
    changed[where] = value;
    *this = Parse(std::move(changed), path);
  }
};

// A run shared by the Python object and every array taken from it.
struct SceneRunHandle {
  std::shared_ptr<const SceneRun> run;
  std::string summary_json;  // As `shockmap simulate --json` prints it.
  std::vector<std::string> displacement_names;
  std::vector<std::string> zone_names;
};

// The recorded histories, named as the columns of the CSV files `simulate --out` writes
// (formats/scene_outputs.h), with "t_s" their common sample times.
py::dict Histories(const SceneRunHandle& h) {
  const TransientResult& r = h.run->result;
  py::dict d;
  const UniformSignal* first = !r.displacement_m.empty()            ? &r.displacement_m[0]
                               : !r.contact_force_n.empty()         ? &r.contact_force_n[0]
                               : !r.energy.kinetic_j.values.empty() ? &r.energy.kinetic_j
                                                                    : nullptr;
  if (first == nullptr) return d;
  d["t_s"] = TimesOf(*first);
  for (std::size_t p = 0; p < r.displacement_m.size(); ++p) {
    d[py::str(h.displacement_names[p] + "_m")] = ArrayOver(h.run, r.displacement_m[p].values);
    if (p < r.velocity_m_s.size()) {
      d[py::str(h.displacement_names[p] + "_velocity_m_s")] =
          ArrayOver(h.run, r.velocity_m_s[p].values);
    }
  }
  for (std::size_t z = 0; z < r.contact_force_n.size(); ++z) {
    d[py::str(h.zone_names[z] + "_n")] = ArrayOver(h.run, r.contact_force_n[z].values);
  }
  const EnergyHistory& e = r.energy;
  for (const auto& [name, signal] :
       {std::pair{"kinetic_j", &e.kinetic_j}, std::pair{"strain_j", &e.strain_j},
        std::pair{"contact_j", &e.contact_j}, std::pair{"dissipated_j", &e.dissipated_j},
        std::pair{"external_work_j", &e.external_work_j}}) {
    if (!signal->values.empty()) d[name] = ArrayOver(h.run, signal->values);
  }
  return d;
}

// A run stopped by SIGINT, SIGTERM or SIGHUP between two progress reports, at `t_s` simulated.
struct RunStopped {
  int signal;
  double t_s;
};

// After the interpreter's handler for the signal that stopped `scene` at `stopped.t_s` has
// returned: the run has no result to give.
[[noreturn]] void ThrowStopped(const Scene& scene, const RunStopped& stopped) {
  ThrowInterrupted(fmt::format(
      "simulate: scene \"{}\" stopped by {} at {:.4g} s of {:.4g} s simulated; a stopped "
      "simulation has no result",
      scene.name, SignalName(stopped.signal), stopped.t_s, scene.solver.end_time_s));
}

SceneRunHandle Simulate(const SceneHandle& handle, bool progress) {
  SceneRunHandle out;
  for (const auto& p : handle.scene.outputs.displacements) out.displacement_names.push_back(p.name);
  std::optional<RunStopped> stopped;
  int late_signal = 0;  // One that came after the run's last progress check.
  {
    py::gil_scoped_release release;
    const StopHandlersDuringRun stop_handlers;
    ProgressReporter reporter("simulate " + handle.scene.name, "s simulated",
                              handle.scene.solver.end_time_s, stderr, progress);
    try {
      auto run = std::make_shared<SceneRun>(RunScene(handle.scene, [&](double t_s) {
        if (const int signal = StopSignal(); signal != 0) throw RunStopped{signal, t_s};
        reporter.Update(t_s);
      }));
      reporter.Finish(run->result.summary.dt_used_s *
                      static_cast<double>(run->result.summary.steps_taken));
      out.run = std::move(run);
      late_signal = StopSignal();
    } catch (const InputError& e) {
      throw InputError(handle.path + ": " + e.what());
    } catch (const RunStopped& s) {
      stopped = s;
    }
  }
  if (stopped) {
    RaiseStop(stopped->signal);
    ThrowStopped(handle.scene, *stopped);
  }
  RaiseStop(late_signal);
  for (int z : out.run->recorded_zones) out.zone_names.push_back(handle.scene.zones[z].name);
  out.summary_json = SceneRunToJson(handle.scene, *out.run).dump();
  return out;
}

}  // namespace

void BindScene(py::module_& m) {
  py::class_<SceneHandle>(m, "Scene", "A scene: beams, contact zones, effects, solver, outputs")
      .def_static(
          "load",
          [](const std::string& path) { return SceneHandle::Parse(ReadJsonFile(path), path); },
          py::arg("path"))
      .def_static(
          "from_json_text",
          [](const std::string& text, const std::string& path) {
            return SceneHandle::Parse(ParseJsonText(text, path), path);
          },
          py::arg("text"), py::arg("path"))
      .def("set", &SceneHandle::Set, py::arg("key"), py::arg("value_json"))
      .def("json_text", [](const SceneHandle& h) { return h.json.dump(); })
      .def_property_readonly("name", [](const SceneHandle& h) { return h.scene.name; })
      .def_property_readonly("path", [](const SceneHandle& h) { return h.path; });
  py::class_<SceneRunHandle>(m, "SceneRun", "One simulation of a scene")
      .def_property_readonly("summary_json", [](const SceneRunHandle& h) { return h.summary_json; })
      .def_property_readonly("histories", &Histories)
      .def_property_readonly("modes_per_beam",
                             [](const SceneRunHandle& h) { return h.run->modes_per_beam; });
  m.def("simulate", &Simulate, py::arg("scene"), py::arg("progress"));
}

}  // namespace shockmap::python
