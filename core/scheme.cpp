#include "core/scheme.h"

namespace shockmap {

std::string ToString(Scheme s) {
  return s == Scheme::kExplicitModal ? "explicit-modal" : "implicit-full";
}

std::optional<Scheme> SchemeFromString(std::string_view s) {
  for (auto v : {Scheme::kExplicitModal, Scheme::kImplicitFull}) {
    if (ToString(v) == s) return v;
  }
  return std::nullopt;
}

NewmarkParameters NewmarkParametersOf(Scheme s) {
  return s == Scheme::kExplicitModal ? NewmarkParameters::CentralDifference()
                                     : NewmarkParameters::AverageAcceleration();
}

}  // namespace shockmap
