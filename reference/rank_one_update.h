#pragma once
// Eigenpairs of a diagonal matrix plus a symmetric rank-one term, diag(d) + rho z z^T, by
// LAPACK's secular-equation solver (dlaed9, the rank-one step of divide and conquer): each
// eigenvalue by dlaed4, the eigenvectors from the Loewner-corrected z, so that they are
// orthonormal to rounding however close the eigenvalues lie to the poles d_i. O(n^2).

#include <Eigen/Dense>

namespace shockmap {

struct RankOneEigen {
  Eigen::VectorXd values;   // Ascending.
  Eigen::MatrixXd vectors;  // Orthonormal columns, in the order of `values`.
};

// Preconditions: d strictly ascending, every z_i != 0, rho > 0 (no deflation is needed).
// Throws std::runtime_error when a root does not converge.
RankOneEigen EigenOfRankOneUpdate(const Eigen::VectorXd& d, const Eigen::VectorXd& z, double rho);

}  // namespace shockmap
