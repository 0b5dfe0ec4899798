#pragma once
// Scene files (JSON, in scenes/): beams, contact zones, effects, solver, outputs, and bundle
// generators that expand a row or a hexagonal bundle of pins in its wrapper into beams and zones.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/scene.h"

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

}  // namespace shockmap
