#pragma once
// One sparse LDL^T factorization of K - sigma M of an FE structure (docs/structures.md): its
// inertia, the number of modes below sigma, and its weakest pivot, which names the DOF a
// structure's supports leave free.

#include <utility>

#include "core/fe_structure.h"
#include "core/sparse_cholesky.h"

namespace shockmap {

class ShiftedFactorization {
 public:
  // Factorizes K - sigma_rad2_s2 M (CHOLMOD's simplicial L D L^T, no pivoting).
  ShiftedFactorization(const FeStructure& s, double sigma_rad2_s2);

  // The number of negative pivots: by Sylvester's law of inertia, the number of eigenvalues
  // omega^2 of K phi = omega^2 M phi below sigma (K positive definite, M positive semi-definite).
  int NegativePivots() const;
  // The row whose pivot is smallest relative to its diagonal entry of K - sigma M (a DOF the
  // supports leave free to move rigidly when K itself is factorized), and that ratio; the row
  // that stopped the factorization and 0 when a pivot was exactly zero.
  std::pair<int, double> WeakestPivot() const;

 private:
  Eigen::VectorXd diagonal_;  // of K - sigma M, in the matrix's own row order
  SparseCholesky factor_;
};

}  // namespace shockmap
