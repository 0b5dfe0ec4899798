#pragma once
// A scene study file (JSON, in studies/): a scene file, a sweep of any of its numeric parameters
// (by path, e.g. "solver.r_ftrunc" or "bundle.wire.stiffness_n_per_m"), the settings of the
// reference each point is scored against (the same scene, refined), and the scoring.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene.h"
#include "formats/scene_file.h"
#include "validation/scores.h"

namespace shockmap {

// Numeric parameters set in a scene, by path, sorted by path.
using SceneParameters = std::vector<std::pair<std::string, double>>;

struct SceneScoring {
  std::string displacement;    // Name of one of the scene's outputs.displacements: Err.
  std::string zone;            // Name of one of its zones: SRf of its first shock.
  double window_s = 0.0;       // Every run's end time (default: the scene's).
  double rest_duration_s = 0;  // Shock grouping (required).
  // Validity thresholds by score name, read as each score's key (err_max, srf_min, ...).
  std::map<std::string, double, std::less<>> thresholds = DefaultThresholds();
};

struct SceneStudySpec {
  std::string file, name, description;
  // Resolved against the study file's folder; it may lie anywhere, as the study's author chose
  // (the scene's own data files are confined by `access`).
  std::string scene_file;
  nlohmann::json scene;  // The scene file's JSON.
  SceneFileAccess access;
  SceneParameters reference;
  SceneScoring scoring;
  std::vector<SceneParameters> points;  // The sweep's full product.
  std::string spec_json;                // The study with the scene embedded, as stored.
};

// Parses the study, reads its scene and checks every point's scene (so that a bad sweep value
// is refused before anything runs). Throws InputError naming the file, the key path or the
// point, the value and what is allowed. The scene's data files are read as `access` allows.
SceneStudySpec ParseSceneStudySpec(const nlohmann::json& json, const std::string& file,
                                   const SceneFileAccess& access = {});

// A scene study as the database stores it (spec_json: the study with its scene embedded as
// "scene_json"), parsed as ParseSceneStudySpec parses the file; `label` names it in messages.
// The scene's own data files, if any, are read relative to the working directory.
SceneStudySpec ParseStoredSceneStudySpec(const nlohmann::json& stored, const std::string& label);

// The scene of a point, set up for scoring: the parameters applied, the end time at the window,
// and only the scored displacement and zone recorded. Throws InputError.
Scene ScoredScene(const SceneStudySpec& spec, const SceneParameters& parameters);

// A point's parameters with the reference's applied over them.
SceneParameters ReferenceParameters(const SceneStudySpec& spec, const SceneParameters& point);

// {"path": value, ...}
std::string ParametersJson(const SceneParameters& parameters);
// Identifies a reference across studies: the scene, the scoring and the reference's parameters
// (the object ParametersJson writes).
std::string SceneReferenceKey(const SceneStudySpec& spec, const nlohmann::json& parameters);
// What a study keeps for life: its stored scores depend on it.
std::string SceneSettingsKey(const SceneStudySpec& spec);

}  // namespace shockmap
