#pragma once
// The sparse Cholesky factorization P K P^T = L L^T of an FE structure's stiffness
// (core/sparse_cholesky.h), its static solves, and the symmetric standard form of its
// flexibility L^-1 P M P^T L^-T whose eigenvalues are 1 / omega^2 (docs/structures.md).

#include "core/fe_structure.h"
#include "core/sparse_cholesky.h"

namespace shockmap {

class StiffnessCholesky {
 public:
  // Throws InputError naming the DOF of the weakest pivot when K is not positive definite.
  explicit StiffnessCholesky(const FeStructure& s);

  int Size() const { return factor_.Size(); }
  // K^-1 rhs.
  Eigen::VectorXd Solve(const Eigen::VectorXd& rhs) const;
  // y = L^-1 P M P^T L^-T x: symmetric, positive semi-definite, with the eigenvalues 1 / omega^2
  // of K phi = omega^2 M phi; its eigenvector v is the mode phi = ShapeOf(v).
  void ApplyFlexibilityForm(const double* x, double* y) const;
  // phi = P^T L^-T v for each column v.
  Eigen::MatrixXd ShapesOf(const Eigen::MatrixXd& v) const;

 private:
  const Eigen::SparseMatrix<double>* mass_ = nullptr;
  SparseCholesky factor_;
};

}  // namespace shockmap
