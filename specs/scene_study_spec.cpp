#include "specs/scene_study_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/input_error.h"
#include "formats/json_reader.h"
#include "formats/parameter_path.h"
#include "formats/scene_file.h"
#include "specs/study_spec.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

Json Applied(const Json& scene, const SceneParameters& parameters) {
  Json variant = scene;
  for (const auto& [path, value] : parameters) variant[*ParameterPointer(path)] = value;
  return variant;
}

SceneParameters ParseParameters(const Json& value, const Json& scene, const std::string& file,
                                const std::string& where) {
  JsonObjectReader r(value, file, where);
  SceneParameters parameters;
  for (const auto& [path, v] : value.items()) {
    NumericParameter(scene, path, file, r.PathOf(path));
    parameters.emplace_back(path, NumberAt(*r.Get(path), file, r.PathOf(path)));
  }
  r.Finish();
  return parameters;
}

using Axes = std::vector<std::pair<std::string, std::vector<double>>>;

// The sweep's axes, by parameter path; refused beyond kMaxStudyPoints points in all.
Axes ParseSweep(JsonObjectReader& r, const Json& scene, const std::string& file) {
  const Json* sweep = r.Get("sweep");
  if (sweep == nullptr || !sweep->is_object() || sweep->empty()) {
    r.Fail("sweep", "expected {\"parameter.path\": [values...], ...} with at least one parameter");
  }
  Axes axes;
  double count = 1.0;
  for (const auto& [path, values] : sweep->items()) {
    const std::string where = r.PathOf("sweep") + "." + path;
    NumericParameter(scene, path, file, where);
    if (!values.is_array() || values.empty())
      FailAt(file, where, "expected a non-empty list of numbers, got " + Shown(values));
    std::vector<double> axis;
    for (std::size_t i = 0; i < values.size(); ++i)
      axis.push_back(NumberAt(values[i], file, where + "[" + std::to_string(i) + "]"));
    count *= static_cast<double>(axis.size());
    axes.emplace_back(path, std::move(axis));
  }
  if (count > static_cast<double>(kMaxStudyPoints)) {
    r.Fail("sweep", "the sweep has " + Shown(Json(count)) + " points: at most " +
                        std::to_string(kMaxStudyPoints) + " are allowed");
  }
  return axes;
}

SceneScoring ParseScoring(JsonObjectReader& r, const std::string& file, const Scene& base) {
  const Json* scoring = r.Get("scoring");
  if (scoring == nullptr) r.Fail("scoring", "required object is missing");
  JsonObjectReader s(*scoring, file, "scoring");
  SceneScoring sc;
  sc.displacement = s.RequiredString("displacement");
  sc.zone = s.RequiredString("zone");
  sc.window_s = s.Number("window_s", base.solver.end_time_s);
  if (!(sc.window_s > 0.0) || sc.window_s > 1e4) s.Fail("window_s", "must lie in (0, 1e4] s");
  sc.rest_duration_s = s.RequiredNumber("rest_duration_s");
  if (!(sc.rest_duration_s > 0.0)) s.Fail("rest_duration_s", "must be > 0");
  ReadThresholds(s, sc.thresholds);
  s.Finish();
  return sc;
}

