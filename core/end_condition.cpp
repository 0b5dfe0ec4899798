#include "core/end_condition.h"

namespace shockmap {

std::string ToString(EndCondition c) {
  switch (c) {
    case EndCondition::kClamped:
      return "clamped";
    case EndCondition::kPinned:
      return "pinned";
    case EndCondition::kFree:
      return "free";
  }
  return "unknown";
}

std::optional<EndCondition> EndConditionFromString(std::string_view s) {
  for (auto c : {EndCondition::kClamped, EndCondition::kPinned, EndCondition::kFree}) {
    if (ToString(c) == s) return c;
  }
  return std::nullopt;
}

}  // namespace shockmap
