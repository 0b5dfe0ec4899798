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

std::vector<int> FeStructure::DofRows(int node, DofComponent component) const {
  std::vector<int> rows;
  for (int i = 0; i < Size(); ++i) {
    if (dofs[i].node == node && dofs[i].component == component) rows.push_back(i);
  }
  return rows;
}

Eigen::VectorXd FeStructure::NodeDirection(int node, const Eigen::Vector3d& n) const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(Size());
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<int> rows = DofRows(node, static_cast<DofComponent>(axis));
    for (const int row : rows) w[row] = n[axis] / static_cast<double>(rows.size());
  }
  return w;
}

}  // namespace shockmap
