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
// stored), M positive semi-definite (singular for bricks with reduced integration); row i of K and
// M is dofs[i]. A node may carry several copies of a component: CalculiX expands beam and shell
// elements into bricks whose nodes it names after the node they were made from
// (docs/structures.md). The node's motion along the component is then the mean of its copies, and a
// force on it is shared equally among them.
struct FeStructure {
  std::string name;
  Eigen::SparseMatrix<double> stiffness;  // N/m, N, N m
  Eigen::SparseMatrix<double> mass;       // kg, kg m, kg m^2
  std::vector<StructureDof> dofs;
  std::map<int, Eigen::Vector3d> node_coordinates_m;

  int Size() const { return static_cast<int>(dofs.size()); }
  // The row of (node, component), or nullopt if that DOF is not free (the first of its copies
  // when it has several: see DofRows, NodeDirection).
  std::optional<int> DofIndex(int node, DofComponent component) const;
  // Every row of (node, component): none when it is not free, several for copies.
  std::vector<int> DofRows(int node, DofComponent component) const;
  // The vector w with w^T u = the node's displacement along the unit vector `n` (3D, over its
  // translations: the mean of each component's copies), which is also the force vector of a unit
  // force on the node along n. Zero when the node has no free translation along n.
  Eigen::VectorXd NodeDirection(int node, const Eigen::Vector3d& n) const;
};

}  // namespace shockmap
