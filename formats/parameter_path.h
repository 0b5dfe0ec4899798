#pragma once
// Parameters of a scene file named by path: keys joined by dots, with [i] for list items
// ("solver.r_ftrunc", "bundle.wire.stiffness_n_per_m", "zones[0].gap_m"). Study files sweep,
// draw or set them.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace shockmap {

// The path as a JSON pointer; nullopt when malformed.
std::optional<nlohmann::json::json_pointer> ParameterPointer(const std::string& path);

// Where the numeric parameter `path` sits in the scene; InputError (naming `file` and `where`)
// unless the scene holds a number there, or when the path is one a study sets itself
// (solver.end_time_s, the window; outputs.*, what it records).
nlohmann::json::json_pointer NumericParameter(const nlohmann::json& scene, const std::string& path,
                                              const std::string& file, const std::string& where);

// Where the parameter `path` sits in the scene when it holds a value of the same JSON type as
// `value` (a number, or true/false), any path (a scene set on its own, as the Python module's
// Scene.set does); InputError naming `file` and `where` otherwise.
nlohmann::json::json_pointer SceneParameter(const nlohmann::json& scene, const std::string& path,
                                            const nlohmann::json& value, const std::string& file,
                                            const std::string& where);

// SceneParameter, refused also where a study sets the value itself (as NumericParameter).
nlohmann::json::json_pointer SameTypeParameter(const nlohmann::json& scene, const std::string& path,
                                               const nlohmann::json& value, const std::string& file,
                                               const std::string& where);

}  // namespace shockmap
