#pragma once
// Entries of a sparse symmetric matrix as read from a file, each with its line, turned into the
// matrix with the checks every structure file gets (docs/structures.md, "What the readers
// refuse"): no entry given twice, the two triangles equal, no DOF row without an entry.

#include <Eigen/SparseCore>
#include <functional>
#include <string>
#include <vector>

namespace shockmap {

struct SparseEntry {
  int row = 0;  // 0-based
  int column = 0;
  double value = 0.0;
  long line = 0;
};

// Two entries whose values differ by more than this share of the larger are not symmetric.
inline constexpr double kSymmetryTolerance = 1e-9;

// The n x n symmetric matrix of `entries`, of which `one_triangle` files hold one triangle
// (mirrored here) and the others both (checked equal within kSymmetryTolerance, then averaged).
// `row_label(i)` names row i in messages (e.g. "row 12 (node 4 uy)"). Throws InputError naming
// `file`, the line(s), the row and column and the values.
Eigen::SparseMatrix<double> SymmetricMatrix(std::vector<SparseEntry> entries, int n,
                                            bool one_triangle, const std::string& file,
                                            const std::function<std::string(int)>& row_label);

}  // namespace shockmap
