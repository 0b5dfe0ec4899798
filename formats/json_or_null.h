#pragma once
// An optional value as JSON: the value, or null when there is none.

#include <nlohmann/json.hpp>
#include <optional>

namespace shockmap {

template <typename T>
nlohmann::json OrNull(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace shockmap
