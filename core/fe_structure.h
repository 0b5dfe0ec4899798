#pragma once
// A structure from an FE code (docs/structures.md): its stiffness and mass over its free degrees
// of freedom, the table naming each of them, and its nodes' coordinates.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shockmap {

enum class DofComponent { kUx, kUy, kUz, kRx, kRy, kRz };

// "ux", "uy", "uz", "rx", "ry", "rz".
std::string_view DofComponentName(DofComponent component);
// The component of that name, or nullopt.
std::optional<DofComponent> DofComponentNamed(std::string_view name);

struct StructureDof {
  int node = 0;
  DofComponent component = DofComponent::kUx;
};

// K and M over the structure's free DOFs (supports eliminated), symmetric (both triangles
// stored), M positive definite; row i of K and M is dofs[i].
struct FeStructure {
  std::string name;
  Eigen::SparseMatrix<double> stiffness;  // N/m, N, N m
  Eigen::SparseMatrix<double> mass;       // kg, kg m, kg m^2
  std::vector<StructureDof> dofs;
  std::map<int, Eigen::Vector3d> node_coordinates_m;

  int Size() const { return static_cast<int>(dofs.size()); }
  // The row of (node, component), or nullopt if that DOF is not free.
  std::optional<int> DofIndex(int node, DofComponent component) const;
};

}  // namespace shockmap