// The full product of the axes, each point sorted by path, without repeats.
std::vector<SceneParameters> FullProduct(const Axes& axes) {
  std::vector<SceneParameters> points = {{}};
  for (const auto& [path, axis] : axes) {
    std::vector<SceneParameters> next;
    for (const auto& p : points) {
      for (double v : axis) {
        SceneParameters q = p;
        q.emplace_back(path, v);
        next.push_back(std::move(q));
      }
    }
    points = std::move(next);
  }
  for (auto& p : points) std::sort(p.begin(), p.end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

// Every point's scene and its reference's must be valid scenes, with the scored outputs.
void CheckEveryPointsScene(const SceneStudySpec& spec) {
  ScoredScene(spec, {});  // The scored output and zone exist.
  for (const auto& p : spec.points) {
    for (const SceneParameters& q : {p, ReferenceParameters(spec, p)}) {
      try {
        ScoredScene(spec, q);
      } catch (const InputError& e) {
        throw InputError(spec.file + ": sweep point " + ParametersJson(q) + ": " + e.what());
      }
    }
  }
}

// ParseSceneStudySpec with the scene's JSON given: read from `scene_file`, or as stored.
SceneStudySpec ParseWithScene(const Json& json, const std::string& file, Json scene,
                              const std::string& scene_file, const SceneFileAccess& access) {
  SceneStudySpec spec;
  spec.file = file;
  spec.access = access;
  JsonObjectReader r(json, file, "");
  std::tie(spec.name, spec.description) = ReadStudyTitle(r, "scene_sweep");
  r.RequiredString("scene");
  spec.scene_file = scene_file;
  spec.scene = std::move(scene);
  const Scene base = ParseScene(spec.scene, spec.scene_file, access);
  const Axes axes = ParseSweep(r, spec.scene, file);
  if (const Json* reference = r.Get("reference")) {
    spec.reference = ParseParameters(*reference, spec.scene, file, "reference");
  }
  if (spec.reference.empty()) {
    r.Fail("reference",
           "give the refined settings each point is scored against, e.g. {\"solver.r_ftrunc\": "
           "1000, \"solver.dt.factor\": 0.05} (the paths must be set in the scene)");
  }
  spec.scoring = ParseScoring(r, file, base);
  r.Finish();
  spec.points = FullProduct(axes);
  std::sort(spec.reference.begin(), spec.reference.end());
  CheckEveryPointsScene(spec);
  Json stored = json;
  stored["scene_json"] = spec.scene;
  // Where the scene's own files (structures' matrices, acceleration tables) are found from any
  // working directory: "scene" is relative to the study file as it was given.
  if (!spec.scene_file.empty()) {
    stored["scene_file"] = std::filesystem::absolute(spec.scene_file).lexically_normal().string();
  }
  stored["settings"] = Json::parse(SceneSettingsKey(spec));
  spec.spec_json = stored.dump();
  return spec;
}

}  // namespace

SceneStudySpec ParseSceneStudySpec(const Json& json, const std::string& file,
                                   const SceneFileAccess& access) {
  std::string scene_path;
  {
    JsonObjectReader r(json, file, "");
    ReadStudyTitle(r, "scene_sweep");
    scene_path = r.RequiredString("scene");
  }
  const std::string scene_file =
      (std::filesystem::path(file).parent_path() / scene_path).lexically_normal();
  return ParseWithScene(json, file, ReadJsonFile(scene_file), scene_file, access);
}

SceneStudySpec ParseStoredSceneStudySpec(const Json& stored, const std::string& label) {
  Json json = stored;
  const Json scene = json.contains("scene_json") ? json["scene_json"] : Json();
  json.erase("scene_json");
  json.erase("settings");
  // Studies stored before "scene_file" name their scene relative to the study file only.
  const char* key = json.contains("scene_file") ? "scene_file" : "scene";
  const std::string scene_file =
      json.contains(key) && json[key].is_string() ? json[key].get<std::string>() : std::string();
  json.erase("scene_file");
  return ParseWithScene(json, label, scene, scene_file, {});
}

Scene ScoredScene(const SceneStudySpec& spec, const SceneParameters& parameters) {
  Scene scene = ParseScene(Applied(spec.scene, parameters), spec.scene_file, spec.access);
  const auto point =
      std::find_if(scene.outputs.displacements.begin(), scene.outputs.displacements.end(),
                   [&](const ObservedPoint& o) { return o.name == spec.scoring.displacement; });
  if (point == scene.outputs.displacements.end()) {
    throw InputError(spec.file + ": scoring.displacement: the scene has no output named \"" +
                     spec.scoring.displacement + "\" in outputs.displacements");
  }
  const auto zone = std::find_if(scene.zones.begin(), scene.zones.end(),
                                 [&](const SceneZone& z) { return z.name == spec.scoring.zone; });
  if (zone == scene.zones.end()) {
    throw InputError(spec.file + ": scoring.zone: the scene has no zone named \"" +
                     spec.scoring.zone + "\"");
  }
  SceneOutputs outputs;
  outputs.displacements = {*point};
  outputs.contact_forces = true;
  outputs.contact_force_zones = {static_cast<int>(zone - scene.zones.begin())};
  outputs.max_contact_force = true;
  outputs.shocks = true;
  outputs.rest_duration_s = spec.scoring.rest_duration_s;
  scene.outputs = outputs;
  scene.solver.end_time_s = spec.scoring.window_s;
  return scene;
}

SceneParameters ReferenceParameters(const SceneStudySpec& spec, const SceneParameters& point) {
  std::map<std::string, double> merged(point.begin(), point.end());
  for (const auto& [path, value] : spec.reference) merged[path] = value;
  return {merged.begin(), merged.end()};
}

std::string ParametersJson(const SceneParameters& parameters) {
  Json json = Json::object();
  for (const auto& [path, value] : parameters) json[path] = value;
  return json.dump();
}

std::string SceneReferenceKey(const SceneStudySpec& spec, const Json& parameters) {
  return Json{{"scene", spec.scene},
              {"parameters", parameters},
              {"displacement", spec.scoring.displacement},
              {"zone", spec.scoring.zone},
              {"window_s", spec.scoring.window_s}}
      .dump();
}

std::string SceneSettingsKey(const SceneStudySpec& spec) {
  return Json{{"scene", spec.scene},
              {"reference", Json::parse(ParametersJson(spec.reference))},
              {"displacement", spec.scoring.displacement},
              {"zone", spec.scoring.zone},
              {"window_s", spec.scoring.window_s},
              {"rest_duration_s", spec.scoring.rest_duration_s}}
      .dump();
}

}  // namespace shockmap
