#include "core/fe_structure.h"

#include <array>

namespace shockmap {
namespace {

constexpr std::array<std::string_view, 6> kComponentNames = {"ux", "uy", "uz", "rx", "ry", "rz"};

}  // namespace

std::string_view DofComponentName(DofComponent component) {
  return kComponentNames[static_cast<int>(component)];
}

std::optional<DofComponent> DofComponentNamed(std::string_view name) {
  for (int c = 0; c < static_cast<int>(kComponentNames.size()); ++c) {
    if (kComponentNames[c] == name) return static_cast<DofComponent>(c);
  }
  return std::nullopt;
}

std::optional<int> FeStructure::DofIndex(int node, DofComponent component) const {
  for (int i = 0; i < Size(); ++i) {
    if (dofs[i].node == node && dofs[i].component == component) return i;
  }
  return std::nullopt;
}

}  // namespace shockmap
