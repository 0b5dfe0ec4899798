#pragma once
// What changed between the lifelong settings a study was stored with and those of its file now.
// Each kind of study declares its lifelong settings as one JSON object (SettingsKey,
// SceneSettingsKey, EnsembleSettingsKey): the problem, scoring and reference settings its stored
// scores depend on, named by their keys. A study run refuses a change of any of them under the
// same name, naming the first one found.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace shockmap {

struct SettingChange {
  std::string key;     // Dotted key path, e.g. "scoring.window_s".
  std::string stored;  // The value stored with the study, as JSON text ("absent" when none).
  std::string given;   // The value the file gives now, likewise.
};

// The first leaf (in the key order of `given`, then keys only `stored` has) whose value differs
// between two settings objects; nullopt when they are equal. `prefix` is prepended to the key.
std::optional<SettingChange> FirstChangedSetting(const nlohmann::json& stored,
                                                 const nlohmann::json& given,
                                                 const std::string& prefix = "");

}  // namespace shockmap
