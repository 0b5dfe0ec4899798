#pragma once
// Readers of an FE structure's files (docs/structures.md): Matrix Market matrices with CSV tables
// of its DOFs and nodes, and CalculiX's matrix storage (*FREQUENCY, SOLVER=MATRIXSTORAGE).
// Every refusal is an InputError naming the file, the entry (line, row, column), the value and
// what is allowed: non-symmetric matrices, a mass that is not positive definite, a DOF without
// any entry or a node without coordinates, sizes that do not match, values that are not finite,
// malformed lines.

#include <string>

#include "core/fe_structure.h"

namespace shockmap {

// K and M as Matrix Market "coordinate real" files ("general" with both triangles, or
// "symmetric" with one), the DOF table as CSV "node,component" (component one of ux uy uz rx
// ry rz; row i of the table is row i of K and M) and the nodes as CSV "node,x,y,z" (m).
FeStructure ReadMatrixMarketStructure(const std::string& stiffness_path,
                                      const std::string& mass_path, const std::string& dofs_path,
                                      const std::string& nodes_path);

// CalculiX's matrix storage of job `stem` (stem.sti, stem.mas: the upper triangle as 1-based
// "row column value" lines; stem.dof: "node.direction" per row, directions 1-3 translations and
// 4-6 rotations) with the nodes' coordinates from the *NODE blocks of the deck `deck_path`.
FeStructure ReadCalculixMatrixStorage(const std::string& stem, const std::string& deck_path);

// Writes `s` as ReadMatrixMarketStructure reads it: stiffness.mtx, mass.mtx ("symmetric", the
// lower triangle, 17 significant digits), dofs.csv and nodes.csv in `dir`, each written in full
// to a temporary file first and then renamed (nothing half-written).
void WriteMatrixMarketStructure(const FeStructure& s, const std::string& dir);

}  // namespace shockmap
