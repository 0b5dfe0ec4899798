#include "specs/setting_change.h"

#include <fmt/format.h>

#include "formats/json_reader.h"

namespace shockmap {
namespace {

// A number in its shortest digits (3000, not 3000.0), anything else as the file shows it.
std::string Value(const nlohmann::json& value) {
  return value.is_number_float() ? fmt::format("{}", value.get<double>()) : Shown(value);
}

std::string Joined(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

}  // namespace

std::optional<SettingChange> FirstChangedSetting(const nlohmann::json& stored,
                                                 const nlohmann::json& given,
                                                 const std::string& prefix) {
  if (stored == given) return std::nullopt;
  if (!stored.is_object() || !given.is_object()) {
    return SettingChange{prefix, Value(stored), Value(given)};
  }
  auto find = [](const nlohmann::json& object, const std::string& key) -> const nlohmann::json* {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  };
  for (const auto& [key, value] : given.items()) {
    const nlohmann::json* was = find(stored, key);
    if (was == nullptr) return SettingChange{Joined(prefix, key), "absent", Value(value)};
    if (auto change = FirstChangedSetting(*was, value, Joined(prefix, key))) return change;
  }
  for (const auto& [key, value] : stored.items()) {
    if (find(given, key) == nullptr) {
      return SettingChange{Joined(prefix, key), Value(value), "absent"};
    }
  }
  return std::nullopt;  // Unreachable: unequal objects differ in some key.
}

}  // namespace shockmap
