#pragma once
// Scene files (JSON, in scenes/): beams, contact zones, effects, solver, outputs, and bundle
// generators that expand a row or a hexagonal bundle of pins in its wrapper into beams and zones.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene.h"
#include "formats/json_reader.h"

namespace shockmap {

// Where a scene's data files (effects.base_motion.csv) may be read from: its own folder and
// below, and the folders listed here (given on the command line). Names resolve against the
// scene's folder, symbolic links followed.
struct SceneFileAccess {
  std::vector<std::filesystem::path> allowed_folders;
};

// Parses and validates a scene file. Throws InputError naming the file, the JSON path, the value
// and what is allowed: unknown keys, wrong types, references to beams that do not exist, gaps or
// stiffnesses out of range, names given twice or holding control characters, a bad CSV load
// history (named with its line) or one outside the folders `access` allows.
Scene LoadScene(const std::string& path, const SceneFileAccess& access = {});

// The same for a scene already read; `path` names it in messages and locates its CSV files.
Scene ParseScene(const nlohmann::json& json, const std::string& path,
                 const SceneFileAccess& access = {});

// The counting of an impact_statistics object (docs/physics.md §6), in a scene's outputs or an
// ensemble study file: rest_duration_s in [0, 100] s (required), force_threshold_n in [0, 1e15]
// N, convention "shockmap" (the default) or "code_aster", window_s [start, end] inside the run
// [0, end_s] (the whole run by default); `end_name` names end_s in a refusal. Other keys are
// the caller's. Throws InputError naming the key, the value and what is allowed.
ImpactCounting ParseImpactCounting(JsonObjectReader& im, double end_s, const std::string& end_name);

}  // namespace shockmap
