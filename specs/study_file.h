#pragma once
// The front door of study files: every study file declares its kind, and is parsed by that
// kind's reader.
//
//   "kind": "canonical"    the paper's problem: grids of (R_k, R_ftrunc, dt) points
//                          (specs/study_spec.h);
//   "kind": "scene_sweep"  a scene file with a sweep of its numeric parameters
//                          (specs/scene_study_spec.h);
//   "kind": "scene_ensemble"  a scene run as an ensemble of randomly drawn members, per
//                          clearance state and numerical setting (specs/ensemble_study_spec.h).
// Files written before the field existed are still read: without "kind", a file naming a
// "scene" is a scene sweep, any other a study of the paper's problem.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <variant>

#include "specs/ensemble_study_spec.h"
#include "specs/scene_study_spec.h"
#include "specs/study_spec.h"

namespace shockmap {

enum class StudyFileKind { kCanonical, kSceneSweep, kSceneEnsemble };

std::string ToString(StudyFileKind kind);
// Throws InputError naming the file and the allowed kinds.
StudyFileKind StudyFileKindFromString(std::string_view text, const std::string& file);

// The declared (or, for older files, implied) kind of a study's JSON. Throws InputError for an
// unknown kind or a JSON that is not an object.
StudyFileKind StudyKindOf(const nlohmann::json& study, const std::string& file);

using StudyFile = std::variant<StudySpec, SceneStudySpec, EnsembleStudySpec>;

// The thresholds a study file gives its scores over the registry's defaults (validation/
// scores.h): "scoring.thresholds" of the paper's problem, "scoring" of a scene sweep (keys
// err_max, srf_min, ...); the defaults for an ensemble, whose members are not scored. Throws
// InputError as the kind's reader does for a value outside a score's range.
std::map<std::string, double, std::less<>> StudyThresholds(const nlohmann::json& study,
                                                           const std::string& file);

// Reads, dispatches and parses a study file; the whole file, and every point's scene, is
// checked before anything runs. Throws InputError naming the file, the key path, the value and
// what is allowed.
// `access`: the folders a scene's data files may come from beyond its own (formats/scene_file.h).
StudyFile ReadStudyFile(const std::string& path, const SceneFileAccess& access = {});
StudyFile ParseStudyFile(const nlohmann::json& json, const std::string& file,
                         const SceneFileAccess& access = {});

}  // namespace shockmap
