#pragma once
// One sparse LDL^T factorization of K - sigma M of an FE structure (docs/structures.md), the
// solves its modes and static flexibility are made of.

#include <Eigen/SparseCholesky>
#include <memory>
#include <utility>

#include "core/fe_structure.h"

namespace shockmap {

class ShiftedFactorization {
 public:
  // Factorizes K - sigma_rad2_s2 M (fill-reducing AMD ordering, no pivoting).
  ShiftedFactorization(const FeStructure& s, double sigma_rad2_s2);

  double Shift() const { return sigma_; }
  // False when a pivot was exactly zero (K - sigma M singular to the factorization's eyes).
  bool Succeeded() const { return succeeded_; }
  // The number of negative pivots: by Sylvester's law of inertia, the number of eigenvalues
  // omega^2 of K phi = omega^2 M phi below sigma (K positive definite, M positive semi-definite).
  int NegativePivots() const;
  // The row whose pivot is smallest relative to its diagonal entry of K - sigma M (a DOF the
  // supports leave free to move rigidly when K itself is factorized), and that ratio.
  std::pair<int, double> WeakestPivot() const;

  Eigen::VectorXd Solve(const Eigen::VectorXd& rhs) const;
  // Solves in place for a raw pointer pair (Spectra's operator interface).
  void Solve(const double* x, double* y) const;
  int Size() const { return static_cast<int>(diagonal_.size()); }

 private:
  double sigma_ = 0.0;
  bool succeeded_ = false;
  Eigen::VectorXd diagonal_;  // of K - sigma M, in the matrix's own row order
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> factor_;  // movable
};

}  // namespace shockmap
