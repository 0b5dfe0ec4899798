#pragma once
// The numerical schemes a comparison can run.

#include <optional>
#include <string>
#include <string_view>

#include "core/newmark.h"

namespace shockmap {

enum class Scheme {
  kExplicitModal,  // The paper's method: truncated modal basis, central differences (§2.3).
  kImplicitFull,   // The comparison: full FE model, average acceleration, implicit contact.
};

std::string ToString(Scheme s);
std::optional<Scheme> SchemeFromString(std::string_view s);
NewmarkParameters NewmarkParametersOf(Scheme s);

}  // namespace shockmap
