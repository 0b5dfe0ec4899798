#pragma once
// Boundary conditions at a beam end.

#include <optional>
#include <string>
#include <string_view>

namespace shockmap {

enum class EndCondition { kClamped, kPinned, kFree };

std::string ToString(EndCondition c);
std::optional<EndCondition> EndConditionFromString(std::string_view s);

}  // namespace shockmap
